#pragma once
/// A result directory written as a set: every file goes into a staging sibling "<DIR>.cairn-tmp-<pid>",
/// which is fsynced and then swapped with DIR in one rename (Linux renameat2 RENAME_EXCHANGE), so
/// that DIR holds either the old complete result or the new complete result, whenever the process
/// stops. The old content is removed after the swap; staging siblings left by killed processes
/// are removed by the next StagedDir on the same DIR. DIR is locked while a StagedDir lives
/// (output/dir_lock.hpp): a second cairn process writing the same DIR is refused at once.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace cairn {

class DirLock;

class StagedDir {
public:
    /// check, before any work, that `final_dir` may receive results and create the staging
    /// sibling: `final_dir` must be absent, or a directory that is empty or may be replaced
    /// (`replace`, from --force); missing parents are created. Throws cairn::Error naming the
    /// directory when it cannot be written (the staging directory cannot be created), is refused,
    /// or is being written by another process.
    StagedDir(const std::string& final_dir, bool replace);
    /// removes the staging directory unless committed
    ~StagedDir();
    StagedDir(const StagedDir&) = delete;
    StagedDir& operator=(const StagedDir&) = delete;

    /// where to write the new result
    const std::filesystem::path& path() const { return staging_; }
    /// the directory the result goes to
    const std::filesystem::path& final_path() const { return final_; }

    /// How carried entries are brought over.
    enum class Carry {
        link,   ///< hard links (no data copied); for entries the command never writes to
        copy,   ///< copies; for entries the command may rewrite in place (an appended CSV, figures)
    };

    /// bring every entry of the current DIR into the staging directory, except the names in
    /// `owned` (which the command writes afresh) and staging leftovers: the commands own only part
    /// of DIR (a run its three files, validate its report beside the study/ and bench/ of others)
    void carry_over(const std::vector<std::string>& owned, Carry how);

    /// fsync the staging tree, swap it into place, fsync the parent and remove the old content;
    /// throws std::runtime_error when the swap fails (DIR is then untouched)
    void commit();

    /// remove the staging directory now (also done by the destructor)
    void discard();

private:
    std::filesystem::path final_;
    std::filesystem::path staging_;
    std::unique_ptr<DirLock> lock_;   ///< held from the checks to the end
    bool done_ = false;
};

}  // namespace cairn

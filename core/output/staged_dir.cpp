#include "output/staged_dir.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "error.hpp"
#include "output/dir_lock.hpp"
#include "output/durable.hpp"

namespace fs = std::filesystem;

namespace cairn {

namespace {

/// the staging sibling is "<DIR>.cairn-tmp-<pid>"; the old result moved aside "<DIR>.cairn-old-<pid>"
constexpr const char* kStagingTag = ".cairn-tmp-";
constexpr const char* kOldTag = ".cairn-old-";

/// the pid in "<name>.cairn-tmp-<pid>" or "<name>.cairn-old-<pid>", or -1 when `entry` is not such
/// a name (names that only cairn makes, so that no directory of the user's is taken for one)
long staging_pid(const std::string& entry, const std::string& name) {
    for (const char* tag : {kStagingTag, kOldTag}) {
        const std::string prefix = name + tag;
        if (entry.size() <= prefix.size() || entry.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string digits = entry.substr(prefix.size());
        if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
        return std::stol(digits);
    }
    return -1;
}

/// true for names that only staging leaves behind: "x.cairn-tmp-<pid>", "x.cairn-old-<pid>", and
/// "x.tmp" (output/atomic_write.hpp)
bool is_leftover(const std::string& entry) {
    if (entry.size() > 4 && entry.compare(entry.size() - 4, 4, ".tmp") == 0) return true;
    for (const std::string tag : {kStagingTag, kOldTag}) {
        const auto at = entry.rfind(tag);
        if (at == std::string::npos || at == 0) continue;
        const std::string digits = entry.substr(at + tag.size());
        if (!digits.empty() && digits.find_first_not_of("0123456789") == std::string::npos) return true;
    }
    return false;
}

/// remove staging siblings of `final` left by processes that no longer exist
void remove_stale(const fs::path& final) {
    std::error_code ec;
    const std::string name = final.filename().string();
    for (fs::directory_iterator it(final.parent_path(), ec), end; !ec && it != end; it.increment(ec)) {
        const long pid = staging_pid(it->path().filename().string(), name);
        if (pid <= 0 || pid == long(::getpid())) continue;
        if (::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;   // alive, or not ours to judge
        std::error_code rm;
        fs::remove_all(it->path(), rm);
    }
}

}  // namespace

StagedDir::StagedDir(const std::string& final_dir, bool replace) {
    if (final_dir.empty()) throw Error("the output directory is empty");
    fs::path p = fs::absolute(fs::path(final_dir)).lexically_normal();
    if (!p.has_filename()) p = p.parent_path();
    if (p == p.root_path()) throw Error("output directory " + final_dir + ": cannot replace the root");
    std::error_code ec;
    if (fs::is_symlink(fs::symlink_status(p, ec))) {   // a link to a directory: swap where it points
        p = fs::canonical(p, ec);
        if (ec) throw Error("output directory " + final_dir + ": " + ec.message());
    }
    final_ = p;
    lock_ = std::make_unique<DirLock>(final_);   // before any check: another writer's DIR is not ours to judge
    const auto st = fs::symlink_status(final_, ec);
    if (fs::exists(st)) {
        if (!fs::is_directory(st))
            throw Error("output path " + final_dir + " exists and is not a directory");
        if (!replace && !fs::is_empty(final_, ec))
            throw Error("output directory " + final_dir +
                        " is not empty; use --force to replace an earlier run's outputs");
    }
    const fs::path parent = final_.parent_path();
    fs::create_directories(parent, ec);
    if (ec) throw Error("output directory " + final_dir + ": cannot create " + parent.string() + ": " + ec.message());
    remove_stale(final_);
    staging_ = parent / (final_.filename().string() + kStagingTag + std::to_string(::getpid()));
    fs::remove_all(staging_, ec);   // a leftover of this very pid (an earlier StagedDir in this process)
    if (::mkdir(staging_.c_str(), 0777) != 0)
        throw Error("output directory " + final_dir + ": cannot write into " + parent.string() + ": " +
                    std::strerror(errno));
    if (fs::is_directory(st)) fs::permissions(staging_, st.permissions(), ec);   // DIR keeps its mode
}

StagedDir::~StagedDir() { discard(); }   // then lock_ is released

void StagedDir::discard() {
    if (done_) return;
    done_ = true;
    std::error_code ec;
    fs::remove_all(staging_, ec);
}

void StagedDir::carry_over(const std::vector<std::string>& owned, Carry how) {
    std::error_code ec;
    if (!fs::is_directory(final_, ec)) return;
    for (const auto& e : fs::directory_iterator(final_)) {
        const std::string name = e.path().filename().string();
        if (is_leftover(name)) continue;
        bool skip = false;
        for (const auto& o : owned) skip = skip || o == name;
        if (skip) continue;
        const auto opts = fs::copy_options::recursive | fs::copy_options::copy_symlinks |
                          (how == Carry::link ? fs::copy_options::create_hard_links : fs::copy_options::none);
        fs::copy(e.path(), staging_ / name, opts, ec);
        if (ec && how == Carry::link) {   // a file system without hard links
            fs::remove_all(staging_ / name, ec);
            fs::copy(e.path(), staging_ / name, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
        } else if (ec) {
            throw std::runtime_error("cannot copy " + e.path().string() + " beside the new result: " + ec.message());
        }
    }
}

void StagedDir::commit() {
    if (done_) throw std::logic_error("StagedDir::commit after commit or discard");
    sync_tree(staging_.string());
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(final_, ec))) {
        if (::rename(staging_.c_str(), final_.c_str()) != 0)
            throw std::runtime_error("cannot rename " + staging_.string() + " to " + final_.string() + ": " +
                                     std::strerror(errno));
    } else if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, final_.c_str(), RENAME_EXCHANGE) != 0) {
        if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP)
            throw std::runtime_error("cannot swap " + staging_.string() + " with " + final_.string() + ": " +
                                     std::strerror(errno));
        // a file system without the atomic swap: the old result is moved aside first, so DIR is
        // briefly absent (never mixed)
        const fs::path old = final_.parent_path() / (final_.filename().string() + kOldTag + std::to_string(::getpid()));
        if (::rename(final_.c_str(), old.c_str()) != 0)
            throw std::runtime_error("cannot move " + final_.string() + " aside: " + std::strerror(errno));
        if (::rename(staging_.c_str(), final_.c_str()) != 0) {
            const int err = errno;
            ::rename(old.c_str(), final_.c_str());   // put the old result back
            throw std::runtime_error("cannot move " + staging_.string() + " into place at " + final_.string() + ": " +
                                     std::strerror(err));
        }
        fs::remove_all(old, ec);
    }
    done_ = true;
    sync_dir(final_.parent_path().string());
    fs::remove_all(staging_, ec);   // after a swap: the old result
}

}  // namespace cairn

#pragma once
/// An advisory lock on an output directory, so that two cairn commands never write one DIR at once
/// (each stages its result and swaps it in whole: the later swap would drop the other's files).
/// The lock is flock(2) on a small file holding the owner's pid, named by a hash of DIR's resolved
/// path in the user's own "<tmp>/cairn-locks-<uid>/" (nothing is added beside DIR); the kernel
/// releases it when the process ends, however it ends. It holds between processes of one machine.

#include <filesystem>

namespace cairn {

class DirLock {
public:
    /// lock `dir` (an absolute, normalised path) or throw cairn::Error naming it and the process
    /// holding it; does not wait. A directory this process has locked already is refused too.
    explicit DirLock(const std::filesystem::path& dir);
    /// releases the lock (the lock file stays, a few bytes: removing it would race with a new owner)
    ~DirLock();
    DirLock(const DirLock&) = delete;
    DirLock& operator=(const DirLock&) = delete;

    /// the lock file of `dir`
    static std::filesystem::path lock_file(const std::filesystem::path& dir);

private:
    std::filesystem::path dir_;
};

}  // namespace cairn

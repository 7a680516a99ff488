#include "output/dir_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <mutex>
#include <string>

#include "error.hpp"

namespace fs = std::filesystem;

namespace cairn {

namespace {

/// the locks this process holds: a descriptor per directory (flock conflicts only between open
/// files, so a second lock of one DIR in this process is caught here)
std::mutex held_mutex;
std::map<fs::path, int> held;

/// the pid written in a lock file, or an empty string
std::string owner_of(int fd) {
    char buf[32] = {};
    const ssize_t n = ::pread(fd, buf, sizeof(buf) - 1, 0);
    std::string s = n > 0 ? std::string(buf, size_t(n)) : std::string();
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s.find_first_not_of("0123456789") == std::string::npos ? s : std::string();
}

}  // namespace

fs::path DirLock::lock_file(const fs::path& dir) {
    std::error_code ec;
    fs::path resolved = fs::weakly_canonical(dir, ec);
    if (ec) resolved = dir;
    std::uint64_t h = 14695981039346656037ull;   // FNV-1a, 64 bit: the same name in every cairn build
    for (const unsigned char c : resolved.string()) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char name[32];
    std::snprintf(name, sizeof(name), "%016llx.lock", static_cast<unsigned long long>(h));
    fs::path tmp = fs::temp_directory_path(ec);   // TMPDIR, else /tmp
    if (ec) tmp = "/tmp";
    return tmp / ("cairn-locks-" + std::to_string(::getuid())) / name;
}

DirLock::DirLock(const fs::path& dir) : dir_(dir) {
    std::lock_guard<std::mutex> guard(held_mutex);
    if (held.count(dir_)) {
        throw Error("output directory " + dir_.string() + " is already being written by this command");
    }
    const fs::path file = lock_file(dir_);
    // the folder is the user's own: a folder of that name made by someone else is refused
    ::mkdir(file.parent_path().c_str(), 0700);
    struct stat st {};
    if (::lstat(file.parent_path().c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::getuid())
        throw Error("output directory " + dir_.string() + ": cannot use the lock folder " +
                    file.parent_path().string() + " (missing, or not a folder of this user)");
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (fd < 0)
        throw Error("output directory " + dir_.string() + ": cannot create its lock file " + file.string() + ": " +
                    std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int err = errno;
        const std::string owner = owner_of(fd);
        ::close(fd);
        if (err == EWOULDBLOCK)
            throw Error("output directory " + dir_.string() + " is being written by another cairn process" +
                        (owner.empty() ? std::string() : " (pid " + owner + ")") +
                        "; wait for it to end or choose another directory");
        throw Error("output directory " + dir_.string() + ": cannot lock " + file.string() + ": " + std::strerror(err));
    }
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) != ssize_t(pid.size())) {
        // the lock holds without the pid: it only makes the refusal message less precise
    }
    held[dir_] = fd;
}

DirLock::~DirLock() {
    std::lock_guard<std::mutex> guard(held_mutex);
    auto it = held.find(dir_);
    if (it == held.end()) return;
    ::close(it->second);
    held.erase(it);
}

}  // namespace cairn

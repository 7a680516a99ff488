#include "output/durable.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace cairn {

namespace {

void sync_path(const std::string& path, int flags) {
    const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
    if (fd < 0) throw std::runtime_error("cannot open " + path + " to sync it: " + std::strerror(errno));
    const int rc = ::fsync(fd);
    const int err = errno;
    ::close(fd);
    if (rc != 0) throw std::runtime_error("cannot sync " + path + " to disk: " + std::strerror(err));
}

}  // namespace

void sync_file(const std::string& path) { sync_path(path, O_RDONLY); }

void sync_dir(const std::string& path) { sync_path(path, O_RDONLY | O_DIRECTORY); }

void sync_tree(const std::string& root) {
    namespace fs = std::filesystem;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        if (e.is_symlink()) continue;
        if (e.is_directory()) sync_dir(e.path().string());
        else if (e.is_regular_file()) sync_file(e.path().string());
    }
    sync_dir(root);
}

}  // namespace cairn

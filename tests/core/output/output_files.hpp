#pragma once
// Files for the output tests: a fresh scratch directory under the build tree, a whole file as text.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace cairn::testing {

/// a fresh, empty directory test_scratch/<name> under the build tree
inline std::filesystem::path scratch_dir(const std::string& name) {
    const auto dir = std::filesystem::path(CAIRN_BINARY_DIR) / "test_scratch" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// the whole content of a file
inline std::string read_all(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace cairn::testing

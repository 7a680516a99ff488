#pragma once
// Running the cairn executable from a test: arguments in, exit code and output out.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace cairn::test {

/// what one invocation of cairn produced
struct Invocation {
    int exit_code = -1;
    std::string out;   ///< stdout
    std::string err;   ///< stderr
};

inline std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// a fresh, empty directory for one test under the build tree
inline std::filesystem::path fresh_dir(const std::string& name) {
    const auto dir = std::filesystem::path(CAIRN_BINARY_DIR) / "test_scratch" / "app" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// run `cairn <args>` (args are passed to the shell as written) with `env` prefixed ("X=y" or "")
inline Invocation run_cairn(const std::string& args, const std::filesystem::path& scratch,
                            const std::string& env = "") {
    const auto out = scratch / "stdout.txt";
    const auto err = scratch / "stderr.txt";
    const std::string cmd = env + " " + CAIRN_BINARY_DIR "/app/cairn " + args + " > '" +
                            out.string() + "' 2> '" + err.string() + "'";
    const int status = std::system(cmd.c_str());
    Invocation r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_file(out);
    r.err = read_file(err);
    return r;
}

}  // namespace cairn::test

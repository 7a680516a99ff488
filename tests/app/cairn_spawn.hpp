#pragma once
// Starting the cairn executable from a test as a child process, with an argument vector (no shell),
// so that the test can signal it: spawn, wait, the exit code or the signal that ended it; and the
// files a command left in a directory.

#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace cairn::test {

using Strings = std::vector<std::string>;

inline Strings operator+(Strings a, const Strings& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

/// start `cairn args...` with stdout and stderr into files under `scratch`; returns the pid
inline pid_t spawn_cairn(const std::vector<std::string>& args, const std::filesystem::path& scratch) {
    const std::string exe = CAIRN_BINARY_DIR "/app/cairn";
    std::vector<std::string> all{exe};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string out = (scratch / "stdout.txt").string();
    const std::string err = (scratch / "stderr.txt").string();
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = -1;
    const int rc = posix_spawn(&pid, exe.c_str(), &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) throw std::runtime_error("cannot start " + exe);
    return pid;
}

/// how a child ended
struct Ended {
    int exit_code = -1;   ///< when it exited
    int signal = 0;       ///< when a signal ended it
    long max_rss_kb = 0;  ///< its peak resident set size, KiB
};

inline Ended wait_for(pid_t pid) {
    int status = 0;
    struct rusage usage {};
    while (::wait4(pid, &status, 0, &usage) < 0) {
    }
    Ended e;
    e.max_rss_kb = usage.ru_maxrss;
    if (WIFEXITED(status)) e.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) e.signal = WTERMSIG(status);
    return e;
}

/// every regular file under `dir`: relative path -> content
inline std::map<std::string, std::string> tree(const std::filesystem::path& dir) {
    std::map<std::string, std::string> t;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
        if (!e.is_regular_file()) continue;
        std::ifstream in(e.path(), std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        t[std::filesystem::relative(e.path(), dir).generic_string()] = ss.str();
    }
    return t;
}

/// names in `dir` that staging left behind ("*.cairn-tmp-<pid>", "*.cairn-old-<pid>", "*.tmp")
inline Strings leftovers(const std::filesystem::path& dir) {
    Strings v;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().filename().string().find(".cairn-") != std::string::npos ||
            e.path().extension() == ".tmp") v.push_back(e.path().filename().string());
    return v;
}

/// wait (up to 60 s) until `p` exists
inline bool wait_until_exists(const std::filesystem::path& p) {
    for (int i = 0; i < 6000; ++i) {
        if (std::filesystem::exists(p)) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
}

/// a child signalled once it was at work
struct Signalled {
    bool staged = false;   ///< it wrote into its staging directory before the signal
    Ended ended;
};

/// start `cairn args...`, wait until `staged` exists inside its staging directory
/// "<name>.cairn-tmp-<pid>" under `dir`, and a little more, then send it `sig`
inline Signalled signal_when_staged(const Strings& args, const std::string& name, const std::string& staged, int sig,
                                    const std::filesystem::path& dir) {
    const pid_t pid = spawn_cairn(args, dir);
    Signalled s;
    s.staged = wait_until_exists(dir / (name + ".cairn-tmp-" + std::to_string(pid)) / staged);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    ::kill(pid, sig);
    s.ended = wait_for(pid);
    return s;
}

}  // namespace cairn::test

#include <iostream>

#include "commands.hpp"
#include "error.hpp"
#include "output/atomic_write.hpp"
#include "report/replay_run_dir.hpp"

namespace cairn {

int replay_command(const ReplayOptions& options) {
    std::vector<ReplayRun> runs;
    std::string page;
    try {
        for (const auto& dir : options.run_dirs) runs.push_back(replay_from_run_dir(dir));
        page = replay_html(options.title.empty() ? "cairn replay" : options.title, runs);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    write_text_atomic(options.out, page);
    std::cout << "replay of " << runs.size() << " run(s) -> " << options.out << "\n";
    return kExitOk;
}

}  // namespace cairn

#include "report/case_replay.hpp"

#include <filesystem>

#include "output/atomic_write.hpp"
#include "report/replay.hpp"

namespace fs = std::filesystem;

namespace cairn::report {

std::string write_case_replay(const validation::CaseResult& c, const std::string& dir, const std::string& file,
                              std::string& note) {
    note.clear();
    if (!replay_available()) {
        note = "no 3-D replay: this cairn was built without it (node and npm were not found; scripts/setup.sh "
               "installs them)";
        return "";
    }
    std::vector<ReplayRun> runs;
    for (const auto& r : c.runs) {
        if (r.samples.empty()) continue;
        runs.push_back(replay_run(r.variant.name, c.scene));
        for (const auto& s : r.samples) add_frame(runs.back(), s);
    }
    if (runs.empty()) {
        note = "no 3-D replay: no variant produced samples";
        return "";
    }
    const fs::path path = fs::path(dir) / file;
    fs::create_directories(path.parent_path());
    write_text_atomic(path.string(), replay_html(c.name, runs));
    return file;
}

}  // namespace cairn::report

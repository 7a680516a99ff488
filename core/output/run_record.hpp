#pragma once
/// The run record (run.json): what was run, with which parameters and engine, and how it went.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "backend/backend.hpp"
#include "run/runner.hpp"

namespace cairn {

/// How a run was asked for, beyond the scene file.
struct RunRequest {
    std::string scene_path;               ///< path of the scene file as resolved
    std::vector<std::string> overrides;   ///< command-line overrides, "key=value", in order
    std::string model_override;           ///< "rigid" or "deformable" from --model; empty = none
    RunOptions options;                   ///< contact mode and the like
};

/// the run record of `result`: scene, backend and versions, every parameter after overrides,
/// time stepping, wall time, status, balance error, final energies and the backend's notes
nlohmann::json run_record(const Scene& scene, const Backend& backend, const RunResult& result,
                          const RunRequest& request);

/// run_record() as the text of run.json (indented, ending in a newline); never throws on text
/// that is not UTF-8 (U+FFFD takes the place of each bad byte)
std::string run_record_text(const Scene& scene, const Backend& backend, const RunResult& result,
                            const RunRequest& request);

/// "completed", "unstable" or "interrupted"
const char* to_string(RunStatus s);

}  // namespace cairn

#include "output/run_files.hpp"

#include <filesystem>

#include "output/atomic_write.hpp"

namespace fs = std::filesystem;

namespace cairn {

void finish_run_files(const std::string& dir, const Scene& scene, const Backend& backend,
                      const RunResult& result, const RunRequest& request) {
    const fs::path d(dir);
    if (result.status != RunStatus::completed) fs::rename(d / kTrajectoryFile, d / kPartialTrajectoryFile);
    write_text_atomic((d / kRunRecordFile).string(), run_record_text(scene, backend, result, request));
}

}  // namespace cairn

#include "run_views.hpp"

#include <filesystem>

#include "error.hpp"
#include "output/atomic_write.hpp"

namespace cairn {

RunViews::RunViews(const Scene& scene, const std::string& label, bool vtk, bool replay)
    : scene_(scene), vtk_(vtk), replay_(replay) {
    if (replay_ && !replay_available())
        throw Error("--replay: this cairn was built without the 3-D replay (node and npm were not found "
                    "when it was built; scripts/setup.sh installs them, then rebuild)");
    if (replay_) run_ = replay_run(label, scene);
}

void RunViews::open(const std::string& dir) {
    dir_ = dir;
    // an earlier run's views (DIR was accepted with --force) would contradict this run
    std::error_code ec;
    std::filesystem::remove_all(dir + "/vtk", ec);
    std::filesystem::remove(dir + "/replay.html", ec);
    if (vtk_) series_ = std::make_unique<VtkSeries>(scene_, dir + "/vtk");
}

SampleObserver RunViews::observer() {
    return [this](const Sample& s, const Backend& backend) {
        if (series_) series_->add(s, backend);
        if (replay_) add_frame(run_, s);
    };
}

void RunViews::finish() {
    if (series_) series_->finish();
    if (replay_) write_text_atomic(dir_ + "/replay.html", replay_html(scene_.name, {run_}));
}

}  // namespace cairn

#include "run_views.hpp"

#include "error.hpp"
#include "output/atomic_write.hpp"

namespace cairn {

RunViews::RunViews(const Scene& scene, const Backend& backend, const std::string& label, bool vtk, bool replay)
    : scene_(scene), backend_(backend), vtk_(vtk), replay_(replay) {
    if (replay_ && !replay_available())
        throw Error("--replay: this cairn was built without the 3-D replay (node and npm were not found "
                    "when it was built; scripts/setup.sh installs them, then rebuild)");
    if (replay_) run_ = replay_run(label, scene);
}

void RunViews::open(const std::string& dir) {
    dir_ = dir;
    if (vtk_) series_ = std::make_unique<VtkSeries>(scene_, dir + "/" + kVtkDir);
}

void RunViews::sample(const Sample& s) {
    if (series_) series_->add(s, backend_);
    if (replay_) add_frame(run_, s);
}

void RunViews::end(const RunResult&) {
    if (series_) series_->finish();
    if (replay_) write_text_atomic(dir_ + "/" + kReplayPage, replay_html(scene_.name, {run_}));
}

}  // namespace cairn

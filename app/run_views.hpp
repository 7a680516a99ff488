#pragma once
/// The 3-D views of one run, written as it goes: the VTK series for ParaView (DIR/vtk/) and the
/// replay page (DIR/replay.html), see docs/visualisation.md.

#include <memory>
#include <string>

#include "run/observed_backend.hpp"
#include "output/vtk_series.hpp"
#include "report/replay.hpp"

namespace cairn {

/// The views asked for; a no-op when neither is.
class RunViews {
public:
    /// check that what is asked for can be written (throws cairn::Error otherwise, before the run)
    RunViews(const Scene& scene, const std::string& label, bool vtk, bool replay);
    /// nothing asked for
    bool empty() const { return !vtk_ && !replay_; }
    /// start writing into `dir` (DIR/vtk/ is created when the VTK series is asked for)
    void open(const std::string& dir);
    /// what the run hands every sample to
    SampleObserver observer();
    /// write the .pvd collections and the replay page
    void finish();

private:
    const Scene& scene_;
    bool vtk_ = false, replay_ = false;
    std::string dir_;
    std::unique_ptr<VtkSeries> series_;
    ReplayRun run_;
};

}  // namespace cairn

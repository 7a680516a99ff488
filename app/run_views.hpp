#pragma once
/// The 3-D views of one run, written as it goes: the VTK series for ParaView (DIR/vtk/) and the
/// replay page (DIR/replay.html), see docs/visualisation.md.

#include <memory>
#include <string>

#include "output/vtk_series.hpp"
#include "report/replay.hpp"
#include "run/sample_sink.hpp"

namespace cairn {

/// what the views write into a run's directory
constexpr const char* kVtkDir = "vtk";
constexpr const char* kReplayPage = "replay.html";

/// A sink for the views asked for (a no-op when neither is). It reads deformable meshes and
/// contact points from the backend, which the runner leaves in the sampled state while the sink
/// takes a sample.
class RunViews : public SampleSink {
public:
    /// check that what is asked for can be written (throws cairn::Error otherwise, before the run)
    RunViews(const Scene& scene, const Backend& backend, const std::string& label, bool vtk, bool replay);
    /// start writing into `dir` (DIR/vtk/ is created when the VTK series is asked for)
    void open(const std::string& dir);
    /// write the files of one sample (VTK) and keep its poses (replay)
    void sample(const Sample& s) override;
    /// write the .pvd collections and the replay page
    void end(const RunResult& run) override;

private:
    const Scene& scene_;
    const Backend& backend_;
    bool vtk_ = false, replay_ = false;
    std::string dir_;
    std::unique_ptr<VtkSeries> series_;
    ReplayRun run_;
};

}  // namespace cairn

#pragma once
/// A backend that forwards every call to another and hands each sample taken, with the inner
/// backend still in the sampled state, to an observer: the hook for outputs that need more than a
/// Sample (deformable meshes, contact points), written as the run goes.

#include <functional>
#include <utility>

#include "backend/backend.hpp"

namespace cairn {

/// called with every sample as it is taken and the backend in that state
using SampleObserver = std::function<void(const Sample&, const Backend&)>;

/// Forwards to `inner`; sample() also calls the observer.
class ObservedBackend : public Backend {
public:
    ObservedBackend(Backend& inner, SampleObserver observer) : inner_(inner), observer_(std::move(observer)) {}
    std::string name() const override { return inner_.name(); }
    std::string engine_version() const override { return inner_.engine_version(); }
    void build(const Scene& scene, const RunOptions& options) override { inner_.build(scene, options); }
    double time_step() const override { return inner_.time_step(); }
    double critical_step() const override { return inner_.critical_step(); }
    StepStatus step() override { return inner_.step(); }
    Sample sample() const override {
        Sample s = inner_.sample();
        if (observer_) observer_(s, inner_);
        return s;
    }
    std::string failure() const override { return inner_.failure(); }
    std::vector<std::string> notes() const override { return inner_.notes(); }
    std::vector<ContactPoint> contact_points() const override { return inner_.contact_points(); }
    BlockMesh block_mesh(int block) const override { return inner_.block_mesh(block); }

private:
    Backend& inner_;
    SampleObserver observer_;
};

}  // namespace cairn

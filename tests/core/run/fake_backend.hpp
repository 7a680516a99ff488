#pragma once
// A tiny backend for testing the runner: a point mass in ballistic flight with exact, analytic
// positions and energies, that can be told to go wrong (NaN, an unstable step, energy growth,
// slow drift).

#include <cmath>
#include <limits>
#include <string>

#include "backend/backend.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"

namespace cairn::testing {

/// how the fake backend misbehaves
struct Faults {
    long long nan_from_step = -1;       ///< positions become NaN from this step on
    long long unstable_at_step = -1;    ///< step() reports unstable at this step
    double growth_rate = 0.0;           ///< kinetic energy gains 1e-3 J·(exp(rate·step) - 1)
    double drift_per_second = 0.0;      ///< dissipated energy gains this many J per second (< 0: losses
                                        ///< the backend does not book, as a rigid engine's impacts)
    long long jump_at_step = -1;        ///< from this step on, kinetic energy has jump_energy more
    double jump_energy = 0.0;           ///< J, energy created at jump_at_step
};

/// Ballistic flight of the first free block of the scene (a point mass of that block's mass).
class FakeBackend : public Backend {
public:
    explicit FakeBackend(Faults f = {}) : faults_(f) {}
    std::string name() const override { return "fake"; }
    std::string engine_version() const override { return "fake 1.0"; }
    void build(const Scene& scene, const RunOptions& options) override {
        if (scene.blocks.empty()) throw Error("fake: the scene has no block");
        scene_ = &scene;
        options_ = options;
        const BlockDef& b = scene.blocks.front();
        mass_ = mass_properties(b.corners, scene.materials[b.material].density).mass;
        dt_ = scene.run.dt.value_or(1e-3);
        step_ = 0;
        built_ = true;
    }
    double time_step() const override { return dt_; }
    double critical_step() const override { return 2e-3; }
    StepStatus step() override {
        ++step_;
        return step_ == faults_.unstable_at_step ? StepStatus::unstable : StepStatus::ok;
    }
    std::string failure() const override {
        return step_ == faults_.unstable_at_step ? "contact spring overshoot" : "";
    }
    Sample sample() const override {
        const BlockDef& b = scene_->blocks.front();
        const double t = double(step_) * dt_;
        Sample s;
        s.t = t;
        BlockState st;
        st.position = b.position + b.velocity * t + 0.5 * scene_->gravity * t * t;
        st.velocity = b.velocity + scene_->gravity * t;
        st.orientation = b.orientation;
        if (faults_.nan_from_step >= 0 && step_ >= faults_.nan_from_step)
            st.position.x() = std::numeric_limits<double>::quiet_NaN();
        s.blocks.push_back(st);
        for (const auto& p : scene_->probes) s.probes.push_back(st.position + p.point);
        s.energy.kinetic = 0.5 * mass_ * st.velocity.squaredNorm() +
                           1e-3 * (std::exp(faults_.growth_rate * double(step_)) - 1.0);
        if (faults_.jump_at_step >= 0 && step_ >= faults_.jump_at_step) s.energy.kinetic += faults_.jump_energy;
        s.energy.potential = -mass_ * scene_->gravity.dot(st.position);
        s.energy.dissipated = faults_.drift_per_second * t;
        return s;
    }
    /// mass of the point, kg
    double mass() const { return mass_; }
    /// the options build() was given
    const RunOptions& options() const { return options_; }

private:
    Faults faults_;
    const Scene* scene_ = nullptr;
    RunOptions options_;
    double mass_ = 0.0;
    double dt_ = 0.0;
    long long step_ = 0;
    bool built_ = false;
};

/// one free 0.1 m cube "A" of density 2000 kg/m³ (2 kg) at z = 1 m, a fixed base "B", probe "P"
inline Scene ballistic_scene() {
    Scene s;
    s.name = "ballistic";
    s.materials.push_back({"stone", 2000.0, 1e9, 0.2});
    BlockDef a;
    a.name = "A";
    a.size = Vec3(0.1, 0.1, 0.1);
    a.corners = box_corners(a.size);
    a.position = Vec3(0.0, 0.0, 1.0);
    a.velocity = Vec3(1.0, 0.0, 2.0);
    BlockDef b = a;
    b.name = "B";
    b.fixed = true;
    b.position = Vec3::Zero();
    b.velocity = Vec3::Zero();
    s.blocks = {a, b};
    s.probes.push_back({"P", 0, Vec3(0.05, 0.05, 0.05)});
    s.run.duration = 0.1;
    s.run.dt = 1e-3;
    s.run.output_interval = 0.01;
    return s;
}

}  // namespace cairn::testing

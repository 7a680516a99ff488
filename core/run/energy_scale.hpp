#pragma once
/// The energy a run's balance error is judged against, kept as running summaries of the samples
/// (updated once per sample, in order; nothing stored per sample).

#include "backend/backend.hpp"
#include "scene/scene.hpp"

namespace cairn {

/// The scales one sample is judged against, J.
struct EnergyBounds {
    /// the energy of the motion: the largest kinetic + contact + strain of the earlier samples,
    /// plus |work of the loads| now, plus the potential energy actually exchanged (max − min of
    /// the potential over the run up to this sample), at least 1 J. The drift flag's scale.
    double motion = 0.0;
    /// the energy the run's sources can have put in: the first sample's kinetic + contact +
    /// strain, plus the largest |work of the loads| so far, plus the potential energy gravity
    /// released (first sample's potential − the lowest since), plus Σ m·g·(diameter) of the free
    /// blocks; at least 1 J. The bar for energy growing without a source, which stops a run. It
    /// leaves out the motion seen so far: energy created by an unstable step would otherwise
    /// raise the bar it is measured against (a block launched by the step, then flying)
    double growth = 0.0;
    /// the bar for energy that appears without a source (RunResult::energy_created): the larger of
    /// `motion` and the largest m·g·(diameter) of one free block. A burst that could lift the
    /// heaviest block by a tenth of its size is seen in a structure at rest, while the settling of a
    /// rigid engine's contacts (a block pushed out of the millimetre it sank) is not
    double created = 0.0;
};

/// Running summaries of a run's energies.
class EnergyScale {
public:
    /// the scene gives the gravity reach of its free blocks
    explicit EnergyScale(const Scene& scene);
    /// take the next sample's energies and return the scales it is judged against; the motion
    /// part comes from the samples before it: energy that grows without a source must not raise
    /// the bar it is measured against
    EnergyBounds add(const Energies& e);

private:
    double gravity_reach_ = 0.0;    // J, Σ m·g·(diameter) of the free blocks
    double block_reach_ = 0.0;      // J, the largest m·g·(diameter) of one free block
    double motion_max_ = 0.0;       // largest |kinetic| + |contact| + |strain| so far, J
    double potential_min_ = 0.0, potential_max_ = 0.0;   // J
    double initial_motion_ = 0.0;    // |kinetic| + |contact| + |strain| of the first sample, J
    double potential_first_ = 0.0;   // J
    double work_max_ = 0.0;          // largest |work of the loads| so far, J
    bool first_ = true;
};

}  // namespace cairn

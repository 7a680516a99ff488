#pragma once
/// The contact damping that makes a penalty contact lose what Housner's rigid impact loses: the
/// damping ratio ζ of the contact springs with which the spring block's first impacts come closest
/// to Housner's amplitude sequence (docs/validation.md, "Rocking with Housner's loss"). It depends
/// on the block's geometry and on kn, and does not always exist.

#include <vector>

#include "analytic/spring_block.hpp"

namespace cairn::oracle {

/// the result of a calibration
struct HousnerDamping {
    double zeta = 0.0;                 ///< the damping ratio found
    std::vector<double> amplitudes;    ///< the spring block's amplitudes after each impact at ζ, rad
    std::vector<double> housner;       ///< Housner's amplitudes after each impact, rad
    double worst = 0.0;                ///< largest |relative error| over the judged impacts
};

/// the ζ in [0, zeta_max] minimising the largest relative error of the first `impacts` amplitudes
/// of `block` (its own zeta ignored) released at θ0 (rad) against Housner's; a scan in steps of
/// zeta_max/100, refined by golden section. `duration` (s) must hold that many swings
HousnerDamping calibrate_housner_damping(SpringBlock block, double theta0, int impacts, double duration,
                                         double zeta_max = 2.0);

}  // namespace cairn::oracle

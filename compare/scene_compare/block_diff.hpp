#pragma once
/// How far one run's block history strays from a baseline run's: RMS differences, the first time
/// the difference passes a threshold, and peaks.

#include <cmath>
#include <string>
#include <vector>

#include "scene_compare/block_history.hpp"

namespace cairn::scene_compare {

/// Thresholds of "diverged".
struct DivergenceThresholds {
    double position = 0.0;   ///< m (compare uses 1 % of the block's smallest edge)
    double angle = 0.01;     ///< rad
};

/// One block of one run against the same block of the baseline run.
struct BlockDiff {
    double position_rms = NAN;     ///< RMS distance between the centres of mass, m
    double angle_rms = NAN;        ///< RMS difference of the rotation angles, rad
    double speed_rms = NAN;        ///< RMS difference of the speeds, m/s
    double position_peak = NAN;    ///< largest distance between the centres of mass, m
    double angle_peak = NAN;       ///< largest |difference| of the rotation angles, rad
    double position_diverged = NAN;   ///< first time the distance passes the threshold, s; NaN = never
    double angle_diverged = NAN;      ///< first time the angle difference passes the threshold, s; NaN = never
    double compared_until = NAN;   ///< last time both runs cover, s
};

/// `run` minus `base` at the times of `run` that `base` covers (base interpolated linearly)
struct DifferenceSeries {
    std::vector<double> t;          ///< s
    std::vector<double> distance;   ///< between the centres of mass, m
    std::vector<double> angle;      ///< rotation angle of run minus base, rad
    std::vector<double> speed;      ///< speed of run minus base, m/s
};

DifferenceSeries differences(const BlockHistory& run, const BlockHistory& base);

/// `run` against `base` at the times of `run` that `base` covers (base interpolated linearly)
BlockDiff block_diff(const BlockHistory& run, const BlockHistory& base, const DivergenceThresholds& th);

/// A run's own peaks for one block.
struct BlockPeaks {
    double displacement = 0.0;   ///< largest distance from the position at t = 0, m
    double angle = 0.0;          ///< largest rotation angle, rad
    double speed = 0.0;          ///< largest speed, m/s
};

BlockPeaks block_peaks(const BlockHistory& h);

/// The free blocks a report draws when it cannot draw all `blocks`: the `max_shown` whose largest
/// displacement over every variant (`peaks_of[variant][block]`) is largest, then the largest
/// rotation, ties to the lower index; in index order. Every block when there are no more.
std::vector<size_t> blocks_to_show(const std::vector<std::vector<BlockPeaks>>& peaks_of, size_t blocks,
                                   int max_shown);

/// One variant's largest rotation over every free block, for comparing kinds of contact.
struct VariantPeak {
    std::string name;           ///< the variant, e.g. "dem-rigid"
    bool compliant = false;     ///< dem's penalty bed (kn, ks in every joint)
    bool rigid = false;         ///< an engine's rigid (non-penalty) contact
    double angle = 0.0;         ///< largest rotation angle of any free block, rad
};

/// the compliant variants whose largest rotation is far from the rigid-contact variants' median
/// (by more than 0.05 rad and more than half that median), as "dem-rigid 3.14 rad, ... against
/// the rigid-contact engines' 0.113 rad (median)"; empty when none is, or either kind is missing
std::string compliance_disagreement(const std::vector<VariantPeak>& peaks);

}  // namespace cairn::scene_compare

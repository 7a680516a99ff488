#pragma once
/// The metrics of one run of a validation case against the analytic reference its scene declares
/// ([reference] kind), and the curves its figure shows.

#include <array>
#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "metrics/metric.hpp"
#include "metrics/signal.hpp"

namespace cairn::cases {

/// What kind of contact a run had: it decides which references apply.
struct ContactKind {
    bool penalty = true;        ///< penalty springs (dem, engines in matched mode); false: rigid contact
    /// the penalty contact is the paper's hitting-point springs (dem); false for an engine's
    /// matched contact, which matches kn·A of a face but not the springs along an edge nor their loss
    bool point_springs = true;
    /// hitting-face divisions of the reference block along its block-frame axes (1: a rigid block's
    /// single face per side; a deformable block's mesh divisions: its hitting grid is per boundary face)
    std::array<int, 3> divisions{1, 1, 1};
    bool deformable = false;    ///< the reference block runs as a hex8 mesh (dem's deformable variant)
};

/// Metrics and figure data of one run.
struct CaseAnalysis {
    std::vector<metrics::Metric> metrics;
    std::string quantity;            ///< what `measured` is, e.g. "penetration of node10 (m)"
    metrics::Series measured;        ///< the run's curve of `quantity`
    std::vector<double> analytic;    ///< the reference curve at measured.t; empty = none
    std::string analytic_label;      ///< description of the reference curve
    std::string analytic_key = "analytic";   ///< short legend of the reference curve
    double event_time = 0.0;         ///< time of the case's first event (for aligning runs), s
    bool has_event = false;          ///< false: no event found
};

/// analyse the samples of one run of `scene` (its reference kind decides the metrics); throws
/// cairn::Error when the scene has no reference or a kind without metrics
CaseAnalysis analyse_case(const Scene& scene, const std::vector<Sample>& samples, ContactKind contact);

/// the reference curve alone, at the given times (what analyse_case puts in `analytic`)
std::vector<double> reference_curve(const Scene& scene, ContactKind contact, const std::vector<double>& times);

}  // namespace cairn::cases

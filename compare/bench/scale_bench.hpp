#pragma once
/// `cairn bench scale`: the cost of each backend per simulated second on running-bond walls of
/// 10³ … 10⁴ bricks, at the time step that reaches the accuracy of the static settlement (the sum
/// of the joints' compressions, within 1 %), with its peak memory and the growth of both with N.

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backend/backend.hpp"

namespace cairn::bench {

/// courses and bricks per course of the scale walls: about n bricks of 0.4 × 0.2 m faces in a
/// nearly square wall (per course = ⌈√(n/2)⌉, courses = ⌈n / per course⌉), count
std::array<int, 2> scale_wall_shape(int n);

/// the static settlement of the top course of a running-bond wall of `courses` courses of
/// height h (m), density rho (kg/m³), gravity g (m/s²), joints of normal stiffness kn (N/m³):
/// the joint under course c carries the courses above it at pressure (courses − c)·ρ g h, so it
/// closes by that over kn; the sum over the joints is ρ g h·C(C + 1)/(2 kn), m
double wall_settlement(int courses, double rho, double g, double h, double kn);

/// The settlement of a wall released touching under gravity, with mass damping, at one dt.
struct ScaleAccuracy {
    std::string backend;
    double dt = 0.0;            ///< s
    double settlement = 0.0;    ///< top-course middle brick, measured, m
    double expected = 0.0;      ///< wall_settlement, m
    double error = 0.0;         ///< settlement / expected − 1
    std::string status;         ///< "completed", "unstable: …", "refused: …"
};

/// One backend on one wall size.
struct ScaleRow {
    std::string backend;
    int blocks = 0;               ///< free bricks
    double dt = 0.0;              ///< s, the largest reaching the accuracy (ScaleAccuracy)
    int steps = 0;                ///< steps timed
    double step_seconds = 0.0;    ///< wall time per step, s
    double cost = 0.0;            ///< wall seconds per simulated second (step_seconds / dt)
    double peak_mb = 0.0;         ///< peak resident memory of the process while building and stepping, MB
    std::string status;           ///< "completed", "unstable: …", "refused: …"
};

/// the settlement test of each backend at the dts of `dts` (largest first), until one settles
/// within `tolerance` (relative): a 10-course wall of 10 bricks per course at kn = ks = 3e9 N/m³,
/// released touching, mass damping α = 300 1/s, 0.3 s
std::vector<ScaleAccuracy> scale_accuracy(const std::vector<std::string>& backends, const std::vector<double>& dts,
                                          double tolerance, const std::function<std::unique_ptr<Backend>(const std::string&)>& make,
                                          bool quiet);

/// per backend: the largest dt whose settlement completed within `tolerance` (0: none did)
double reaching_dt(const std::vector<ScaleAccuracy>& acc, const std::string& backend, double tolerance);

/// time `steps` steps of every backend on the wall of each size (placed at its static
/// penetrations, kn = 3e9, each backend at dts[i]), one after the other
std::vector<ScaleRow> run_scale(const std::vector<std::string>& backends, const std::vector<double>& dts,
                                const std::vector<int>& sizes, int steps,
                                const std::function<std::unique_ptr<Backend>(const std::string&)>& make, bool quiet);

/// least-squares slope of log(y) against log(x) over the positive pairs (NaN below two)
double fitted_exponent(const std::vector<double>& x, const std::vector<double>& y);

/// scale.csv / scale_accuracy.csv text and their parses
std::string scale_csv(const std::vector<ScaleRow>& rows);
std::vector<ScaleRow> parse_scale_csv(const std::string& text);
std::string scale_accuracy_csv(const std::vector<ScaleAccuracy>& rows);
std::vector<ScaleAccuracy> parse_scale_accuracy_csv(const std::string& text);

/// peak resident memory of this process since the last reset, MB (0 where /proc is missing);
/// reset_peak_memory() starts a new peak (Linux clear_refs)
double peak_memory_mb();
void reset_peak_memory();

}  // namespace cairn::bench

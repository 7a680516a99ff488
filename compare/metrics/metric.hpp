#pragma once
/// One checked number of a validation case: value, analytic reference, stated tolerance, verdict.

#include <string>

namespace cairn::metrics {

/// How a metric is judged.
enum class Check {
    relative,   ///< |value − reference| ≤ tolerance·|reference|
    absolute,   ///< |value − reference| ≤ tolerance (in the metric's unit)
    at_most,    ///< value ≤ reference + tolerance (a bound)
    at_least,   ///< value ≥ reference
    info,       ///< reported, not judged (no analytic reference holds)
    not_comparable,   ///< the reference does not model what this variant does (basis: the reason)
};

/// A measured number against its reference.
struct Metric {
    std::string name;              ///< e.g. "equilibrium penetration"
    std::string unit;              ///< e.g. "m", "s", "rad", "" (dimensionless)
    double value = 0.0;            ///< measured, in `unit`
    double reference = 0.0;       ///< analytic value, in `unit` (ignored for info without one)
    bool has_reference = true;     ///< false: nothing to compare with
    double tolerance = 0.0;        ///< relative fraction (relative) or in `unit` (absolute, at_most)
    Check check = Check::info;
    std::string basis;             ///< the oracle and why the tolerance is that wide
    bool measured = true;          ///< false: the event did not happen (value meaningless) → miss

    /// (value − reference)/|reference|; 0 when there is no reference or it is 0
    double relative_error() const;
    /// true when the check holds (info and not-comparable metrics are never misses)
    bool pass() const;
    /// true when the metric is judged (neither info nor not comparable)
    bool judged() const { return check != Check::info && check != Check::not_comparable; }
    /// "pass", "miss", "not comparable" or "info"
    const char* verdict() const;
    /// the tolerance as text: "1 %", "≤ 2e-02 m", "≥ 1", "-"
    std::string tolerance_text() const;
};

/// a metric checked relative to its reference
Metric relative(std::string name, std::string unit, double value, double reference, double tol,
                std::string basis);
/// a metric checked against an absolute tolerance
Metric absolute(std::string name, std::string unit, double value, double reference, double tol,
                std::string basis);
/// an upper bound: value ≤ bound + tol
Metric at_most(std::string name, std::string unit, double value, double bound, double tol,
               std::string basis);
/// a lower bound: value ≥ bound
Metric at_least(std::string name, std::string unit, double value, double bound, std::string basis);
/// a reported number without a check; `reference` optional (NaN = none)
Metric info(std::string name, std::string unit, double value, double reference, std::string basis);
/// a number the reference cannot judge for this variant: `reason` says what the reference does not
/// model (e.g. an undamped reference for a dissipative contact); `reference` shown if finite
Metric not_comparable(std::string name, std::string unit, double value, double reference, std::string reason);
/// a metric whose event never happened in the run (e.g. no impact): a miss with a note
Metric missing(std::string name, std::string unit, double reference, double tol, Check check,
               std::string basis);

}  // namespace cairn::metrics

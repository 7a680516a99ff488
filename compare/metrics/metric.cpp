#include "metrics/metric.hpp"

#include <cmath>
#include <cstdio>

namespace cairn::metrics {

double Metric::relative_error() const {
    if (!has_reference || reference == 0.0 || !measured) return 0.0;
    return (value - reference) / std::abs(reference);
}

bool Metric::pass() const {
    if (!judged()) return true;
    if (!measured || !std::isfinite(value)) return false;
    switch (check) {
        case Check::relative: return std::abs(value - reference) <= tolerance * std::abs(reference);
        case Check::absolute: return std::abs(value - reference) <= tolerance;
        case Check::at_most: return value <= reference + tolerance;
        case Check::at_least: return value >= reference;
        case Check::info:
        case Check::not_comparable: return true;
    }
    return false;
}

const char* Metric::verdict() const {
    if (check == Check::info) return "info";
    if (check == Check::not_comparable) return "not comparable";
    return pass() ? "pass" : "miss";
}

std::string Metric::tolerance_text() const {
    char buf[64];
    switch (check) {
        case Check::relative: std::snprintf(buf, sizeof buf, "%g %%", 100.0 * tolerance); break;
        case Check::absolute: std::snprintf(buf, sizeof buf, "± %.3g %s", tolerance, unit.c_str()); break;
        case Check::at_most: std::snprintf(buf, sizeof buf, "≤ ref + %.3g %s", tolerance, unit.c_str()); break;
        case Check::at_least: std::snprintf(buf, sizeof buf, "≥ ref"); break;
        case Check::info:
        case Check::not_comparable: return "-";
    }
    return buf;
}

namespace {
Metric make(std::string name, std::string unit, double value, double reference, double tol,
            Check check, std::string basis) {
    Metric m;
    m.name = std::move(name);
    m.unit = std::move(unit);
    m.value = value;
    m.reference = reference;
    m.has_reference = std::isfinite(reference);
    m.tolerance = tol;
    m.check = check;
    m.basis = std::move(basis);
    m.measured = std::isfinite(value);
    return m;
}
}  // namespace

Metric relative(std::string name, std::string unit, double value, double reference, double tol,
                std::string basis) {
    return make(std::move(name), std::move(unit), value, reference, tol, Check::relative, std::move(basis));
}
Metric absolute(std::string name, std::string unit, double value, double reference, double tol,
                std::string basis) {
    return make(std::move(name), std::move(unit), value, reference, tol, Check::absolute, std::move(basis));
}
Metric at_most(std::string name, std::string unit, double value, double bound, double tol,
               std::string basis) {
    return make(std::move(name), std::move(unit), value, bound, tol, Check::at_most, std::move(basis));
}
Metric at_least(std::string name, std::string unit, double value, double bound, std::string basis) {
    return make(std::move(name), std::move(unit), value, bound, 0.0, Check::at_least, std::move(basis));
}
Metric info(std::string name, std::string unit, double value, double reference, std::string basis) {
    return make(std::move(name), std::move(unit), value, reference, 0.0, Check::info, std::move(basis));
}
Metric not_comparable(std::string name, std::string unit, double value, double reference, std::string reason) {
    return make(std::move(name), std::move(unit), value, reference, 0.0, Check::not_comparable, std::move(reason));
}
Metric missing(std::string name, std::string unit, double reference, double tol, Check check,
               std::string basis) {
    Metric m = make(std::move(name), std::move(unit), NAN, reference, tol, check, std::move(basis));
    m.measured = false;
    return m;
}

}  // namespace cairn::metrics

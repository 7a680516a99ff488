#include "report/validation_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace cairn::report {

using validation::CaseResult;
using validation::CaseRun;
using validation::Outcome;

namespace {

std::string num(double v) {
    if (!std::isfinite(v)) return "";
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

std::string pct(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%+.3f %%", 100.0 * v);
    return b;
}

std::string csv(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string o = "\"";
    for (char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
    return o + "\"";
}

/// the metric that misses by the most (relative to its tolerance), or the first checked one
const metrics::Metric* worst(const CaseRun& r) {
    const metrics::Metric* w = nullptr;
    double score = -1.0;
    for (const auto& m : r.analysis.metrics) {
        if (m.check == metrics::Check::info) continue;
        double s = !m.measured ? 1e300
                   : m.check == metrics::Check::relative && m.tolerance > 0
                       ? std::abs(m.relative_error()) / m.tolerance
                       : (m.pass() ? 0.0 : 1e299);
        if (s > score) { score = s; w = &m; }
    }
    return w;
}

std::string metric_brief(const metrics::Metric& m) {
    if (!m.measured) return m.name + ": not measured (" + m.basis + ")";
    if (m.check == metrics::Check::relative)
        return m.name + " " + num(m.value) + " " + m.unit + " vs " + num(m.reference) + " (" + pct(m.relative_error()) +
               ", tol " + m.tolerance_text() + ")";
    return m.name + " " + num(m.value) + " " + m.unit + " (" + m.tolerance_text() + " " + num(m.reference) + ")";
}

}  // namespace

std::string worst_metric_text(const CaseRun& r) {
    if (!r.analysed) return r.message;
    const auto* w = worst(r);
    return w ? metric_brief(*w) : "";
}

std::string run_verdict(const CaseRun& r) {
    if (r.outcome == Outcome::refused) return "cannot represent";
    if (r.outcome == Outcome::failed) return "failed";
    if (!r.analysed) return r.outcome == Outcome::unstable ? "unstable" : "no metrics";
    int checked = 0, missed = 0;
    for (const auto& m : r.analysis.metrics) {
        if (m.check == metrics::Check::info) continue;
        ++checked;
        if (!m.pass()) ++missed;
    }
    std::string v = missed ? "MISS " + std::to_string(missed) + "/" + std::to_string(checked)
                           : "pass " + std::to_string(checked) + "/" + std::to_string(checked);
    if (r.outcome == Outcome::unstable) v += " (unstable)";
    return v;
}

std::string summary_csv(const std::vector<CaseResult>& cases) {
    std::ostringstream o;
    o << "case,variant,backend,contact_mode,model,metric,unit,value,reference,relative_error,tolerance,pass,"
         "wall_seconds,status\n";
    for (const auto& c : cases) {
        for (const auto& r : c.runs) {
            const std::string head = c.name + "," + r.variant.name + "," + r.variant.backend + "," +
                                     r.variant.contact_label() + "," + r.variant.model + ",";
            const std::string tail = "," + num(r.wall_seconds) + "," + csv(validation::to_string(r.outcome)) + "\n";
            if (!r.analysed) {
                std::string pass = r.outcome == Outcome::refused ? "cannot represent: " + r.message
                                                                 : std::string(validation::to_string(r.outcome)) + ": " + r.message;
                o << head << "run,,,,,," << csv(pass) << tail;
                continue;
            }
            auto row = [&](const metrics::Metric& m) {
                o << head << csv(m.name) << "," << csv(m.unit) << "," << (m.measured ? num(m.value) : "") << ","
                  << (m.has_reference ? num(m.reference) : "") << ","
                  << (m.has_reference && m.measured && m.reference != 0.0 ? num(m.relative_error()) : "") << ","
                  << csv(m.tolerance_text()) << "," << m.verdict() << tail;
            };
            for (const auto& m : r.analysis.metrics) row(m);
            for (const auto& m : r.diffs) row(m);
        }
    }
    return o.str();
}

std::string verdict_text(const std::vector<CaseResult>& cases) {
    std::ostringstream o;
    char line[512];
    std::snprintf(line, sizeof line, "%-18s %-16s %-18s %s\n", "case", "variant", "verdict", "worst metric");
    o << line;
    for (const auto& c : cases)
        for (const auto& r : c.runs) {
            std::string detail = worst_metric_text(r);
            if (detail.size() > 140) detail = detail.substr(0, 137) + "...";
            std::snprintf(line, sizeof line, "%-18s %-16s %-18s %s\n", c.name.c_str(), r.variant.name.c_str(),
                          run_verdict(r).c_str(), detail.c_str());
            o << line;
        }
    return o.str();
}

}  // namespace cairn::report

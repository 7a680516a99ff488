#include "report/validation_report.hpp"

#include "report/text.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace cairn::report {

using validation::CaseResult;
using validation::CaseRun;

namespace {

/// the metric that misses by the most (relative to its tolerance), or the first checked one
const metrics::Metric* worst(const CaseRun& r) {
    const metrics::Metric* w = nullptr;
    double score = -1.0;
    for (const auto& m : r.analysis.metrics) {
        if (!m.judged()) continue;
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
        return m.name + " " + number_text(m.value) + " " + m.unit + " vs " + number_text(m.reference) + " (" + percent_text(m.relative_error()) +
               ", tol " + m.tolerance_text() + ")";
    const std::string value = m.name + " " + number_text(m.value) + " " + m.unit;
    if (!m.has_reference) return value + " (" + m.tolerance_text() + ")";
    return value + " vs " + number_text(m.reference) + " " + m.unit + " (" + m.tolerance_text() + ")";
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
    int checked = 0, missed = 0, nc = 0;
    for (const auto& m : r.analysis.metrics) {
        if (m.check == metrics::Check::not_comparable) ++nc;
        if (!m.judged()) continue;
        ++checked;
        if (!m.pass()) ++missed;
    }
    std::string v = missed    ? "miss " + std::to_string(missed) + "/" + std::to_string(checked)
                    : checked ? "pass " + std::to_string(checked) + "/" + std::to_string(checked)
                              : "not comparable";
    if (checked && nc) v += ", " + std::to_string(nc) + " not comparable";
    if (r.outcome == Outcome::unstable) v += " (unstable)";
    return v;
}

std::string verdict_cell(const CaseRun& r) {
    const std::string v = run_verdict(r);
    int nc = 0;
    if (r.analysed)
        for (const auto& m : r.analysis.metrics) nc += m.check == metrics::Check::not_comparable;
    const std::string tail = nc ? " (" + std::to_string(nc) + " n.c.)" : "";
    if (v.rfind("pass", 0) == 0) return "pass" + tail;
    if (v.rfind("miss", 0) == 0) return "miss" + tail;
    if (v.rfind("not comparable", 0) == 0) return "n.c.";
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
            const std::string tail = "," + number_text(r.wall_seconds) + "," + report::csv_field(validation::outcome_text(r.outcome)) + "\n";
            if (!r.analysed) {
                std::string pass = r.outcome == Outcome::refused ? "cannot represent: " + r.message
                                                                 : std::string(validation::outcome_text(r.outcome)) + ": " + r.message;
                o << head << "run,,,,,," << report::csv_field(pass) << tail;
                continue;
            }
            auto row = [&](const metrics::Metric& m) {
                o << head << report::csv_field(m.name) << "," << report::csv_field(m.unit) << "," << (m.measured ? number_text(m.value) : "") << ","
                  << (m.has_reference ? number_text(m.reference) : "") << ","
                  << (m.has_reference && m.measured && m.reference != 0.0 ? number_text(m.relative_error()) : "") << ","
                  << report::csv_field(m.tolerance_text()) << ","
                  << (m.check == metrics::Check::not_comparable ? report::csv_field("not comparable: " + m.basis) : std::string(m.verdict()))
                  << tail;
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

#include "bench/trade_point.hpp"

#include "report/text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace cairn::bench {

std::string TradePoint::key() const { return case_name + "|" + variant + "|" + knobs; }

bool TradePoint::measured() const { return status == "completed" && std::isfinite(error); }

std::vector<size_t> pareto_front(const std::vector<TradePoint>& points) {
    std::vector<size_t> idx;
    for (size_t i = 0; i < points.size(); ++i)
        if (points[i].measured() && std::isfinite(points[i].wall_seconds)) idx.push_back(i);
    // by wall time, then error: a point is on the front when its error beats every cheaper one
    std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) {
        if (points[a].wall_seconds != points[b].wall_seconds) return points[a].wall_seconds < points[b].wall_seconds;
        return points[a].error < points[b].error;
    });
    std::vector<size_t> front;
    double best = INFINITY;
    for (size_t i : idx)
        if (points[i].error < best) {
            front.push_back(i);
            best = points[i].error;
        }
    return front;
}

std::optional<size_t> cheapest_reaching(const std::vector<TradePoint>& points, const std::string& case_name,
                                        const std::string& variant, double target) {
    std::optional<size_t> best;
    for (size_t i = 0; i < points.size(); ++i) {
        const TradePoint& p = points[i];
        if (p.case_name != case_name || p.variant != variant || !p.measured() || p.error > target) continue;
        if (!best || p.wall_seconds < points[*best].wall_seconds) best = i;
    }
    return best;
}

std::optional<size_t> most_accurate(const std::vector<TradePoint>& points, const std::string& case_name,
                                    const std::string& variant) {
    std::optional<size_t> best;
    for (size_t i = 0; i < points.size(); ++i) {
        const TradePoint& p = points[i];
        if (p.case_name != case_name || p.variant != variant || !p.measured()) continue;
        const TradePoint* b = best ? &points[*best] : nullptr;
        if (!b || p.error < b->error || (p.error == b->error && p.wall_seconds < b->wall_seconds)) best = i;
    }
    return best;
}

namespace {

const char* kColumns[] = {"key", "case", "backend", "variant", "knobs", "kn", "dt", "steps", "sim_seconds",
                          "wall_seconds", "error", "error_metric", "status"};
constexpr size_t kNumColumns = sizeof(kColumns) / sizeof(kColumns[0]);

double to_number(const std::string& s) {
    if (s.empty()) return NAN;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    return end && *end == '\0' ? v : NAN;
}

}  // namespace

std::string trade_csv_header() {
    std::string h;
    for (size_t i = 0; i < kNumColumns; ++i) h += (i ? "," : "") + std::string(kColumns[i]);
    return h;
}

std::string trade_csv_row(const TradePoint& p) {
    std::ostringstream o;
    o << report::csv_field(p.key()) << "," << p.case_name << "," << p.backend << "," << p.variant << ","
      << report::csv_field(p.knobs) << "," << report::number_text(p.kn) << "," << report::number_text(p.dt) << "," << p.steps << ","
      << report::number_text(p.sim_seconds) << "," << report::number_text(p.wall_seconds) << "," << report::number_text(p.error) << ","
      << report::csv_field(p.error_metric) << "," << report::csv_field(p.status);
    return o.str();
}

std::vector<TradePoint> parse_trade_csv(const std::string& text) {
    std::vector<TradePoint> out;
    std::istringstream in(text);
    std::string line;
    bool header = true;
    while (std::getline(in, line)) {
        if (header) { header = false; continue; }
        const auto f = report::split_csv_line(line);
        if (f.size() != kNumColumns || f[12].empty()) continue;   // a row cut short by an interruption
        TradePoint p;
        p.case_name = f[1];
        p.backend = f[2];
        p.variant = f[3];
        p.knobs = f[4];
        p.kn = to_number(f[5]);
        p.dt = to_number(f[6]);
        p.steps = std::isfinite(to_number(f[7])) ? (long long)to_number(f[7]) : 0;
        p.sim_seconds = to_number(f[8]);
        p.wall_seconds = to_number(f[9]);
        p.error = to_number(f[10]);
        p.error_metric = f[11];
        p.status = f[12];
        if (p.key() != f[0]) continue;
        out.push_back(p);
    }
    return out;
}

std::vector<TradePoint> read_trade_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) return {};
    std::stringstream ss;
    ss << in.rdbuf();
    return parse_trade_csv(ss.str());
}

}  // namespace cairn::bench

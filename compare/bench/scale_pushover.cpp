#include "bench/scale_pushover.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "bench/wall_bench.hpp"
#include "cases/case_analysis.hpp"
#include "cases/case_kind.hpp"
#include "error.hpp"
#include "report/text.hpp"
#include "run/runner.hpp"

namespace cairn::bench {

namespace {

std::string setting_text(const std::vector<Override>& o) {
    std::string s;
    for (const auto& x : o) s += (s.empty() ? "" : " ") + x.key + "=" + x.value;
    return s;
}

}  // namespace

std::vector<std::vector<Override>> pushover_settings(const std::string& backend) {
    std::vector<std::vector<Override>> out;
    if (backend == "dem") {
        for (const char* f : {"0.4", "0.2", "0.1"}) out.push_back({{"run.dt", "\"auto\""}, {"run.dt_safety", f}});
        return out;
    }
    for (const char* dt : {"1e-3", "3e-4", "1e-4"}) {
        std::vector<Override> o{{"run.dt", dt}};
        if (backend == "ode") o.push_back({"backends.ode.stepper", "\"step\""});
        out.push_back(o);
    }
    return out;
}

std::vector<PushoverPoint> scale_pushover(const std::string& path, const std::vector<std::string>& backends,
                                          double tolerance,
                                          const std::function<std::unique_ptr<Backend>(const std::string&)>& make,
                                          bool quiet) {
    std::vector<PushoverPoint> out;
    for (const auto& name : backends)
        for (const auto& setting : pushover_settings(name)) {
            if (cheapest_reaching(out, name, tolerance)) break;   // a cheaper setting already does
            PushoverPoint p{name, setting_text(setting), 0.0, NAN, NAN, NAN, 0.0, ""};
            try {
                const Scene s = load_scene(path, setting);
                auto b = make(name);
                RunOptions ro;
                ro.contact_mode = "rigid";   // the reference is the rigid wall (dem: its own penalty joints)
                CollectingSink sink;
                const RunResult r = run_scene(*b, s, ro, sink);
                p.dt = r.dt;
                p.cost = r.final_time > 0.0 ? r.wall_seconds / r.final_time : 0.0;
                p.status = r.status == RunStatus::completed ? "completed"
                           : r.status == RunStatus::unstable ? "unstable: " + r.message
                                                             : "interrupted";
                const auto a = cases::analyse_case(s, sink.samples, {name == "dem"});
                if (!a.metrics.empty()) {
                    const auto& m = a.metrics.front();   // a/g when the top turns the threshold
                    p.reference = m.reference;
                    if (m.measured) p.multiplier = m.value, p.error = m.value / m.reference - 1.0;
                }
            } catch (const Error& e) {
                p.status = std::string("refused: ") + e.what();
            }
            if (!quiet)
                std::fprintf(stderr, "scale pushover %s %s: a/g %.4g (reference %.4g), %.3g s per simulated s, %s\n",
                             name.c_str(), p.setting.c_str(), p.multiplier, p.reference, p.cost,
                             p.status.substr(0, 80).c_str());
            out.push_back(p);
        }
    return out;
}

const PushoverPoint* cheapest_reaching(const std::vector<PushoverPoint>& points, const std::string& backend,
                                       double tolerance) {
    const PushoverPoint* best = nullptr;
    for (const auto& p : points)
        if (p.backend == backend && p.status == "completed" && std::abs(p.error) <= tolerance &&
            (!best || p.cost < best->cost))
            best = &p;
    return best;
}

std::string pushover_csv(const std::vector<PushoverPoint>& points) {
    std::ostringstream o;
    auto num = [](double x) { return report::number_text(x); };
    o << "backend,setting,dt,multiplier,reference,error,cost,status\n";
    for (const auto& p : points)
        o << p.backend << "," << report::csv_field(p.setting) << "," << num(p.dt) << "," << num(p.multiplier) << ","
          << num(p.reference) << "," << num(p.error) << "," << num(p.cost) << "," << report::csv_field(p.status) << "\n";
    return o.str();
}

std::vector<PushoverPoint> parse_pushover_csv(const std::string& text) {
    std::vector<PushoverPoint> out;
    for_each_csv_row(text, 8, [&](const std::vector<std::string>& f) {
        out.push_back({f[0], f[1], csv_number(f[2]), csv_number(f[3]), csv_number(f[4]), csv_number(f[5]),
                       csv_number(f[6]), f[7]});
    });
    return out;
}

}  // namespace cairn::bench

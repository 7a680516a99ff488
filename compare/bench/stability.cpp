#include "bench/stability.hpp"

#include "report/text.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "run/run_jobs.hpp"
#include "bench/trade_point.hpp"
#include "geometry/hexahedron.hpp"

namespace cairn::bench {

const char* to_string(StabilityClass c) {
    switch (c) {
        case StabilityClass::stable: return "stable";
        case StabilityClass::unstable: return "unstable";
        case StabilityClass::drifting: return "drifting";
        case StabilityClass::wrong: return "wrong";
        case StabilityClass::refused: return "refused";
    }
    return "?";
}

StabilityClass classify(const StabilityInput& in) {
    if (in.outcome == "unstable" || in.outcome == "failed") return StabilityClass::unstable;
    if (in.outcome == "refused") return StabilityClass::refused;
    if (in.energy_booked && (in.energy_drift || in.max_balance_error > kDriftBound)) return StabilityClass::drifting;
    if (in.has_oracle && !in.oracle_pass) return StabilityClass::wrong;
    return StabilityClass::stable;
}

double max_penetration(const Scene& scene, const std::vector<Sample>& samples) {
    if (!scene.reference || samples.empty()) return NAN;
    const int a = scene.reference->block;
    const BlockDef& ref = scene.blocks.at(size_t(a));
    double top = -INFINITY;
    for (const auto& b : scene.blocks)
        if (b.fixed) {
            for (const auto& c : b.corners) top = std::max(top, (b.position + b.orientation * c).z());
            break;
        }
    if (!std::isfinite(top)) return NAN;
    const Vec3 centre = mass_properties(ref.corners, 1.0).centre;
    const int f = [&] {
        int k = 0;
        for (int i = 0; i < a; ++i) k += scene.blocks[size_t(i)].fixed ? 0 : 1;
        return k;
    }();
    double pen = 0.0;
    for (const auto& s : samples) {
        const BlockState& st = s.blocks.at(size_t(f));
        for (const auto& c : ref.corners) pen = std::max(pen, top - (st.position + st.orientation * (c - centre)).z());
    }
    return pen;
}

std::vector<StabilityPoint> run_stability(std::vector<StabilityConfig>& configs, int jobs, bool quiet,
                                          const std::vector<BackendInfo>& backends) {
    std::vector<RunSpec> specs;
    for (const auto& c : configs) {
        RunSpec s;
        s.scene = &c.scene;
        s.backend = c.point.backend;
        s.options.contact_mode = c.contact_mode;
        s.options.limits.allow_unstable_dt = true;   // the map goes beyond the critical step
        s.label = c.point.parameter + " " + c.point.value_text;
        specs.push_back(std::move(s));
    }
    std::vector<StabilityPoint> out(configs.size());
    JobsOptions options;
    options.jobs = jobs;
    options.quiet = quiet;
    options.tag = "stability";
    run_jobs(specs, backends, options, [&](size_t j, JobResult& r) {
        StabilityConfig& c = configs[j];
        StabilityPoint p = c.point;
        StabilityInput in;
        in.outcome = to_string(r.outcome);
        in.energy_booked = p.energy_booked;
        in.energy_drift = r.result.energy_drift;
        in.max_balance_error = r.result.max_balance_error;
        p.message = r.message;
        p.dt = r.result.dt;
        p.steps = r.result.steps;
        p.wall_seconds = r.median_wall;
        p.max_balance_error = r.result.max_balance_error;
        p.penetration = r.result.samples.empty() ? NAN : max_penetration(c.scene, r.result.samples);
        if (r.outcome == Outcome::completed) {
            try {
                const Judgement jd = c.judge(c.scene, r.result.samples);
                in.oracle_pass = jd.pass;
                p.check = jd.text;
            } catch (const std::exception& e) {
                in.oracle_pass = false;
                p.check = std::string("analysis failed: ") + e.what();
            }
        } else {
            in.has_oracle = false;
        }
        p.cls = classify(in);
        out[j] = p;   // each worker writes its own slot
    });
    return out;
}

namespace {

const char* kHeader =
    "backend,parameter,value,value_text,class,max_balance_error,energy_booked,penetration,dt,steps,wall_seconds,check,message";

double num(const std::string& s) {
    if (s.empty()) return NAN;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    return end && *end == '\0' ? v : NAN;
}

}  // namespace

std::string stability_csv(const std::vector<StabilityPoint>& points) {
    std::ostringstream o;
    o << kHeader << "\n";
    for (const auto& p : points)
        o << p.backend << "," << report::csv_field(p.parameter) << "," << report::number_text(p.value) << "," << report::csv_field(p.value_text)
          << "," << to_string(p.cls) << "," << report::number_text(p.max_balance_error) << "," << (p.energy_booked ? 1 : 0)
          << "," << report::number_text(p.penetration) << "," << report::number_text(p.dt) << "," << p.steps << ","
          << report::number_text(p.wall_seconds) << "," << report::csv_field(p.check) << "," << report::csv_field(p.message) << "\n";
    return o.str();
}

std::vector<StabilityPoint> parse_stability_csv(const std::string& text) {
    std::vector<StabilityPoint> out;
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        const auto f = report::split_csv_line(line);
        if (f.size() != 13) continue;
        StabilityPoint p;
        p.backend = f[0];
        p.parameter = f[1];
        p.value = num(f[2]);
        p.value_text = f[3];
        for (auto c : {StabilityClass::stable, StabilityClass::unstable, StabilityClass::drifting,
                       StabilityClass::wrong, StabilityClass::refused})
            if (f[4] == to_string(c)) p.cls = c;
        p.max_balance_error = num(f[5]);
        p.energy_booked = f[6] == "1";
        p.penetration = num(f[7]);
        p.dt = num(f[8]);
        p.steps = std::isfinite(num(f[9])) ? (long long)num(f[9]) : 0;
        p.wall_seconds = num(f[10]);
        p.check = f[11];
        p.message = f[12];
        out.push_back(p);
    }
    return out;
}

}  // namespace cairn::bench

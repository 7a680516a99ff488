#include "bench/wall_bench.hpp"

#include "scene/wall_builder.hpp"
#include "report/text.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "run/run_jobs.hpp"
#include "bench/trade_point.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"

namespace cairn::bench {

std::vector<WallSetup> wall_setups() {
    return {{"kn 3e7, touching, dt 1e-3", 3e7, 1e-3, false, "rigid"},
            {"kn 3e9, static penetration, dt 1e-4", 3e9, 1e-4, true, "rigid"},
            {"kn 3e9, static penetration, dt 1e-4, engines matched", 3e9, 1e-4, true, "matched"}};
}

Scene wall_scene(int courses, int per_course, const WallSetup& setup) {
    Scene s;
    s.name = "wall";
    s.source = "<wall " + std::to_string(courses) + "x" + std::to_string(per_course) + ">";
    s.materials.push_back({"stone", 2600.0, 30e9, 0.2});
    s.contact.kn = setup.kn;
    s.contact.ks = setup.kn;
    s.contact.friction = 0.6;
    s.run.dt = setup.dt;
    s.run.duration = 1.0;
    // the running-bond wall of cairn make wall, odd courses shifted whole (the first measured setup)
    WallSpec wall;
    wall.courses = courses;
    wall.bricks = per_course;
    wall.half_bricks = false;
    wall.density = 2600.0;
    wall.placed_kn = setup.placed ? setup.kn : 0.0;
    add_wall(s, wall);
    return s;
}

namespace {

/// the contact of a backend on a setup, from the backend's facts
std::string contact_text(const BackendInfo& info, const WallSetup& s) {
    char b[200];
    if (info.contact == ContactModel::penalty)
        std::snprintf(b, sizeof b, "penalty kn = %g N/m³ per hitting point (grid 0.1 m), elastic-Coulomb", s.kn);
    else if (s.contact_mode == "matched")
        std::snprintf(b, sizeof b, "matched springs kn·A/4 per contact point, kn = %g N/m³", s.kn);
    else
        std::snprintf(b, sizeof b, "rigid: %s", info.solver.c_str());
    return b;
}

}  // namespace

std::vector<WallResult> run_wall(const std::vector<std::string>& backends, const std::vector<WallSetup>& setups,
                                 int courses, int per_course, int steps, int repeats,
                                 const std::vector<BackendInfo>& infos, bool quiet) {
    std::vector<WallResult> out;
    for (const auto& setup : setups) {
        const Scene scene = wall_scene(courses, per_course, setup);
        const size_t first = out.size();
        for (const auto& name : backends) {
            const BackendInfo& info = find_backend(infos, name);
            WallResult r{setup.name, name, contact_text(info, setup), setup.kn, setup.dt, courses * per_course, steps, 0.0, 0.0, 0.0, ""};
            std::vector<double> rates;
            try {
                for (int k = 0; k < std::max(1, repeats) && r.status.empty(); ++k) {
                    auto b = info.make();
                    RunOptions ro;
                    ro.contact_mode = setup.contact_mode;
                    b->build(scene, ro);
                    const auto t0 = std::chrono::steady_clock::now();
                    for (int i = 0; i < steps; ++i)
                        if (b->step() != StepStatus::ok) { r.status = "unstable: " + b->failure(); break; }
                    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                    rates.push_back(steps / sec);
                    const Sample x = b->sample();
                    double worst = 0.0;
                    for (int i = 0; i < per_course; ++i) {
                        const size_t fb = size_t((courses - 1) * per_course + i);
                        worst = std::max(worst, (x.blocks.at(fb).position - scene.blocks.at(fb + 1).position).norm());
                    }
                    r.top_settlement = worst;
                }
                if (r.status.empty()) r.status = "completed";
            } catch (const Error& e) {
                r.status = std::string("refused: ") + e.what();
            }
            r.steps_per_second = r.status == "completed" ? median(rates) : 0.0;
            if (!quiet)
                std::fprintf(stderr, "wall [%s] %s: %.1f steps/s, top moved %.3g m, %s\n", setup.name.c_str(),
                             name.c_str(), r.steps_per_second, r.top_settlement, r.status.substr(0, 80).c_str());
            out.push_back(r);
        }
        double bullet = 0.0;
        for (size_t i = first; i < out.size(); ++i)
            if (out[i].backend == "bullet") bullet = out[i].steps_per_second;
        for (size_t i = first; i < out.size(); ++i)
            out[i].ratio_to_bullet = bullet > 0.0 ? out[i].steps_per_second / bullet : 0.0;
    }
    return out;
}

std::string wall_csv(const std::vector<WallResult>& rows) {
    std::ostringstream o;
    o << "setup,backend,contact,kn,dt,blocks,steps,steps_per_second,ratio_to_bullet,top_settlement,status\n";
    for (const auto& r : rows)
        o << report::csv_field(r.setup) << "," << r.backend << "," << report::csv_field(r.contact) << "," << report::number_text(r.kn) << ","
          << report::number_text(r.dt) << "," << r.blocks << "," << r.steps << "," << report::number_text(r.steps_per_second) << ","
          << report::number_text(r.ratio_to_bullet) << "," << report::number_text(r.top_settlement) << "," << report::csv_field(r.status) << "\n";
    return o.str();
}

void for_each_csv_row(const std::string& text, size_t fields,
                      const std::function<void(const std::vector<std::string>&)>& row) {
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        const auto f = report::split_csv_line(line);
        if (f.size() == fields) row(f);
    }
}

double csv_number(const std::string& field) { return field.empty() ? NAN : std::strtod(field.c_str(), nullptr); }

std::vector<WallResult> parse_wall_csv(const std::string& text) {
    std::vector<WallResult> out;
    const auto num = csv_number;
    for_each_csv_row(text, 11, [&](const std::vector<std::string>& f) {
        out.push_back({f[0], f[1], f[2], num(f[3]), num(f[4]), std::atoi(f[5].c_str()), std::atoi(f[6].c_str()),
                       num(f[7]), num(f[8]), num(f[9]), f[10]});
    });
    return out;
}

}  // namespace cairn::bench

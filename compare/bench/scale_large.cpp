#include "bench/scale_large.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "bench/scale_bench.hpp"
#include "bench/wall_bench.hpp"
#include "report/text.hpp"
#include "run/runner.hpp"

namespace cairn::bench {

namespace {

// sums the active sub-contacts of the samples after t = 0 (released touching, none is active then)
class ContactCounter : public SampleSink {
public:
    double sum = 0.0;
    long long count = 0;
    void sample(const Sample& s) override {
        if (s.t > 0.0) sum += s.contacts, ++count;
    }
};

}  // namespace

TowerSpec large_tower(int n) {
    TowerSpec t;
    t.courses = std::max(1, int(std::lround(std::sqrt(double(std::max(n, 1))))));
    const int per = std::max(10, int(std::lround(double(n) / t.courses)));
    // a course holds 2·length + 2·width − 2 bricks
    const int sum = std::max(6, (per + 2) / 2);
    t.length = std::max(3, sum / 2);
    t.width = std::max(3, sum - t.length);
    return t;
}

Scene large_scene(int n, const GroundMotion& record, double duration) {
    Scene s;
    s.source = "bench scale --large";
    s.description = "Brick tower of about " + std::to_string(n) + " bricks under El Centro 1940 NS (cairn bench scale --large)";
    s.materials.push_back({"stone", 2600.0, 30e9, 0.2});
    s.contact.kn = s.contact.ks = 1e9;
    s.contact.friction = 0.7;
    s.contact.damping_rule = ContactDampingRule::ratio;
    s.contact.damping = 0.1;
    s.contact.scheme = ContactScheme::overlap;
    s.contact.subdivision = 1;   // flat joints: the normal force and moment are exact at any sub-division
    s.run.duration = duration;
    s.run.output_interval = 0.05;
    add_tower(s, large_tower(n));
    s.ground_motion = record;
    return s;
}

LargeRun run_large(Backend& backend, int n, const GroundMotion& record, double duration) {
    const Scene scene = large_scene(n, record, duration);
    LargeRun r;
    r.duration = duration;
    for (const auto& b : scene.blocks) r.blocks += b.fixed ? 0 : 1;
    reset_peak_memory();
    ContactCounter counter;
    const auto t0 = std::chrono::steady_clock::now();
    const RunResult run = run_scene(backend, scene, RunOptions{}, counter);
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.peak_mb = peak_memory_mb();
    r.dt = run.dt;
    r.critical_step = run.critical_step;
    r.steps = run.steps;
    r.wall_seconds = run.wall_seconds;
    r.build_seconds = std::max(0.0, total - run.wall_seconds);
    r.contacts = counter.count > 0 ? counter.sum / double(counter.count) : 0.0;
    r.max_balance_error = run.max_balance_error;
    r.energy_closed = !run.energy_drift;
    r.status = run.status == RunStatus::completed ? "completed"
               : run.status == RunStatus::unstable ? "unstable: " + run.message
                                                   : "interrupted";
    if (run.status == RunStatus::completed) r.duration = run.final_time;
    return r;
}

std::string large_csv(const LargeRun& r) {
    const double record_seconds = kLargeRecordSeconds;
    std::ostringstream o;
    auto num = [](double x) { return report::number_text(x); };
    o << "blocks,duration,dt,critical_step,steps,wall_seconds,build_seconds,peak_mb,contacts,ns_per_contact,"
         "max_balance_error,energy_closed,cost,record_seconds,extrapolated_seconds,status\n";
    o << r.blocks << "," << num(r.duration) << "," << num(r.dt) << "," << num(r.critical_step) << "," << r.steps << ","
      << num(r.wall_seconds) << "," << num(r.build_seconds) << "," << num(r.peak_mb) << "," << num(r.contacts) << ","
      << num(r.ns_per_contact()) << "," << num(r.max_balance_error) << "," << (r.energy_closed ? "yes" : "no") << ","
      << num(r.cost()) << "," << num(record_seconds) << "," << num(r.cost() * record_seconds) << ","
      << report::csv_field(r.status) << "\n";
    return o.str();
}

LargeRun parse_large_csv(const std::string& text) {
    LargeRun r;
    for_each_csv_row(text, 16, [&](const std::vector<std::string>& f) {
        r.blocks = std::atoi(f[0].c_str());
        r.duration = csv_number(f[1]);
        r.dt = csv_number(f[2]);
        r.critical_step = csv_number(f[3]);
        r.steps = std::atoll(f[4].c_str());
        r.wall_seconds = csv_number(f[5]);
        r.build_seconds = csv_number(f[6]);
        r.peak_mb = csv_number(f[7]);
        r.contacts = csv_number(f[8]);
        r.max_balance_error = csv_number(f[10]);
        r.energy_closed = f[11] == "yes";
        r.status = f[15];
    });
    return r;
}

}  // namespace cairn::bench

#include "run/runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "error.hpp"
#include "run/energy_scale.hpp"
#include "run/stop.hpp"

namespace cairn {

namespace {

/// energy growth beyond this fraction of the scale has no source: the run is unstable
constexpr double kGrowthBound = 1.0;
/// wall time between progress calls, s
constexpr double kProgressEvery = 0.5;

bool finite(const Vec3& v) { return v.allFinite(); }

/// empty if every number in the sample is finite, otherwise what is not
std::string non_finite(const Sample& s, const Scene& scene) {
    const Energies& e = s.energy;
    for (double x : {s.t, e.kinetic, e.potential, e.contact, e.strain, e.dissipated, e.external})
        if (!std::isfinite(x)) return "an energy or the time is not finite (NaN or inf)";
    for (size_t i = 0; i < s.probes.size(); ++i)
        if (!finite(s.probes[i]))
            return "probe " + (i < scene.probes.size() ? scene.probes[i].name : std::to_string(i)) +
                   " position is not finite (NaN or inf)";
    for (const auto& b : s.blocks)
        if (!finite(b.position) || !b.orientation.coeffs().allFinite() || !finite(b.velocity) ||
            !finite(b.angular_velocity))
            return "a block state is not finite (NaN or inf)";
    return {};
}

/// the message of an unstable run: time, reason, time step and critical step
std::string unstable_message(double t, const std::string& why, double dt, double critical) {
    std::string m = "unstable at t = " + number_format("%.6g", t) + " s: " +
                    (why.empty() ? std::string("the backend reported an unstable step") : why) +
                    "; time step " + number_format("%.2e", dt) + " s, ";
    m += critical > 0.0 ? "critical step " + number_format("%.2e", critical) + " s"
                        : std::string("critical step unknown");
    return m + " (run with a smaller dt or dt = \"auto\")";
}

}  // namespace

std::string energy_created_text(const RunResult& r) {
    if (!r.energy_created) return {};
    return "energy appeared from nowhere: +" + number_format("%.3g", r.energy_gain) + " J by t = " +
           number_format("%.6g", r.energy_gain_time) + " s (" +
           number_format("%.2g", r.energy_gain / r.energy_gain_scale) + " × its scale, the larger of the motion's energy and the heaviest block's m·g·diameter: " +
           number_format("%.3g", r.energy_gain_scale) + " J)";
}

RunResult run_scene(Backend& backend, const Scene& scene, const RunOptions& options, SampleSink& sink,
                    const ProgressFn& progress) {
    backend.build(scene, options);

    RunResult r;
    r.dt = backend.time_step();
    r.critical_step = backend.critical_step();
    const RunSize size = check_run_size(scene, backend.name(), r.dt, r.critical_step, options.limits);
    r.output_every = int(std::min<long long>(size.output_every, std::numeric_limits<int>::max()));
    const long long total_steps = size.steps;

    EnergyScale energy_scale(scene);
    double lowest_error = 0.0;   // J, the lowest balance error so far

    // check one sample; returns the reason if the run must stop
    auto check = [&](const Sample& s) -> std::string {
        if (auto bad = non_finite(s, scene); !bad.empty()) return bad;
        const Energies& e = s.energy;
        if (r.sample_count == 0) r.initial_total = e.total();
        const EnergyBounds scale = energy_scale.add(e);
        const double err = e.total() - r.initial_total;
        r.max_balance_error = std::max(r.max_balance_error, std::abs(err) / scale.motion);
        if (std::abs(err) > kDriftBound * scale.motion) r.energy_drift = true;
        lowest_error = std::min(lowest_error, err);
        const double rise = err - lowest_error;
        if (rise > r.energy_gain) {
            r.energy_gain = rise;
            r.energy_gain_time = s.t;
            r.energy_gain_scale = scale.created;
        }
        if (rise > kCreatedBound * scale.created) r.energy_created = true;
        if (err > kGrowthBound * scale.growth)
            return "energy growing without a source (balance error " + number_format("%.3g", err) +
                   " J against an energy scale of " + number_format("%.3g", scale.growth) + " J)";
        return {};
    };

    // hand a finite sample to the sink and keep the running summary
    auto keep = [&](const Sample& s) {
        ++r.sample_count;
        r.final_time = s.t;
        r.final_energy = s.energy;
        sink.sample(s);
    };

    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    double next_progress = kProgressEvery;

    // record a sample; false (with the message set) when it shows the run is unstable
    long long sampled = -1;   // step of the last sample taken
    auto record = [&](long long step) {
        sampled = step;
        const Sample s = backend.sample();
        const std::string why = check(s);
        const bool finite_sample = why.empty() || non_finite(s, scene).empty();
        if (finite_sample) keep(s);
        if (why.empty()) return true;
        r.status = RunStatus::unstable;
        r.message = unstable_message(double(step) * r.dt, why, r.dt, r.critical_step);
        return false;
    };

    sink.begin(scene, r);
    bool ok = record(0);
    for (long long k = 1; ok && k <= total_steps; ++k) {
        if (stop_requested()) {
            // the state reached so far ends the partial trajectory
            if (sampled != r.steps) ok = record(r.steps);
            if (ok) {
                r.status = RunStatus::interrupted;
                r.message = "interrupted at t = " + number_format("%.6g", double(r.steps) * r.dt) +
                            " s after " + std::to_string(r.steps) + " of " +
                            std::to_string(total_steps) + " steps";
            }
            break;
        }
        const StepStatus st = backend.step();
        r.steps = k;
        if (st == StepStatus::unstable) {
            r.status = RunStatus::unstable;
            r.message = unstable_message(double(k) * r.dt, backend.failure(), r.dt, r.critical_step);
            // keep the state at failure when it is still finite: it shows what went wrong
            const Sample s = backend.sample();
            if (non_finite(s, scene).empty()) keep(s);
            break;
        }
        if (k % r.output_every == 0 || k == total_steps) ok = record(k);
        if (progress && elapsed() >= next_progress) {
            progress(double(k) / double(total_steps));
            next_progress = elapsed() + kProgressEvery;
        }
    }
    r.wall_seconds = elapsed();
    for (const std::string& note : backend.notes())
        if (note.rfind("warning: ", 0) == 0) r.warnings.push_back(note);
    sink.end(r);
    return r;
}

RunResult run_scene(Backend& backend, const Scene& scene, const RunOptions& options,
                    const ProgressFn& progress) {
    CollectingSink sink;
    RunResult r = run_scene(backend, scene, options, sink, progress);
    r.samples = std::move(sink.samples);
    return r;
}

}  // namespace cairn

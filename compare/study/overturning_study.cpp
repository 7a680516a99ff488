// the overturning study: grid, bisection and the oracle's boundary
#include "study/overturning_study.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "cases/case_util.hpp"
#include "error.hpp"
#include "run/core_pool.hpp"
#include "run/runner.hpp"
#include "run/sample_sink.hpp"
#include "run/stop.hpp"
#include "scene/scene_io.hpp"

namespace cairn::study {

namespace {

std::string num(double v) {
    std::ostringstream o;
    o.precision(12);
    o << v;
    return o.str();
}

/// ends a backend run once its verdict is known
struct Decided {
    bool overturned;
};

/// the verdict of a backend run from its samples (VerdictRule)
class VerdictSink : public SampleSink {
public:
    VerdictSink(VerdictRule rule, int free_block) : rule_(rule), f_(free_block) {}
    double max_theta = 0.0, last_theta = 0.0;
    void sample(const Sample& s) override {
        const Quat& q = s.blocks.at(size_t(f_)).orientation;
        const double th = 2.0 * std::atan2(q.y(), q.w());   // twist about +y: θ > 0 moves the top to +x
        max_theta = std::max(max_theta, std::abs(th));
        last_theta = th;
        const double e = s.energy.kinetic + s.energy.potential + s.energy.contact;
        if (!std::isfinite(e0_)) e0_ = e;
        if (std::abs(th) >= M_PI / 3.0) throw Decided{true};
        if (s.t >= rule_.pulse_end && e - e0_ < 0.5 * rule_.hill) throw Decided{false};
    }

private:
    VerdictRule rule_;
    int f_;
    double e0_ = NAN;
};

OverturningRun run_backend(const OverturningSetup& s, const OverturningRun& job, const BackendMaker& make) {
    OverturningRun out = job;
    const auto start = std::chrono::steady_clock::now();
    try {
        const oracle::Pulse pulse = point_pulse(s, job.ratio, job.level);
        const Scene scene = pulse_scene(s, pulse);
        const int b = rocking_block_of(scene).block;
        const double mass = cases::block_mass(scene, b), radius = std::hypot(s.b, s.h);
        const VerdictRule rule{pulse.duration(), mass * s.g * radius * (1.0 - std::cos(std::atan(s.b / s.h))),
                               std::atan(s.b / s.h)};
        VerdictSink sink(rule, cases::free_index(scene, b));
        auto backend = make(job.method);
        try {
            const RunResult r = run_scene(*backend, scene, RunOptions{}, sink);
            if (r.status != RunStatus::completed) {
                out.status = r.status == RunStatus::unstable ? "unstable: " + r.message : "interrupted";
            } else {
                out.overturned = std::abs(sink.last_theta) > rule.alpha;   // undecided at the end
            }
        } catch (const Decided& d) {
            out.overturned = d.overturned;
        }
        out.max_theta = sink.max_theta;
    } catch (const std::exception& e) {
        out.status = std::string(e.what()).substr(0, 300);   // a scene message can quote a whole record
    }
    out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

/// the first overturning level of a method's grid verdicts at one ratio, bracketed
Boundary bracket(const std::vector<OverturningRun>& runs, const std::string& method, double ratio) {
    Boundary b;
    b.method = method;
    b.ratio = ratio;
    double last_safe = 1.0;   // below g tan α a rigid block never uplifts
    for (const auto& r : runs) {
        if (r.method != method || r.ratio != ratio) continue;
        if (r.status != "completed") {
            b.note = "run failed at a_p/(g tan a) = " + num(r.level) + ": " + r.status;
            return b;
        }
        if (r.overturned) {
            b.lo = last_safe;
            b.hi = r.level;
            return b;
        }
        last_safe = r.level;
    }
    b.note = "no overturning on the grid";
    return b;
}

}  // namespace

RockingBlockOf rocking_block_of(const Scene& scene) {
    RockingBlockOf r;
    for (size_t i = 0; i < scene.blocks.size(); ++i)
        if (!scene.blocks[i].fixed) {
            if (r.block >= 0) throw Error(scene.source + ": the study needs exactly one free block (" +
                                          scene.blocks[size_t(r.block)].name + " and " + scene.blocks[i].name + ")");
            r.block = int(i);
        }
    if (r.block < 0) throw Error(scene.source + ": the study needs one free block (all are fixed)");
    const BlockDef& b = scene.blocks[size_t(r.block)];
    if (b.orientation.angularDistance(Quat::Identity()) > 1e-12)
        throw Error(scene.source + ": blocks." + b.name + ".orientation: the block must stand upright");
    double x0 = 1e300, x1 = -1e300, z0 = 1e300, z1 = -1e300;
    for (const auto& c : b.corners) {
        x0 = std::min(x0, c.x()), x1 = std::max(x1, c.x()), z0 = std::min(z0, c.z()), z1 = std::max(z1, c.z());
    }
    r.b = 0.5 * (x1 - x0);
    r.h = 0.5 * (z1 - z0);
    r.g = -scene.gravity.z();
    if (!(r.g > 0.0) || scene.gravity.head<2>().norm() > 0.0)
        throw Error(scene.source + ": gravity: the study needs gravity along -z");
    return r;
}

std::string block_scene_text(double w, double d, double h) {
    if (!(w > 0.0) || !(d > 0.0) || !(h > 0.0) || w > 100.0 || d > 100.0 || h > 100.0)
        throw Error("--block: width, height and depth must be in (0, 100] m (got " + num(w) + ", " + num(h) + ", " +
                    num(d) + ")");
    std::ostringstream o;
    o << "description = \"block " << w << " x " << d << " x " << h << " m on a fixed slab\"\n"
      << "[run]\nduration = 1.0\noutput_interval = 0.002\n"
      << "[materials.stone]\ndensity = 2600\nyoung = 30e9\npoisson = 0.2\n"
      // the in-house engine rocks like Housner's block only with hitting points on the two bottom
      // edges alone (a push at an inner row has a moment about the new edge that keeps the block
      // turning: more of the rotation survives each impact), a stiff spring (a soft edge tilts the
      // block before it uplifts and launches it early) and a dashpot near critical (a plastic corner
      // impact); docs/studies.md gives the measurements
      << "[contact]\nscheme = \"paper\"\ngrid_spacing = " << num(w)
      << "\nkn = 3e10\nks = 3e10\nfriction = 5.0\ndamping_ratio = 0.6\n"
      << "[blocks.A]\nsize = [" << num(w) << ", " << num(d) << ", " << num(h) << "]\nposition = [0.0, 0.0, "
      << num(0.5 * h) << "]\nmaterial = \"stone\"\n"
      // the slab wide enough along x to hold the block lying on its side, and no larger: the in-house
      // engine's hitting points scale with its area (a 6 x 6 m slab makes its runs 60 times slower)
      << "[blocks.B]\nsize = [" << num(w + 2.0 * h + 0.4) << ", " << num(d + 0.3)
      << ", 0.5]\nposition = [0.0, 0.0, -0.25]\n"
      << "material = \"stone\"\nfixed = true\n";
    return o.str();
}

std::vector<double> default_levels() { return {1.5, 2.0, 2.75, 3.75, 5.0, 6.75, 9.0, 12.0}; }
std::vector<double> default_ratios() { return {1, 2, 3, 4, 5, 6, 7, 8, 9}; }

oracle::RockingOracle setup_oracle(const OverturningSetup& s) { return oracle::RockingOracle(s.b, s.h, s.g); }

oracle::Pulse point_pulse(const OverturningSetup& s, double ratio, double level) {
    const auto o = setup_oracle(s);
    return oracle::Pulse{s.pulse, level * s.g * std::tan(o.alpha()), ratio * o.p()};
}

Scene motion_scene(const std::string& text, const std::string& source, std::vector<Override> overrides,
                   const TimeSeries& ts, double duration) {
    std::ostringstream gm;
    gm << "\n[ground_motion]\nunits = \"m/s2\"\ndirection = [1.0, 0.0, 0.0]\ntime = [";
    for (size_t i = 0; i < ts.time.size(); ++i) gm << (i ? ", " : "") << num(ts.time[i]);
    gm << "]\nacceleration = [";
    for (size_t i = 0; i < ts.value.size(); ++i) gm << (i ? ", " : "") << num(ts.value[i]);
    gm << "]\n";
    overrides.push_back({"run.duration", num(duration)});
    return parse_scene(text + gm.str(), source, overrides);
}

Scene pulse_scene(const OverturningSetup& s, const oracle::Pulse& pulse) {
    return motion_scene(s.scene_text, s.scene_source, s.overrides, pulse.sampled(pulse.duration() / 800.0),
                        pulse.duration() + s.tail);
}

OverturningRun oracle_run(const OverturningSetup& s, double ratio, double level) {
    const auto o = setup_oracle(s);
    const oracle::Pulse pulse = point_pulse(s, ratio, level);
    oracle::RockingOptions opt;
    opt.duration = pulse.duration() + 60.0;   // decided long before: it settles or falls
    const auto res = o.run(pulse.motion(), opt);
    OverturningRun r;
    r.method = "oracle";
    r.ratio = ratio;
    r.level = level;
    r.overturned = res.overturned;
    r.max_theta = res.max_abs_theta;
    if (res.stop == "duration") r.status = "undecided after " + num(opt.duration) + " s";
    return r;
}

std::vector<OverturningRun> grid_jobs(const OverturningSetup& s) {
    std::vector<OverturningRun> jobs;
    for (const auto& m : s.backends)
        for (double w : s.ratios)
            for (double l : s.levels) {
                OverturningRun j;
                j.method = m;
                j.ratio = w;
                j.level = l;
                jobs.push_back(j);
            }
    return jobs;
}

void run_pool(size_t n, int jobs, const std::function<std::string(size_t)>& method,
              const std::function<void(size_t)>& fn, const std::function<bool(const std::string&)>& exclusive) {
    run_on_cores(n, jobs, fn, [&](size_t k) { return exclusive && exclusive(method(k)); });
}

std::vector<OverturningRun> run_overturning_jobs(const OverturningSetup& s, const std::vector<OverturningRun>& jobs,
                                                 const BackendMaker& make) {
    std::vector<OverturningRun> out(jobs.size());
    std::mutex print;
    size_t done = 0;
    run_pool(jobs.size(), s.jobs, [&](size_t k) { return jobs[k].method; }, [&](size_t k) {
        out[k] = run_backend(s, jobs[k], make);
        std::lock_guard<std::mutex> lock(print);
        ++done;
        if (!s.quiet)
            std::cerr << "overturning " << done << "/" << jobs.size() << ": " << out[k].method << " w/p=" << out[k].ratio
                      << " a/(g tan a)=" << out[k].level << " "
                      << (out[k].status != "completed" ? out[k].status : out[k].overturned ? "overturned" : "safe") << " "
                      << out[k].wall_seconds << " s\n";
    }, s.exclusive);
    if (stop_requested()) throw Error("the overturning study was interrupted");
    return out;
}

namespace {

/// the oracle's minimum overturning amplitude at a ratio: the first overturning level on a scan
/// in steps of 2 % from `from` to `to`, then bisected 40 times; NaN if none
double oracle_minimum(const OverturningSetup& s, double ratio, double from, double to, double* lo_out = nullptr) {
    double lo = NAN, hi = NAN, prev = from;
    for (double l = from; l <= to; l *= 1.02) {
        if (oracle_run(s, ratio, l).overturned) {
            lo = prev;
            hi = l;
            break;
        }
        prev = l;
    }
    if (!std::isfinite(hi)) return NAN;
    for (int i = 0; i < 40; ++i) {
        const double m = 0.5 * (lo + hi);
        (oracle_run(s, ratio, m).overturned ? hi : lo) = m;
    }
    if (lo_out) *lo_out = lo;
    return 0.5 * (lo + hi);
}

}  // namespace

OverturningResult run_overturning(const OverturningSetup& s, const BackendMaker& make) {
    const auto start = std::chrono::steady_clock::now();
    OverturningResult res;
    // the oracle on the grid and its boundary per grid frequency
    for (double w : s.ratios)
        for (double l : s.levels) res.grid.push_back(oracle_run(s, w, l));
    const double top = s.levels.empty() ? 10.0 : 1.5 * s.levels.back();
    for (double w : s.ratios) {
        Boundary b;
        b.method = "oracle";
        b.ratio = w;
        double lo = NAN;
        const double m = oracle_minimum(s, w, 1.0, top, &lo);
        if (std::isfinite(m)) {
            b.lo = lo;
            b.hi = 2.0 * m - lo;
            // does the verdict flip more than once within 20 % of the boundary (islands of either verdict)?
            int flips = 0;
            bool prev = false;
            std::vector<double> at;
            for (int i = 0; i <= 400; ++i) {
                const double l = m * (0.8 + 0.4 * i / 400.0);
                const bool v = oracle_run(s, w, l).overturned;
                if (i > 0 && v != prev) {
                    ++flips;
                    at.push_back(l);
                }
                prev = v;
            }
            b.flips = at;
            if (flips > 1) {
                std::string where;
                for (double x : at) where += (where.empty() ? "" : ", ") + num(std::round(x * 1000.0) / 1000.0);
                res.non_monotonic.push_back("at w_p/p = " + num(w) + " the oracle's verdict flips " +
                                            std::to_string(flips) + " times between 0.8 and 1.2 times its minimum " +
                                            "overturning amplitude (at a_p/(g tan a) = " + where + ")");
            }
        } else {
            b.note = "no overturning below a_p/(g tan a) = " + num(top);
        }
        res.boundaries.push_back(b);
    }
    // the oracle's boundary on a fine frequency grid, for the figure
    const double wmax = s.ratios.empty() ? 10.0 : s.ratios.back();
    const double dw = std::max(0.1, (wmax - 0.5) / 100.0);   // at most about 100 frequencies
    for (double w = 0.5; w <= wmax + 1e-9; w += dw) {
        res.fine_ratios.push_back(w);
        res.fine_levels.push_back(oracle_minimum(s, w, 1.0, top));
    }
    // the backends: the grid, then bisection rounds over every (backend, frequency) at once
    const auto grid = run_overturning_jobs(s, grid_jobs(s), make);
    res.grid.insert(res.grid.end(), grid.begin(), grid.end());
    std::vector<Boundary> chains;
    for (const auto& m : s.backends)
        for (double w : s.ratios) chains.push_back(bracket(grid, m, w));
    for (int round = 0; round < s.bisect; ++round) {
        std::vector<OverturningRun> jobs;
        std::vector<size_t> of;
        for (size_t c = 0; c < chains.size(); ++c) {
            if (!chains[c].found() || !chains[c].note.empty()) continue;
            OverturningRun j;
            j.method = chains[c].method;
            j.ratio = chains[c].ratio;
            j.level = chains[c].level();
            jobs.push_back(j);
            of.push_back(c);
        }
        if (jobs.empty()) break;
        const auto runs = run_overturning_jobs(s, jobs, make);
        for (size_t i = 0; i < runs.size(); ++i) {
            Boundary& b = chains[of[i]];
            if (runs[i].status != "completed") {
                b.note = "run failed at a_p/(g tan a) = " + num(runs[i].level) + ": " + runs[i].status;
                continue;
            }
            (runs[i].overturned ? b.hi : b.lo) = runs[i].level;
        }
        res.bisection.insert(res.bisection.end(), runs.begin(), runs.end());
    }
    res.boundaries.insert(res.boundaries.end(), chains.begin(), chains.end());
    res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return res;
}

}  // namespace cairn::study

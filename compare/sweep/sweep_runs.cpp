// expanding a sweep plan into runs: scenes × backends × records × intensities × axes × repeats
#include "sweep/sweep_runs.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <toml++/toml.h>

#include "error.hpp"
#include "output/atomic_write.hpp"
#include "report/text.hpp"
#include "scene/scene_io.hpp"

namespace fs = std::filesystem;

namespace cairn::sweep {

namespace {

/// the scene loader's g (units = "g" multiplies by it), m/s²
constexpr double kG = 9.81;

/// a number as exact text (17 significant digits): the same double gives the same text
std::string exact(double v) { return report::number_text(v, 17); }

/// FNV-1a, 64 bits, as 16 hex digits
std::string hash_id(const std::string& s) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : s) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016" PRIx64, h);
    return buf;
}

/// `s` as a TOML string (escaped by toml++)
std::string quoted(const std::string& s) {
    std::ostringstream o;
    o << toml::value<std::string>(s);
    return o.str();
}

/// the overrides that put a record in a scene (scale set separately)
std::vector<std::string> record_overrides(const RecordSpec& rec, const std::string& records_dir) {
    if (rec.file.empty())
        return {"ground_motion.file=" + quoted((fs::path(records_dir) / (rec.name + ".csv")).string()),
                "ground_motion.units=\"g\"", "ground_motion.time_column=\"t_s\"",
                "ground_motion.acceleration_column=\"accel_g\""};
    return {"ground_motion.file=" + quoted(rec.file), "ground_motion.units=" + quoted(rec.units),
            "ground_motion.time_column=" + quoted(rec.time_column),
            "ground_motion.acceleration_column=" + quoted(rec.acceleration_column)};
}

std::vector<Override> parsed(const std::vector<std::string>& list) {
    std::vector<Override> out;
    for (const auto& s : list) out.push_back(parse_override(s));
    return out;
}

/// write `text` to `path` unless it already holds exactly that
void write_if_changed(const std::string& path, const std::string& text) {
    std::ifstream in(path, std::ios::binary);
    if (in) {
        std::ostringstream old;
        old << in.rdbuf();
        if (old.str() == text) return;
    }
    write_text_atomic(path, text);
}

/// the block the outcome is taken from, and its overturning angle atan(base/height) in its frame
void outcome_block(const Scene& scene, const SweepPlan& plan, const std::string& scene_name, std::string& block,
                   double& angle) {
    int found = -1;
    for (size_t i = 0; i < scene.blocks.size(); ++i) {
        const auto& b = scene.blocks[i];
        if (plan.block.empty() ? !b.fixed : b.name == plan.block) {
            found = int(i);
            break;
        }
    }
    if (found < 0)
        throw Error(plan.path + ": block = " + (plan.block.empty() ? "(none)" : plan.block) + ": scene " + scene_name +
                    (plan.block.empty() ? " has no free block" : " has no such block"));
    const auto& b = scene.blocks[size_t(found)];
    if (b.fixed) throw Error(plan.path + ": block = " + plan.block + ": the block is fixed in scene " + scene_name);
    block = b.name;
    Vec3 lo = b.corners[0], hi = b.corners[0];
    for (const auto& c : b.corners) {
        lo = lo.cwiseMin(c);
        hi = hi.cwiseMax(c);
    }
    const Vec3 e = hi - lo;
    angle = plan.overturn_angle > 0.0 ? plan.overturn_angle : std::atan(std::min(e.x(), e.y()) / e.z());
}

}  // namespace

std::string pulse_csv(const RecordSpec& rec) {
    const double f = rec.frequency;
    const double duration = rec.pulse == "ricker" ? 3.0 / f : double(rec.cycles) / f;
    const int n = rec.pulse == "ricker" ? 1200 : 400 * rec.cycles;   // samples over the pulse
    std::ostringstream o;
    o << "# synthetic " << rec.pulse << " pulse, f = " << exact(f) << " Hz"
      << (rec.pulse == "ricker" ? "" : ", " + std::to_string(rec.cycles) + " cycle(s)")
      << ", unit peak; written by cairn sweep (not a recorded ground motion)\n"
      << "t_s,accel_g\n";
    for (int i = 0; i <= n; ++i) {
        const double t = duration * double(i) / double(n);
        double a = 0.0;
        if (rec.pulse == "sine") a = std::sin(2.0 * M_PI * f * t);
        else if (rec.pulse == "cosine") a = std::cos(2.0 * M_PI * f * t);
        else {
            const double u = M_PI * f * (t - 1.5 / f);   // Ricker wavelet centred at 1.5/f
            a = (1.0 - 2.0 * u * u) * std::exp(-u * u);
        }
        if (rec.pulse == "sine" && i == n) a = 0.0;   // exactly back to rest
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.9g,%.9g\n", t, a);
        o << buf;
    }
    return o.str();
}

Sweep expand_sweep(const SweepPlan& plan, const std::string& records_dir_arg) {
    const std::string records_dir = fs::absolute(records_dir_arg).lexically_normal().string();
    Sweep sweep;
    sweep.plan = plan;
    if (!plan.records.empty()) fs::create_directories(records_dir);
    for (const auto& rec : plan.records)
        if (rec.file.empty()) write_if_changed((fs::path(records_dir) / (rec.name + ".csv")).string(), pulse_csv(rec));

    // no records: each scene's own ground motion, under the name "scene"
    const bool own = plan.records.empty();
    std::vector<RecordSpec> records = plan.records;
    if (own) {
        records.emplace_back();
        records.back().name = "scene";
    }
    std::set<std::string> ids;
    for (size_t s = 0; s < plan.scenes.size(); ++s) {
        const std::string scene_path = fs::absolute(plan.scenes[s]).lexically_normal().string();
        const std::string& name = plan.scene_names[s];
        std::string block;
        double angle = 0.0;
        for (const auto& rec : records) {
            // the record's peak ground acceleration, g, from the scene loaded with it unscaled
            std::vector<std::string> base = plan.set;
            if (!own)
                for (const auto& o : record_overrides(rec, records_dir)) base.push_back(o);
            double pga = 0.0;
            try {
                std::vector<std::string> unscaled = base;
                unscaled.push_back("ground_motion.scale=1.0");
                const Scene scene = load_scene(scene_path, parsed(unscaled));
                if (block.empty()) outcome_block(scene, plan, name, block, angle);
                if (scene.ground_motion)   // the largest component's peak
                    for (const auto& c : scene.ground_motion->components)
                        for (double a : c.acceleration.value) pga = std::max(pga, std::abs(a) / kG);
            } catch (const Error& e) {
                throw Error(plan.path + ": scene " + name + " with record " + rec.name + ": " + e.what());
            }
            if (!plan.intensities.empty() && !(pga > 0.0))
                throw Error(plan.path + ": intensities: scene " + name + " with record " + rec.name +
                            " has no ground acceleration to scale");
            const std::vector<double> levels = plan.intensities.empty() ? std::vector<double>{pga} : plan.intensities;
            // the axes' cartesian product, the last axis fastest
            size_t combos = 1;
            for (const auto& a : plan.axes) combos *= a.values.size();
            for (const auto& backend : plan.backends)
                for (double level : levels)
                    for (size_t c = 0; c < combos; ++c)
                        for (int rep = 0; rep < plan.repeats; ++rep) {
                            SweepRun run;
                            run.index = sweep.runs.size();
                            run.scene = scene_path;
                            run.scene_name = name;
                            run.backend = backend;
                            run.record = rec.name;
                            run.intensity = level;
                            run.scale = plan.intensities.empty() ? 1.0 : level / pga;
                            run.repeat = rep;
                            run.block = block;
                            run.overturn_angle = angle;
                            run.overrides = base;
                            if (!plan.intensities.empty() || !own)
                                run.overrides.push_back("ground_motion.scale=" + exact(run.scale));
                            std::string key = name + "\n" + backend + "\n" + rec.name + "\n" + exact(level) + "\n";
                            size_t rest = c;
                            std::vector<std::string> vals(plan.axes.size());
                            for (size_t a = plan.axes.size(); a-- > 0;) {
                                vals[a] = plan.axes[a].values[rest % plan.axes[a].values.size()];
                                rest /= plan.axes[a].values.size();
                            }
                            for (size_t a = 0; a < plan.axes.size(); ++a) {
                                run.overrides.push_back(plan.axes[a].key + "=" + vals[a]);
                                key += plan.axes[a].key + "=" + vals[a] + "\n";
                            }
                            run.axis_values = vals;
                            key += std::to_string(rep);
                            run.id = hash_id(key);
                            if (!ids.insert(run.id).second)
                                throw Error(plan.path + ": two runs of the plan are the same (" + name + ", " + backend +
                                            ", " + rec.name + "): a scene, record or axis value is repeated");
                            sweep.runs.push_back(std::move(run));
                        }
        }
    }
    return sweep;
}

std::vector<SweepRun> shard_of(const std::vector<SweepRun>& runs, int i, int n) {
    std::vector<SweepRun> out;
    for (size_t k = size_t(i); k < runs.size(); k += size_t(n)) out.push_back(runs[k]);
    return out;
}

std::string sweep_manifest(const Sweep& sweep) {
    std::ostringstream o;
    o << "cairn sweep manifest 1\nkind " << sweep.plan.kind << "\naxes";
    for (const auto& a : sweep.plan.axes) o << " " << a.key;
    o << "\n";
    for (const auto& r : sweep.runs) {
        o << r.id << " " << r.scene_name << " " << r.backend << " " << r.record << " " << exact(r.intensity) << " "
          << exact(r.scale) << " " << r.block << " " << exact(r.overturn_angle);
        for (const auto& v : r.axis_values) o << " " << v;
        o << " " << r.repeat << "\n";
    }
    return o.str();
}

}  // namespace cairn::sweep

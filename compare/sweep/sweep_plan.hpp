#pragma once
/// A sweep plan (docs/sweeps.md): scenes × backends × ground-motion records × intensities × scene
/// overrides × repeats, read from an untrusted TOML file with every error naming the file, the
/// line, the key and the value, and bounded sizes.

#include <functional>
#include <string>
#include <vector>

namespace cairn::sweep {

/// One ground-motion record of the suite.
struct RecordSpec {
    std::string name;              ///< [A-Za-z0-9_-], unique in the plan
    std::string file;              ///< CSV record, absolute path; empty for a synthetic pulse
    std::string units = "g";       ///< "g" or "m/s2" (file records)
    std::string time_column = "t_s";          ///< file records
    std::string acceleration_column = "accel_g";   ///< file records
    std::string pulse;             ///< "sine", "cosine" or "ricker" for a synthetic pulse, else ""
    double frequency = 0.0;        ///< pulse frequency f_p, Hz
    int cycles = 1;                ///< sine and cosine pulses: full cycles
    std::string source;            ///< where the record comes from (shown in the report)
};

/// A scene-override axis: one key, several values (TOML text).
struct Axis {
    std::string key;                   ///< dotted scene key, as for --set
    std::vector<std::string> values;   ///< each as TOML text
};

/// The plan.
struct SweepPlan {
    std::string path;                  ///< the plan file
    std::string kind = "grid";         ///< "grid" or "fragility" (adds the fragility curves)
    std::vector<std::string> scenes;   ///< resolved scene files
    std::vector<std::string> scene_names;   ///< as written in the plan (shown in the table)
    std::vector<std::string> backends; ///< registry names, or variants "bullet-matched", "dem-deformable"
    std::string block;                 ///< the block whose outcome is recorded; "" = the first free one
    double overturn_angle = 0.0;       ///< rad; 0 = atan(base/height) of the block
    int repeats = 1;                   ///< runs per point (the wall time varies, the result does not)
    std::vector<std::string> set;      ///< "key=value" overrides of every run
    std::vector<RecordSpec> records;   ///< empty = each scene's own ground motion
    std::vector<double> intensities;   ///< peak ground acceleration of the scaled record, g; empty = as recorded
    std::vector<Axis> axes;            ///< further overrides, crossed with everything else
};

/// A backend entry of a plan split into what a run needs.
struct BackendVariant {
    std::string backend;            ///< registry name
    std::string contact = "rigid";  ///< contact mode of the reference engines: "rigid" or "matched"
    std::string model;              ///< "deformable" for every free block, "" = the scene's models
};

/// "bullet" → {bullet, rigid, ""}, "ode-matched" → {ode, matched, ""}, "dem-deformable" →
/// {dem, rigid, deformable}, "dem-rigid" → {dem, rigid, rigid}; throws cairn::Error for another suffix
BackendVariant backend_variant(const std::string& name);

/// limits on a plan (bad input must not make cairn allocate or loop without bound)
constexpr std::size_t kMaxPlanBytes = 1u << 20;
constexpr std::size_t kMaxPlanRuns = 100000;

/// read and check the plan at `path`; `resolve_scene` turns a scene name or path (already made
/// relative to the plan's folder when such a file exists) into a file, throwing cairn::Error.
/// Throws cairn::Error naming the file, key and value for anything wrong.
SweepPlan read_sweep_plan(const std::string& path,
                          const std::function<std::string(const std::string&)>& resolve_scene);

}  // namespace cairn::sweep

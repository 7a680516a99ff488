#pragma once
/// `cairn bench stability`: every backend pushed to the extremes (contact stiffness, time step,
/// mass ratio, friction, slenderness, impact speed, a long run), each point classed stable /
/// unstable / drifting / wrong with its energy drift and penetration; stability.csv.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backend/backend_info.hpp"
#include "run/runner.hpp"   // kDriftBound: the runner's energy_drift bound, read by the classifier

namespace cairn::bench {

/// How a point held.
enum class StabilityClass {
    stable,     ///< completed, energy closed (where booked), inside the oracle's tolerance
    unstable,   ///< blew up: the runner's RunStatus::unstable (or the run failed)
    drifting,   ///< completed, but the energy balance error passed kDriftBound (run/runner.hpp) of the energy scale
    wrong,      ///< completed and closed, but outside the oracle's tolerance
    refused,    ///< the backend cannot build the scene
};

/// "stable", "unstable", "drifting", "wrong", "refused"
const char* to_string(StabilityClass c);

/// What the classifier reads of one run.
struct StabilityInput {
    std::string outcome;            ///< "completed", "unstable", "refused", "failed"
    bool energy_booked = true;      ///< false: the backend does not book what it dissipates (rigid-mode engines)
    bool energy_drift = false;      ///< the runner's flag
    double max_balance_error = 0.0; ///< largest |balance error| / energy scale
    bool has_oracle = true;         ///< an oracle judged the run
    bool oracle_pass = true;        ///< inside its tolerance
};

/// unstable (or failed) > refused > drifting > wrong > stable
StabilityClass classify(const StabilityInput& in);

/// A judgement of a run against its oracle.
struct Judgement {
    bool pass = false;
    std::string text;   ///< "peak penetration 1.39e-02 m vs 1.39e-02 m (2 %)"
};

/// One point of the map.
struct StabilityPoint {
    std::string backend;
    std::string parameter;          ///< "kn", "dt", "mass ratio", "friction", "alpha", "impact speed", "long run"
    std::string value_text;         ///< as shown on the map: "1e+09", "0.5 crit", "30°"
    double value = 0.0;             ///< the parameter's value in SI (dt: the factor or s)
    StabilityClass cls = StabilityClass::stable;
    double max_balance_error = 0.0; ///< largest |balance error| / energy scale
    bool energy_booked = true;
    double penetration = 0.0;       ///< largest penetration of the reference block's corners into the fixed block, m
    std::string check;              ///< the oracle's judgement text
    double dt = 0.0;                ///< s
    long long steps = 0;
    double wall_seconds = 0.0;      ///< s
    std::string message;            ///< why it stopped, or was refused
};

/// One point to run.
struct StabilityConfig {
    StabilityPoint point;                 ///< keys filled
    Scene scene;
    std::string contact_mode = "rigid";
    std::function<Judgement(const Scene&, const std::vector<Sample>&)> judge;
};

/// every point of the map for one backend (scenes from `scenarios_dir`); dem of `backends` is built
/// once per scene to read its critical step; `long_steps` steps for the long run
std::vector<StabilityConfig> stability_configs(const std::string& backend, const std::string& scenarios_dir,
                                               const std::vector<BackendInfo>& backends, long long long_steps);

/// largest penetration (m) of the reference block's corners below the top of the first fixed block
double max_penetration(const Scene& scene, const std::vector<Sample>& samples);

/// run every point (`jobs` at a time, on the run layer) and class it
std::vector<StabilityPoint> run_stability(std::vector<StabilityConfig>& configs, int jobs, bool quiet,
                                          const std::vector<BackendInfo>& backends);

/// stability.csv text
std::string stability_csv(const std::vector<StabilityPoint>& points);
/// parse stability.csv text
std::vector<StabilityPoint> parse_stability_csv(const std::string& text);

}  // namespace cairn::bench

#pragma once
/// Reading a reference engine's own settings table (Scene::backend_settings[name]) and the
/// options every engine shares: contact mode and time step.

#include <set>
#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "scene/scene.hpp"

namespace cairn {

/// Typed access to one backend's settings table; finish() rejects keys nobody asked for.
class EngineSettings {
public:
    /// the table of `backend` in `scene` (empty if the scene has none)
    EngineSettings(const Scene& scene, std::string backend);
    /// an integer ≥ `min`, or `fallback` when absent
    long long integer(const std::string& key, long long fallback, long long min);
    /// a number ≥ `min` (integers accepted), or `fallback` when absent
    double number(const std::string& key, double fallback, double min);
    /// one of `allowed`, or `fallback` when absent
    std::string word(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& allowed);
    /// a boolean, or `fallback` when absent
    bool flag(const std::string& key, bool fallback);
    /// throws cairn::Error naming the first key that was never read, with its origin
    void finish() const;

private:
    const Setting* find(const std::string& key);
    [[noreturn]] void bad(const std::string& key, const Setting& s, const std::string& want) const;
    std::string backend_;
    const std::map<std::string, Setting>* table_ = nullptr;
    std::set<std::string> read_;
};

/// "rigid" or "matched": the run option, unless it is the default and the scene's table sets
/// `contact_mode`; throws cairn::Error for any other value
std::string contact_mode(EngineSettings& settings, const RunOptions& options);

/// the default step of the reference engines when the scene says dt = auto, s
constexpr double kEngineDefaultStep = 1e-4;

/// the scene's fixed step, or kEngineDefaultStep for dt = auto
double engine_time_step(const Scene& scene);

}  // namespace cairn

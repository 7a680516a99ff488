#include "engine_settings.hpp"

#include <sstream>

#include "error.hpp"

namespace cairn {

EngineSettings::EngineSettings(const Scene& scene, std::string backend) : backend_(std::move(backend)) {
    auto it = scene.backend_settings.find(backend_);
    if (it != scene.backend_settings.end()) table_ = &it->second;
}

const Setting* EngineSettings::find(const std::string& key) {
    read_.insert(key);
    if (!table_) return nullptr;
    auto it = table_->find(key);
    return it == table_->end() ? nullptr : &it->second;
}

void EngineSettings::bad(const std::string& key, const Setting& s, const std::string& want) const {
    std::ostringstream v;
    std::visit([&](const auto& x) { v << x; }, s.value);
    throw Error(s.origin + ": " + backend_ + " setting '" + key + "' = " + v.str() + ": expected " + want);
}

long long EngineSettings::integer(const std::string& key, long long fallback, long long min) {
    const Setting* s = find(key);
    if (!s) return fallback;
    const long long* v = std::get_if<long long>(&s->value);
    if (!v || *v < min) bad(key, *s, "an integer >= " + std::to_string(min));
    return *v;
}

double EngineSettings::number(const std::string& key, double fallback, double min) {
    const Setting* s = find(key);
    if (!s) return fallback;
    double v = 0.0;
    if (const double* d = std::get_if<double>(&s->value)) v = *d;
    else if (const long long* i = std::get_if<long long>(&s->value)) v = static_cast<double>(*i);
    else bad(key, *s, "a number");
    if (!(v >= min)) {
        std::ostringstream m;
        m << "a number >= " << min;
        bad(key, *s, m.str());
    }
    return v;
}

std::string EngineSettings::word(const std::string& key, const std::string& fallback,
                                 const std::vector<std::string>& allowed) {
    const Setting* s = find(key);
    if (!s) return fallback;
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    const std::string* v = std::get_if<std::string>(&s->value);
    if (!v) bad(key, *s, "one of " + list);
    for (const auto& a : allowed)
        if (*v == a) return *v;
    bad(key, *s, "one of " + list);
}

bool EngineSettings::flag(const std::string& key, bool fallback) {
    const Setting* s = find(key);
    if (!s) return fallback;
    const bool* v = std::get_if<bool>(&s->value);
    if (!v) bad(key, *s, "true or false");
    return *v;
}

void EngineSettings::finish() const {
    if (!table_) return;
    for (const auto& [key, s] : *table_) {
        if (read_.count(key)) continue;
        std::string known;
        for (const auto& k : read_) known += (known.empty() ? "" : ", ") + k;
        throw Error(s.origin + ": unknown " + backend_ + " setting '" + key + "' (known: " + known + ")");
    }
}

std::string contact_mode(EngineSettings& settings, const RunOptions& options) {
    const std::vector<std::string> modes{"rigid", "matched"};
    std::string scene_mode = settings.word("contact_mode", "", modes);
    if (options.contact_mode != "rigid" && options.contact_mode != "matched")
        throw Error("unknown contact mode '" + options.contact_mode + "' (expected rigid or matched)");
    if (options.contact_mode == "rigid" && !scene_mode.empty()) return scene_mode;
    return options.contact_mode;
}

double engine_time_step(const Scene& scene) {
    if (!scene.run.dt) return kEngineDefaultStep;
    if (!(*scene.run.dt > 0.0))
        throw Error("run.dt = " + std::to_string(*scene.run.dt) + ": the time step must be positive");
    return *scene.run.dt;
}

}  // namespace cairn

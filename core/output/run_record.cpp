#include "output/run_record.hpp"

#include "scene/scene_io.hpp"

namespace cairn {

const char* to_string(RunStatus s) {
    switch (s) {
        case RunStatus::completed: return "completed";
        case RunStatus::unstable: return "unstable";
    }
    return "?";
}

namespace {

nlohmann::json energies_json(const Energies& e, double total0) {
    return {{"kinetic", e.kinetic},       {"potential", e.potential},
            {"contact", e.contact},       {"strain", e.strain},
            {"dissipated", e.dissipated}, {"external", e.external},
            {"balance_error", e.total() - total0}};
}

}  // namespace

nlohmann::json run_record(const Scene& scene, const Backend& backend, const RunResult& result,
                          const RunRequest& request) {
    nlohmann::json j;
    j["scene"] = {{"name", scene.name}, {"path", request.scene_path}};
    j["backend"] = backend.name();
    j["engine_version"] = backend.engine_version();
    j["cairn_version"] = CAIRN_VERSION;
    j["overrides"] = request.overrides;
    j["model_override"] = request.model_override.empty() ? nlohmann::json(nullptr)
                                                         : nlohmann::json(request.model_override);
    j["contact_mode"] = request.options.contact_mode;
    j["parameters"] = scene_to_json(scene);
    j["dt"] = result.dt;
    j["critical_step"] = result.critical_step;
    j["steps"] = result.steps;
    j["output_every"] = result.output_every;
    j["samples"] = result.samples.size();
    j["wall_seconds"] = result.wall_seconds;
    j["status"] = to_string(result.status);
    j["message"] = result.message;
    j["partial"] = result.status != RunStatus::completed;
    j["energy_drift"] = result.energy_drift;
    j["max_balance_error"] = result.max_balance_error;
    if (!result.samples.empty()) {
        const Sample& last = result.samples.back();
        j["final_time"] = last.t;
        j["final_energies"] = energies_json(last.energy, result.samples.front().energy.total());
    } else {
        j["final_time"] = nullptr;
        j["final_energies"] = nullptr;
    }
    j["notes"] = backend.notes();
    return j;
}

}  // namespace cairn

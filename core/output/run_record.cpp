#include "output/run_record.hpp"

#include "scene/scene_io.hpp"

namespace cairn {

const char* to_string(RunStatus s) {
    switch (s) {
        case RunStatus::completed: return "completed";
        case RunStatus::unstable: return "unstable";
        case RunStatus::interrupted: return "interrupted";
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
    j["samples"] = result.sample_count;
    j["wall_seconds"] = result.wall_seconds;
    j["status"] = to_string(result.status);
    j["message"] = result.message;
    j["partial"] = result.status != RunStatus::completed;
    j["energy_drift"] = result.energy_drift;
    j["max_balance_error"] = result.max_balance_error;
    j["energy_gain"] = result.energy_gain;
    j["energy_gain_time"] = result.energy_gain_time;
    j["energy_created"] = result.energy_created;
    if (result.sample_count > 0) {
        j["final_time"] = result.final_time;
        j["final_energies"] = energies_json(result.final_energy, result.initial_total);
    } else {
        j["final_time"] = nullptr;
        j["final_energies"] = nullptr;
    }
    j["notes"] = backend.notes();
    return j;
}

std::string run_record_text(const Scene& scene, const Backend& backend, const RunResult& result,
                            const RunRequest& request) {
    // text that is not UTF-8 (a scene path with a Latin-1 byte) is kept with U+FFFD in its place
    // rather than throwing after the trajectory is written
    return run_record(scene, backend, result, request)
               .dump(2, ' ', false, nlohmann::json::error_handler_t::replace) +
           "\n";
}

}  // namespace cairn

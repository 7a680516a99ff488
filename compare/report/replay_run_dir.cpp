#include "report/replay_run_dir.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "error.hpp"
#include "report/trajectory_reader.hpp"
#include "scene/scene_io.hpp"

namespace fs = std::filesystem;

namespace cairn {

ReplayRun replay_from_run_dir(const std::string& dir) {
    const std::string record_path = (fs::path(dir) / "run.json").string();
    std::ifstream record_in(record_path);
    if (!record_in) throw Error(record_path + ": cannot read (is " + dir + " a directory written by cairn run?)");
    nlohmann::json record;
    try {
        record = nlohmann::json::parse(record_in);
    } catch (const std::exception& e) {
        throw Error(record_path + ": not valid JSON (" + e.what() + ")");
    }
    std::string scene_path, label;
    std::vector<Override> overrides;
    try {
        scene_path = record.at("scene").at("path").get<std::string>();
        for (const auto& o : record.at("overrides")) overrides.push_back(parse_override(o.get<std::string>()));
        label = record.at("backend").get<std::string>();
        if (record.contains("model_override") && record["model_override"].is_string())
            label += " " + record["model_override"].get<std::string>();
        if (record.contains("contact_mode") && record["contact_mode"] != "rigid")
            label += " (" + record["contact_mode"].get<std::string>() + " contact)";
    } catch (const nlohmann::json::exception& e) {
        throw Error(record_path + ": missing or wrong scene.path, overrides or backend (" + e.what() + ")");
    }
    const Scene scene = load_scene(scene_path, overrides);
    ReplayRun run = replay_run(label, scene);

    report::TrajectoryReader csv(dir);
    const std::string hint = " (the scene " + scene_path + " changed since the run?)";
    const std::size_t t_col = csv.column("t", hint);
    std::vector<std::size_t> cols;   // x, y, z, qw, qx, qy, qz of every free block, scene order
    for (const auto& b : scene.blocks)
        if (!b.fixed)
            for (const char* k : {".x", ".y", ".z", ".qw", ".qx", ".qy", ".qz"}) cols.push_back(csv.column(b.name + k, hint));
    while (csv.next()) {
        Sample s;
        s.t = csv.number(t_col);
        for (size_t k = 0; k < cols.size(); k += 7) {
            BlockState b;
            b.position = Vec3(csv.number(cols[k]), csv.number(cols[k + 1]), csv.number(cols[k + 2]));
            b.orientation = Quat(csv.number(cols[k + 3]), csv.number(cols[k + 4]), csv.number(cols[k + 5]),
                                 csv.number(cols[k + 6]));
            s.blocks.push_back(b);
        }
        add_frame(run, s);
    }
    return run;
}

}  // namespace cairn

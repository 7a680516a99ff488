#include "sweep/sweep_result.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "error.hpp"
#include "geometry/types.hpp"
#include "report/trajectory_reader.hpp"

namespace fs = std::filesystem;

namespace cairn::sweep {

void read_trajectory_outcome(const std::string& run_dir, const SweepRun& run, SweepResult& r) {
    report::TrajectoryReader csv(run_dir);
    const std::size_t t_col = csv.column("t");
    std::vector<std::size_t> cols;
    for (const char* k : {".x", ".y", ".qw", ".qx", ".qy", ".qz"}) cols.push_back(csv.column(run.block + k));
    double x0 = 0, y0 = 0;
    bool first = true;
    r.peak_rotation = 0.0;
    while (csv.next()) {
        const double x = csv.number(cols[0]), y = csv.number(cols[1]);
        const Quat q(csv.number(cols[2]), csv.number(cols[3]), csv.number(cols[4]), csv.number(cols[5]));
        // tilt: the angle between the block's z axis and the vertical
        const Vec3 axis = q.normalized() * Vec3::UnitZ();
        const double tilt = std::acos(std::clamp(axis.z(), -1.0, 1.0));
        if (first) {
            x0 = x;
            y0 = y;
            first = false;
        }
        r.peak_rotation = std::max(r.peak_rotation, tilt);
        r.final_rotation = tilt;
        r.residual_displacement = std::hypot(x - x0, y - y0);
        r.duration = csv.number(t_col);
    }
    if (first) throw Error(csv.path() + ": no samples");
    r.overturned = r.final_rotation > run.overturn_angle;
}

std::string result_json(const SweepRun& run, const SweepResult& r) {
    nlohmann::ordered_json j;
    j["id"] = run.id;
    j["scene"] = run.scene_name;
    j["backend"] = run.backend;
    j["record"] = run.record;
    j["intensity_g"] = run.intensity;
    j["scale"] = run.scale;
    j["repeat"] = run.repeat;
    j["overrides"] = run.overrides;
    j["status"] = r.status;
    j["message"] = r.message;
    j["overturned"] = r.overturned;
    j["peak_rotation"] = r.peak_rotation;
    j["final_rotation"] = r.final_rotation;
    j["residual_displacement"] = r.residual_displacement;
    j["duration"] = r.duration;
    j["steps"] = r.steps;
    j["dt"] = r.dt;
    j["wall_seconds"] = r.wall_seconds;
    return j.dump(2) + "\n";
}

SweepResult read_result(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot read");
    SweepResult r;
    try {
        const auto j = nlohmann::json::parse(in);
        r.id = j.at("id").get<std::string>();
        r.status = j.at("status").get<std::string>();
        r.message = j.at("message").get<std::string>();
        r.overturned = j.at("overturned").get<bool>();
        r.peak_rotation = j.at("peak_rotation").get<double>();
        r.final_rotation = j.at("final_rotation").get<double>();
        r.residual_displacement = j.at("residual_displacement").get<double>();
        r.duration = j.at("duration").get<double>();
        r.steps = j.at("steps").get<long long>();
        r.dt = j.at("dt").get<double>();
        r.wall_seconds = j.at("wall_seconds").get<double>();
    } catch (const std::exception& e) {
        throw Error(path + ": not a sweep result (" + e.what() + ")");
    }
    return r;
}

}  // namespace cairn::sweep

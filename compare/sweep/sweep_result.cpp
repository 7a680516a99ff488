#include "sweep/sweep_result.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "error.hpp"
#include "geometry/types.hpp"
#include "report/text.hpp"

namespace fs = std::filesystem;

namespace cairn::sweep {

namespace {

/// longest trajectory line read, characters
constexpr std::size_t kMaxLine = 1u << 20;

bool read_line(std::istream& in, std::string& line, const std::string& path) {
    return report::read_bounded_line(in, line, path, kMaxLine);
}

}  // namespace

void read_trajectory_outcome(const std::string& run_dir, const SweepRun& run, SweepResult& r) {
    fs::path csv = fs::path(run_dir) / "trajectory.csv";
    if (!fs::exists(csv)) csv = fs::path(run_dir) / "trajectory.partial.csv";
    std::ifstream in(csv);
    if (!in) throw Error(csv.string() + ": cannot read");
    std::string line;
    if (!read_line(in, line, csv.string())) throw Error(csv.string() + ": empty");
    const auto header = report::split_csv_line(line);
    auto column = [&](const std::string& name) {
        for (size_t i = 0; i < header.size(); ++i)
            if (header[i].substr(0, header[i].find(' ')) == name) return i;
        throw Error(csv.string() + ": no column " + name);
    };
    const size_t t_col = column("t");
    std::vector<size_t> cols;
    for (const char* k : {".x", ".y", ".qw", ".qx", ".qy", ".qz"}) cols.push_back(column(run.block + k));
    double x0 = 0, y0 = 0;
    bool first = true;
    r.peak_rotation = 0.0;
    for (int row = 2; read_line(in, line, csv.string()); ++row) {
        const auto f = report::split_csv_line(line);
        auto num = [&](size_t c) {
            if (c >= f.size()) throw Error(csv.string() + ": line " + std::to_string(row) + " has too few fields");
            char* end = nullptr;
            const double v = std::strtod(f[c].c_str(), &end);
            if (f[c].empty() || *end != '\0')
                throw Error(csv.string() + ": line " + std::to_string(row) + ": '" + f[c] + "' is not a number");
            return v;
        };
        const double x = num(cols[0]), y = num(cols[1]);
        const Quat q(num(cols[2]), num(cols[3]), num(cols[4]), num(cols[5]));
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
        r.duration = num(t_col);
    }
    if (first) throw Error(csv.string() + ": no samples");
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

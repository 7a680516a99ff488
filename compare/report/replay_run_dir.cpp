#include "report/replay_run_dir.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "error.hpp"
#include "report/text.hpp"
#include "scene/scene_io.hpp"

namespace fs = std::filesystem;

namespace cairn {

namespace {

/// longest trajectory line accepted, characters (a row of 17-digit numbers for thousands of blocks)
constexpr size_t kMaxLine = 16u << 20;

/// read one line of at most kMaxLine characters; false at the end of the file
bool read_line(std::istream& in, std::string& line, const std::string& path) {
    line.clear();
    char c;
    while (in.get(c)) {
        if (c == '\n') return true;
        if (line.size() >= kMaxLine) throw Error(path + ": a line longer than " + std::to_string(kMaxLine) + " characters");
        line += c;
    }
    return !line.empty();
}

/// a column name without its unit ("t [s]" -> "t"; a name without one is kept)
std::string column_name(const std::string& s) {
    const auto open = s.rfind(" [");
    return open != std::string::npos && !s.empty() && s.back() == ']' ? s.substr(0, open) : s;
}

}  // namespace

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

    fs::path csv = fs::path(dir) / "trajectory.csv";
    if (!fs::exists(csv)) csv = fs::path(dir) / "trajectory.partial.csv";
    std::ifstream in(csv);
    if (!in) throw Error(csv.string() + ": cannot read");
    std::string line;
    if (!read_line(in, line, csv.string())) throw Error(csv.string() + ": empty");
    const auto header = report::split_csv_line(line);
    auto column = [&](const std::string& name) {
        for (size_t i = 0; i < header.size(); ++i)
            if (column_name(header[i]) == name) return int(i);
        throw Error(csv.string() + ": no column " + name + " (the scene " + scene_path + " changed since the run?)");
    };
    const int t_col = column("t");
    std::vector<int> cols;   // x, y, z, qw, qx, qy, qz of every free block, scene order
    for (const auto& b : scene.blocks)
        if (!b.fixed)
            for (const char* k : {".x", ".y", ".z", ".qw", ".qx", ".qy", ".qz"}) cols.push_back(column(b.name + k));
    for (int row = 2; read_line(in, line, csv.string()); ++row) {
        const auto f = report::split_csv_line(line);
        Sample s;
        auto num = [&](int c) {
            if (c >= int(f.size())) throw Error(csv.string() + ": line " + std::to_string(row) + " has too few fields");
            char* end = nullptr;
            const double v = std::strtod(f[c].c_str(), &end);
            if (f[c].empty() || *end != '\0')
                throw Error(csv.string() + ": line " + std::to_string(row) + ": '" + f[c] + "' is not a number");
            return v;
        };
        s.t = num(t_col);
        for (size_t k = 0; k < cols.size(); k += 7) {
            BlockState b;
            b.position = Vec3(num(cols[k]), num(cols[k + 1]), num(cols[k + 2]));
            b.orientation = Quat(num(cols[k + 3]), num(cols[k + 4]), num(cols[k + 5]), num(cols[k + 6]));
            s.blocks.push_back(b);
        }
        add_frame(run, s);
    }
    return run;
}

}  // namespace cairn

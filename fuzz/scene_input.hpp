#pragma once
// One input of the scene-loader fuzzer, shared by the fuzz target and its regression test.
// Up to three parts split by a line "%%":
//   1. a scene (TOML), read as if it were the file DIR/scene.toml;
//   2. `--set` overrides, one "key=value" per line;
//   3. the ground-motion CSV, written to DIR/g.csv (a scene reaches it with file = "g.csv").

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/scene_io.hpp"

namespace cairn::fuzz {

/// `text` cut at each line that is exactly "%%" (three parts at most)
inline std::vector<std::string> split_parts(const std::string& text) {
    std::vector<std::string> parts(1);
    size_t from = 0;
    while (from <= text.size()) {
        size_t end = text.find('\n', from);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(from, end - from);
        if (line == "%%" && parts.size() < 3) parts.emplace_back();
        else parts.back() += line + (end < text.size() ? "\n" : "");
        from = end + 1;
    }
    return parts;
}

/// load the scene of one input with its overrides and CSV, in scratch directory `dir`, and
/// serialise it as run.json would; a refused input throws cairn::Error
inline void load_input(const std::string& data, const std::filesystem::path& dir) {
    const auto parts = split_parts(data);
    const auto csv = dir / "g.csv";
    if (parts.size() > 2) std::ofstream(csv, std::ios::binary | std::ios::trunc) << parts[2];
    else std::filesystem::remove(csv);
    std::vector<Override> overrides;
    if (parts.size() > 1) {
        const std::string& o = parts[1];
        size_t from = 0;
        while (from < o.size()) {
            size_t end = o.find('\n', from);
            if (end == std::string::npos) end = o.size();
            if (end > from) overrides.push_back(parse_override(o.substr(from, end - from)));
            from = end + 1;
        }
    }
    const Scene scene = parse_scene(parts[0], (dir / "scene.toml").string(), overrides);
    (void)scene_to_json(scene).dump();
}

}  // namespace cairn::fuzz

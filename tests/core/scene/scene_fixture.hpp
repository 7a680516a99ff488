#pragma once
// a small valid scene whose line numbers the rejection tests rely on, and helpers to vary it

#include <sstream>
#include <string>
#include <vector>

#include "error.hpp"
#include "scene/scene_io.hpp"

namespace cairn::test {

// line numbers: 3 duration, 5 density, 9 kn, 10 friction, 11 [blocks.A], 12 size, 13 position,
// 14 material, 15 [blocks.B], 19 fixed; text appended by with_extra() starts at line 20
inline const std::string kBaseScene = R"(name = "t"
[run]
duration = 0.5
[materials.stone]
density = 2600
young = 30e9
poisson = 0.2
[contact]
kn = 3e7
friction = 0.6
[blocks.A]
size = [1, 1, 1]
position = [0, 0, 0.5]
material = "stone"
[blocks.B]
size = [1, 1, 1]
position = [0, 0, -0.5]
material = "stone"
fixed = true
)";

// the base scene with line `line` (1-based) replaced by `text`
inline std::string with_line(int line, const std::string& text) {
    std::istringstream in(kBaseScene);
    std::string out, l;
    for (int i = 1; std::getline(in, l); ++i) out += (i == line ? text : l) + "\n";
    return out;
}

// the base scene with `text` appended (its first line is line 20)
inline std::string with_extra(const std::string& text) { return kBaseScene + text; }

// the message of the cairn::Error that parsing raises, or "" if it parses
inline std::string error_of(const std::string& text, const std::vector<Override>& overrides = {}) {
    try {
        parse_scene(text, "bad.toml", overrides);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace cairn::test

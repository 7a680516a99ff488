// physical parameters refuse non-finite and out-of-range values, naming file, line, key and value
#include <catch2/catch.hpp>

#include "scene_fixture.hpp"

using namespace cairn;
using Catch::Matchers::Contains;
using test::error_of;
using test::with_line;

TEST_CASE("density, young, kn, duration refuse nan, inf, zero and negative values", "[scene][reject][limits]") {
    struct Key {
        int line;
        std::string key, name;
    };
    const Key keys[] = {{5, "materials.stone.density", "density"},
                        {6, "materials.stone.young", "young"},
                        {9, "contact.kn", "kn"},
                        {3, "run.duration", "duration"}};
    for (const auto& k : keys)
        for (const std::string v : {"nan", "inf", "-inf", "0", "-1", "-1e-300"}) {
            const std::string msg = error_of(with_line(k.line, k.name + " = " + v));
            const bool finite = v != "nan" && v != "inf" && v != "-inf";
            CAPTURE(k.key, v);
            CHECK_THAT(msg, Contains("bad.toml:" + std::to_string(k.line) + ": " + k.key + " = " + v + ": " +
                                     (finite ? "must be > 0" : "must be a finite number")));
        }
}

TEST_CASE("the other physical parameters refuse nan and out-of-range values", "[scene][reject][limits]") {
    const std::pair<std::string, std::string> cases[] = {
        {"[contact]\nkn = 1e7\nfriction = 0.5\nks = -1\n", "contact.ks = -1: must be >= 0"},
        {"[contact]\nkn = 1e7\nfriction = -0.1\n", "contact.friction = -0.1: must be >= 0"},
        {"[contact]\nkn = 1e7\nfriction = 0.5\ngrid_spacing = 0\n", "contact.grid_spacing = 0: must be > 0"},
        {"[contact]\nkn = 1e7\nfriction = 0.5\ngrid_spacing = inf\n", "contact.grid_spacing = inf: must be a finite number"},
        {"[contact]\nkn = 1e7\nfriction = 0.5\ndamping_ratio = nan\n", "contact.damping_ratio = nan: must be a finite number"},
        {"[damping]\nalpha = -1\n", "damping.alpha = -1: must be >= 0"},
        {"[damping]\nbeta = inf\n", "damping.beta = inf: must be a finite number"},
        {"[run]\nduration = 1\ndt = -1e-3\n", "run.dt = -1e-3: must be > 0"},
        {"[run]\nduration = 1\noutput_interval = 0\n", "run.output_interval = 0: must be > 0"},
        {"[materials.x]\ndensity = 1\nyoung = 1\npoisson = 0.5\n", "materials.x.poisson = 0.5: must be in (-1, 0.5)"},
    };
    // each case replaces one section of the base scene
    for (const auto& [section, expected] : cases) {
        std::string text = test::kBaseScene;
        const std::string head = section.substr(0, section.find('\n') + 1);
        if (text.find(head) != std::string::npos && head != "[materials.x]\n") {
            // drop the base section (up to the next header) and put the case there
            const size_t at = text.find(head), next = text.find("\n[", at + 1);
            text.replace(at, next + 1 - at, section);
        } else {
            text += section;
        }
        CAPTURE(section);
        CHECK_THAT(error_of(text), Contains(expected));
    }
}

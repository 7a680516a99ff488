// `cairn make arch|wall|column|tower|house`: a scene file from a generator (docs/cli.md)
#include <cmath>
#include <iostream>
#include <map>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "error.hpp"
#include "output/atomic_write.hpp"
#include "scene/arch_builder.hpp"
#include "scene/column_builder.hpp"
#include "scene/house_builder.hpp"
#include "scene/scene_io.hpp"
#include "scene/scene_limits.hpp"
#include "scene/scene_toml.hpp"
#include "scene/wall_builder.hpp"

namespace cairn {

namespace {

// what a parameter measures: its SI unit and the suffixes it accepts
enum class Unit { count, length, angle, stiffness, density, time, ratio };

struct Param {
    const char* name;      // option name without "--"
    const char* value;     // default, as typed
    Unit unit;
    const char* help;
};

// the parameters of each generator, in the order of their help
const std::map<std::string, std::vector<Param>>& generator_params() {
    static const std::map<std::string, std::vector<Param>> params = {
        {"arch",
         {{"voussoirs", "9", Unit::count, "number of voussoirs N"},
          {"radius", "2.25m", Unit::length, "centreline radius R"},
          {"thickness", "0.5m", Unit::length, "radial thickness t"},
          {"depth", "0.5m", Unit::length, "depth along y"},
          {"angle", "180deg", Unit::angle, "angle the arch subtends: 180deg semicircular, less segmental"},
          {"pointed", "0", Unit::ratio,
           "pointed (two-centred) arch: each half's centre offset from the axis as a fraction of the span 2R; 0 round"}}},
        {"wall",
         {{"courses", "6", Unit::count, "courses"},
          {"bricks", "6", Unit::count, "whole bricks per course"},
          {"brick-length", "0.4m", Unit::length, "brick length (along the wall)"},
          {"brick-thickness", "0.2m", Unit::length, "brick thickness (the wall's)"},
          {"brick-height", "0.2m", Unit::length, "brick height"}}},
        {"column",
         {{"drums", "3", Unit::count, "number of drums"},
          {"width", "0.3m", Unit::length, "side of the square section"},
          {"drum-height", "0.5m", Unit::length, "height of each drum"}}},
        {"tower",
         {{"length", "10", Unit::count, "outer length along x, in brick lengths"},
          {"width", "10", Unit::count, "outer width along y, in brick lengths"},
          {"courses", "40", Unit::count, "courses"},
          {"brick-length", "0.24m", Unit::length, "brick length; the walls are half of it thick"},
          {"brick-height", "0.07m", Unit::length, "brick height"}}},
        {"house",
         {{"length", "16", Unit::count, "outer length along x, in brick lengths"},
          {"width", "12", Unit::count, "outer width along y, in brick lengths"},
          {"courses", "36", Unit::count, "courses"},
          {"brick-length", "0.24m", Unit::length, "brick length; the walls are half of it thick"},
          {"brick-height", "0.07m", Unit::length, "brick height"},
          {"door-width", "0.96m", Unit::length, "door in the front wall (−y), centred"},
          {"door-height", "2m", Unit::length, "door height, rounded to whole courses"},
          {"window-width", "0.72m", Unit::length, "window centred in each other wall"},
          {"window-sill", "0.9m", Unit::length, "sill height, rounded to whole courses"},
          {"window-height", "1m", Unit::length, "window height, rounded to whole courses"}}},
    };
    return params;
}

// parameters every generator takes: the material, the contact law and the run
const std::vector<Param>& common_params() {
    static const std::vector<Param> params = {
        {"density", "2600", Unit::density, "density of the blocks, kg/m³"},
        {"kn", "1e9", Unit::stiffness, "normal contact stiffness per area, N/m³ (= ks)"},
        {"friction", "0.7", Unit::ratio, "Coulomb friction coefficient"},
        {"damping-ratio", "0.1", Unit::ratio, "contact damping ratio ζ"},
        {"duration", "1s", Unit::time, "simulated time"},
    };
    return params;
}

const char* unit_text(Unit u) {
    switch (u) {
    case Unit::count: return "count";
    case Unit::length: return "m; also cm, mm";
    case Unit::angle: return "rad; also deg";
    case Unit::stiffness: return "N/m³";
    case Unit::density: return "kg/m³";
    case Unit::time: return "s; also ms";
    case Unit::ratio: return "dimensionless";
    }
    return "";
}

// the value of `text` in SI, or an error naming the option
double quantity(const std::string& option, const std::string& text, Unit unit) {
    const std::string where = "--" + option + " " + printable(text);
    std::size_t used = 0;
    double x = 0.0;
    try {
        x = std::stod(text, &used);
    } catch (const std::exception&) {
        throw Error(where + ": not a number");
    }
    const std::string suffix = text.substr(used);
    double factor = 1.0;
    const std::map<Unit, std::map<std::string, double>> suffixes = {
        {Unit::length, {{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}}},
        {Unit::angle, {{"rad", 1.0}, {"deg", M_PI / 180.0}}},
        {Unit::time, {{"s", 1.0}, {"ms", 0.001}}},
    };
    if (!suffix.empty()) {
        auto it = suffixes.find(unit);
        if (it == suffixes.end() || !it->second.count(suffix))
            throw Error(where + ": unit '" + printable(suffix) + "' not accepted (" + unit_text(unit) + ")");
        factor = it->second.at(suffix);
    }
    x *= factor;
    if (!std::isfinite(x)) throw Error(where + ": not finite");
    if (unit == Unit::count) {
        // counts are whole and bounded so that no input can ask for an unbounded scene
        if (x != std::floor(x) || x < 1 || x > 1000) throw Error(where + ": expected a whole number from 1 to 1000");
    } else if (unit == Unit::ratio ? x < 0.0 : !(x > 0.0)) {
        throw Error(where + (unit == Unit::ratio ? ": must be >= 0" : ": must be > 0"));
    }
    return x;
}

// most blocks a generated scene may hold (a 10⁴-block tower is about 1 MB of TOML)
constexpr long long kMaxGeneratedBlocks = 100000;

Scene generate(const std::string& kind, const std::map<std::string, double>& v) {
    Scene s;
    s.materials.push_back({"stone", v.at("density"), 30e9, 0.2});
    s.contact.kn = s.contact.ks = v.at("kn");
    s.contact.friction = v.at("friction");
    s.contact.damping_rule = v.at("damping-ratio") > 0 ? ContactDampingRule::ratio : ContactDampingRule::none;
    s.contact.damping = v.at("damping-ratio");
    s.run.duration = v.at("duration");
    s.run.output_interval = 0.005;
    auto count = [&](const char* k) { return int(v.at(k)); };
    if (kind == "arch") {
        ArchSpec a{count("voussoirs"), v.at("radius"), v.at("thickness"), v.at("depth"), v.at("angle")};
        if (a.thickness >= 2 * a.radius) throw Error("--thickness must be less than twice --radius");
        if (a.angle > M_PI + 1e-12) throw Error("--angle must be at most 180deg");
        a.angle = std::min(a.angle, M_PI);
        a.pointed = v.at("pointed");
        if (a.pointed > 1.0) throw Error("--pointed must be at most 1 (centres a span beyond the axis)");
        if (a.pointed > 0.0 && a.angle < M_PI) throw Error("--pointed needs a full arch: --angle 180deg");
        add_arch(s, a);
        s.description = "Arch of " + std::to_string(a.voussoirs) + " voussoirs on two fixed springers (cairn make arch)";
    } else if (kind == "wall") {
        WallSpec w;
        w.courses = count("courses");
        w.bricks = count("bricks");
        w.brick = Vec3(v.at("brick-length"), v.at("brick-thickness"), v.at("brick-height"));
        add_wall(s, w);
        s.description = "Dry brick wall of " + std::to_string(w.courses) + " courses in running bond (cairn make wall)";
    } else if (kind == "column") {
        ColumnSpec c{count("drums"), v.at("width"), v.at("drum-height"), true};
        add_column(s, c);
        s.description = "Column of " + std::to_string(c.drums) + " drums on a fixed base (cairn make column)";
    } else {
        TowerSpec t{count("length"), count("width"), count("courses"), v.at("brick-length"), v.at("brick-height"), {}};
        if (tower_brick_count(t) > kMaxGeneratedBlocks)
            throw Error("a " + kind + " of " + std::to_string(tower_brick_count(t)) + " bricks, beyond the limit of " +
                        std::to_string(kMaxGeneratedBlocks));
        // a row of a 10⁴-block trajectory is about 1.5 MB: sample every 50 ms, not 5
        s.run.output_interval = 0.05;
        if (kind == "tower") {
            add_tower(s, t);
            s.description = "Brick tower of four bonded walls, " + std::to_string(t.courses) + " courses (cairn make tower)";
        } else {
            HouseSpec h{t, v.at("door-width"), v.at("door-height"), v.at("window-width"), v.at("window-sill"),
                        v.at("window-height")};
            add_house(s, h);
            s.description = "Brick house of four bonded walls with a door and three windows (cairn make house)";
        }
    }
    if ((long long)s.blocks.size() > kMaxGeneratedBlocks)
        throw Error("a scene of " + std::to_string(s.blocks.size()) + " blocks, beyond the limit of " +
                    std::to_string(kMaxGeneratedBlocks));
    return s;
}

}  // namespace

std::vector<CLI::App*> add_make_commands(CLI::App& app, MakeOptions& options) {
    auto* make = app.add_subcommand("make", "write a scene file from a generator: arch, wall, column, tower, house");
    make->require_subcommand(1);
    std::vector<CLI::App*> subs;
    for (const auto& [kind, params] : generator_params()) {
        auto* sub = make->add_subcommand(kind, "cairn make " + kind + " (lengths take m, cm or mm)");
        std::vector<Param> all = params;
        all.insert(all.end(), common_params().begin(), common_params().end());
        for (const Param& p : all) {
            options.values[kind][p.name] = p.value;
            sub->add_option(std::string("--") + p.name, options.values[kind][p.name],
                            std::string(p.help) + " [" + unit_text(p.unit) + "] (default " + p.value + ")");
        }
        sub->add_option("--out,-o", options.out, "scene file to write (default: standard output)");
        subs.push_back(sub);
    }
    return subs;
}

std::string make_scene_text(const std::string& kind, const std::map<std::string, std::string>& values) {
    std::vector<Param> all = generator_params().at(kind);
    all.insert(all.end(), common_params().begin(), common_params().end());
    std::map<std::string, double> v;
    std::string command = "cairn make " + kind;
    for (const Param& p : all) {
        auto it = values.find(p.name);
        const std::string text = it == values.end() ? p.value : it->second;
        v[p.name] = quantity(p.name, text, p.unit);
        command += " --" + std::string(p.name) + " " + text;
    }
    const Scene scene = generate(kind, v);
    return scene_toml(scene, "generated by: " + command + "\n" + std::to_string(scene.blocks.size()) +
                                 " blocks; edit freely (docs/scenes.md)\n");
}

int make_command(const std::string& kind, const MakeOptions& options) {
    std::string text;
    try {
        text = make_scene_text(kind, options.values.at(kind));
        // what is written must load: the loader's own checks (overlaps at t = 0, limits)
        parse_scene(text, options.out.empty() ? "<cairn make " + kind + ">" : options.out);
    } catch (const Error& e) {
        std::cerr << "error: cairn make " << kind << ": " << e.what() << "\n";
        return kExitBadInput;
    }
    if (options.out.empty()) {
        std::cout << text;
        return std::cout.good() ? kExitOk : kExitFailure;
    }
    write_text_atomic(options.out, text);
    std::cerr << "cairn make " << kind << " -> " << options.out << "\n";
    return kExitOk;
}

}  // namespace cairn

// `cairn make arch|wall|column|colonnade|tower|house`: a scene file from a generator (docs/cli.md)
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

#include <CLI/CLI.hpp>

#include "analytic/arch_thrust.hpp"
#include "analytic/block_limit_analysis.hpp"
#include "commands.hpp"
#include "error.hpp"
#include "geometry/overlap.hpp"
#include "output/atomic_write.hpp"
#include "output/number_format.hpp"
#include "scene/arch_builder.hpp"
#include "scene/colonnade_builder.hpp"
#include "scene/column_builder.hpp"
#include "scene/house_builder.hpp"
#include "scene/scene_io.hpp"
#include "scene/scene_limits.hpp"
#include "scene/scene_toml.hpp"
#include "scene/wall_builder.hpp"

namespace cairn {

namespace {

// what a parameter measures: its SI unit and the suffixes it accepts
enum class Unit { count, length, angle, stiffness, density, time, ratio, choice, openings };

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
          {"thickness-ratio", "0", Unit::ratio, "t/R; when > 0 it sets the thickness instead of --thickness"},
          {"depth", "0.5m", Unit::length, "depth along y"},
          {"angle", "180deg", Unit::angle, "angle the arch subtends: 180deg semicircular, less segmental"},
          {"pointed", "0", Unit::ratio,
           "pointed (two-centred) arch: each half's centre offset from the axis as a fraction of the span 2R; 0 round"},
          {"reference", "none", Unit::choice,
           "none, or limit-analysis: a [reference] of kind arch that expects the arch to stand when a limit analysis of "
           "its blocks as written (straight-sided) at --friction finds a thrust state, else to collapse; a round "
           "arch's comment gives the least t/R of N annular voussoirs beside it"}}},
        {"wall",
         {{"courses", "6", Unit::count, "courses"},
          {"bricks", "6", Unit::count, "whole bricks per course"},
          {"brick-length", "0.4m", Unit::length, "brick length (along the wall)"},
          {"brick-thickness", "0.2m", Unit::length, "brick thickness (the wall's)"},
          {"brick-height", "0.2m", Unit::length, "brick height"},
          {"bond", "running", Unit::choice,
           "running (one brick thick, half-brick offsets) or english (a brick length thick: stretcher "
           "courses of two leaves alternate with header courses closed by queen closers)"},
          {"opening", "", Unit::openings,
           "a door or window x0,z0,width,height (m from the wall's left end and foot; sides rounded to quarter "
           "bricks, sill and head to courses; a lintel over it); repeatable"}}},
        {"column",
         {{"drums", "3", Unit::count, "number of drums"},
          {"width", "0.3m", Unit::length, "side of the square section"},
          {"drum-height", "0.5m", Unit::length, "height of each drum"}}},
        {"colonnade",
         {{"columns", "2", Unit::count, "number of columns (at least 2; 2: a trilithon)"},
          {"width", "0.4m", Unit::length, "side of a column's square section"},
          {"height", "1.6m", Unit::length, "column height"},
          {"spacing", "1.2m", Unit::length, "columns centre to centre, along x (at least the width)"},
          {"beam-height", "0.4m", Unit::length, "height of the beam over the columns"}}},
        {"tower",
         {{"length", "10", Unit::count, "outer length along x, in brick lengths"},
          {"width", "10", Unit::count, "outer width along y, in brick lengths"},
          {"courses", "40", Unit::count, "courses"},
          {"brick-length", "0.24m", Unit::length, "brick length; the walls are half of it thick"},
          {"brick-height", "0.07m", Unit::length, "brick height"},
          {"opening", "", Unit::openings,
           "a hole wall,x0,z0,width,height: wall 0 front (-y), 1 right, 2 back, 3 left; m along the wall from its "
           "-x or -y end and from the base; sides rounded to half bricks, heights to courses; a lintel over it; "
           "repeatable"}}},
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
          {"window-height", "1m", Unit::length, "window height, rounded to whole courses"},
          {"opening", "", Unit::openings,
           "another hole wall,x0,z0,width,height: wall 0 front (-y), 1 right, 2 back, 3 left; m along the wall from its "
           "-x or -y end and from the base; sides rounded to half bricks, heights to courses; a lintel over it; "
           "repeatable"}}},
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
        {"scheme", "overlap", Unit::choice,
         "contact scheme of the in-house engine: paper (hitting points) or overlap (integrated over each face)"},
        {"subdivision", "2", Unit::count, "overlap scheme: sub-contacts per edge of a face, 1 to 16 (1: one sub-contact a face, its twist held by a torsion spring)"},
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
    case Unit::choice: return "a name";
    case Unit::openings: return "m,m,m,m";
    }
    return "";
}

// the value of `text` in SI, or an error naming the option; zero_ok: a length may be 0
double quantity(const std::string& option, const std::string& text, Unit unit, bool zero_ok = false) {
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
    } else if (unit == Unit::ratio || zero_ok ? x < 0.0 : !(x > 0.0)) {
        throw Error(where + (unit == Unit::ratio || zero_ok ? ": must be >= 0" : ": must be > 0"));
    }
    return x;
}

// most blocks a generated scene may hold (a 10⁴-block tower is about 1 MB of TOML)
constexpr long long kMaxGeneratedBlocks = 100000;

// the names a choice parameter accepts
const std::vector<std::string>& choices(const std::string& name) {
    static const std::map<std::string, std::vector<std::string>> c = {
        {"bond", {"running", "english"}},
        {"reference", {"none", "limit-analysis"}},
        {"scheme", {"paper", "overlap"}},
    };
    return c.at(name);
}

// the comma-separated parts of each `--opening` value (the values joined by ';'), each of `parts`
// parts, or an error showing the expected form
std::vector<std::vector<std::string>> opening_parts(const std::string& joined, std::size_t parts, const char* form) {
    std::vector<std::vector<std::string>> out;
    std::size_t start = 0;
    while (start < joined.size()) {
        std::size_t end = joined.find(';', start);
        if (end == std::string::npos) end = joined.size();
        const std::string one = joined.substr(start, end - start);
        start = end + 1;
        std::vector<std::string> p;
        std::size_t from = 0;
        while (p.size() <= parts) {
            std::size_t comma = one.find(',', from);
            p.push_back(one.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
            if (comma == std::string::npos) break;
            from = comma + 1;
        }
        if (p.size() != parts)
            throw Error("--opening " + printable(one) + ": expected " + form + " (m; also cm, mm)");
        out.push_back(p);
        if (out.size() > 1000) throw Error("--opening: more than 1000 openings");
    }
    return out;
}

// the wall's openings of `--opening x0,z0,width,height`
std::vector<WallOpening> openings(const std::string& joined) {
    std::vector<WallOpening> out;
    for (const auto& p : opening_parts(joined, 4, "x0,z0,width,height")) {
        double x[4];
        for (int k = 0; k < 4; ++k) x[k] = quantity("opening", p[size_t(k)], Unit::length, k < 2);
        out.push_back({x[0], x[1], x[2], x[3]});
    }
    return out;
}

// a tower's or house's openings of `--opening wall,x0,z0,width,height` (wall 0-3; x0 along the
// wall from its start, z0 from the base; heights rounded to whole courses of height h)
std::vector<Opening> tower_openings(const std::string& joined, double h) {
    std::vector<Opening> out;
    for (const auto& p : opening_parts(joined, 5, "wall,x0,z0,width,height")) {
        if (p[0].size() != 1 || p[0][0] < '0' || p[0][0] > '3')
            throw Error("--opening " + printable(p[0]) + ",...: the wall is 0 (front, -y), 1 (+x), 2 (+y) or 3 (-x)");
        double x[4];
        for (int k = 0; k < 4; ++k) x[k] = quantity("opening", p[size_t(k) + 1], Unit::length, k < 2);
        out.push_back({p[0][0] - '0', x[0], x[0] + x[2], int(std::lround(x[1] / h)), int(std::lround((x[1] + x[3]) / h))});
    }
    return out;
}

// a generated scene: the scene and the TOML tables scene_toml does not write (probes, reference)
struct Generated {
    Scene scene;
    std::string extra;
    std::string warning;   ///< a reason the scene may not behave as its parameters suggest; empty if none
};

/// joint stiffness number kn·t/(ρ·g·R) at which a 21-voussoir semicircular arch of t/R = ratio ×
/// its least t/R was measured to stand on dem (docs/dem.md, "An arch near its minimum thickness
/// needs stiff joints"; R = 1 m, overlap, ζ = 0.1, the generator's settled start): the least measured
/// value at which it stood, log-interpolated between the measured ratios; 0 from 1.5 × on (every
/// arch measured there stood at kn 1e9)
double arch_joint_stiffness_needed(double ratio) {
    static const std::pair<double, double> stands[] = {
        {1.0769, 1.3526e5}, {1.1237, 4.705e4}, {1.2173, 1.0194e4}, {1.3110, 8.234e3}, {1.4046, 5.881e3},
        {1.4983, 6.273e3}};
    constexpr int n = 6;
    if (ratio >= stands[n - 1].first) return 0.0;
    if (ratio <= stands[0].first) return stands[0].second;
    for (int i = 0; i < n - 1; ++i)
        if (ratio <= stands[i + 1].first) {
            const double f = (ratio - stands[i].first) / (stands[i + 1].first - stands[i].first);
            return std::exp(std::log(stands[i].second) + f * (std::log(stands[i + 1].second) - std::log(stands[i].second)));
        }
    return 0.0;
}

/// a warning when a semicircular arch above its least thickness has joints too soft for it to
/// stand on dem's penalty contact (empty otherwise)
std::string arch_stiffness_warning(const ArchSpec& a, double kn, double density, double least) {
    const double ratio = a.thickness / a.radius / least;
    const double g = 9.81;
    const double number = kn * a.thickness / (density * g * a.radius);
    const double needed = arch_joint_stiffness_needed(ratio);
    if (ratio <= 1.0 || number >= 0.999 * needed) return {};   // 0.999: the table's own points pass
    // the kn to suggest, rounded up to two significant digits (rounding to nearest could suggest the kn
    // the scene already has)
    const double kn_needed = needed * density * g * a.radius / a.thickness;
    const double unit = std::pow(10.0, std::floor(std::log10(kn_needed)) - 1.0);
    const double kn_suggested = std::ceil(kn_needed / unit * (1.0 - 1e-12)) * unit;
    std::ostringstream w;
    w.precision(3);
    w << "t/R = " << a.thickness / a.radius << " is " << ratio << " x the least t/R (" << least << ") of " << a.voussoirs
      << " voussoirs, and kn*t/(rho*g*R) = " << number << " is below the " << needed
      << " at which such arches were measured to stand on dem's compliant joints (docs/dem.md, \"An arch near its"
         " minimum thickness needs stiff joints\"): on dem it may collapse under its own weight while the rigid engines"
         " keep it up; --kn " << kn_suggested << " or more compares with rigid-joint"
         " limit analysis";
    return w.str();
}

Generated generate(const std::string& kind, const std::map<std::string, double>& v,
                   const std::map<std::string, std::string>& text) {
    Generated g;
    Scene& s = g.scene;
    s.materials.push_back({"stone", v.at("density"), 30e9, 0.2});
    s.contact.kn = s.contact.ks = v.at("kn");
    s.contact.friction = v.at("friction");
    s.contact.damping_rule = v.at("damping-ratio") > 0 ? ContactDampingRule::ratio : ContactDampingRule::none;
    s.contact.damping = v.at("damping-ratio");
    s.contact.scheme = text.at("scheme") == "overlap" ? ContactScheme::overlap : ContactScheme::paper;
    s.contact.subdivision = int(v.at("subdivision"));
    if (s.contact.subdivision > 16) throw Error("--subdivision must be at most 16");
    s.run.duration = v.at("duration");
    s.run.output_interval = 0.005;
    auto count = [&](const char* k) { return int(v.at(k)); };
    if (kind == "arch") {
        ArchSpec a{count("voussoirs"), v.at("radius"), v.at("thickness"), v.at("depth"), v.at("angle")};
        if (v.at("thickness-ratio") > 0.0) a.thickness = v.at("thickness-ratio") * a.radius;
        if (a.thickness >= 2 * a.radius) throw Error("--thickness must be less than twice --radius");
        if (a.angle > M_PI + 1e-12) throw Error("--angle must be at most 180deg");
        a.angle = std::min(a.angle, M_PI);
        a.pointed = v.at("pointed");
        if (a.pointed > 1.0) throw Error("--pointed must be at most 1 (centres a span beyond the axis)");
        if (a.pointed > 0.0 && a.angle < M_PI) throw Error("--pointed needs a full arch: --angle 180deg");
        add_arch(s, a);
        std::ostringstream o;
        o.precision(10);
        o << (a.pointed > 0.0 ? "Pointed" : a.angle < M_PI ? "Segmental" : "Semicircular") << " arch of " << a.voussoirs
          << " voussoirs, t/R = " << a.thickness / a.radius << ", on two fixed springers (cairn make arch)";
        s.description = o.str();
        o.str("");
        if (a.pointed == 0.0) {
            // the middle of the crown's intrados, on the keystone (odd N) or left of the crown joint
            o << "[probes.crown]   # middle of the crown's intrados\nblock = \"V" << (a.voussoirs + 1) / 2
              << "\"\npoint = [0.0, 0.0, " << a.radius - 0.5 * a.thickness << "]   # m, world\n\n";
        } else {
            // the centre of the keystone (odd N) or of the voussoir left of the crown joint
            const std::string name = "V" + std::to_string((a.voussoirs + 1) / 2);
            for (const auto& b : s.blocks)
                if (b.name == name) {
                    const Vec3 c = mass_properties(placed_corners(b.corners, b.position, b.orientation), 1.0).centre;
                    o << "[probes.crown]   # centre of the voussoir at the crown\nblock = \"" << name << "\"\npoint = ["
                      << c.x() << ", " << c.y() << ", " << c.z() << "]   # m, world\n\n";
                }
        }
        const bool semicircular = a.pointed == 0.0 && a.angle >= M_PI;
        const double least = semicircular ? oracle::SemicircularArch{a.voussoirs}.minimum_thickness() : NAN;
        if (semicircular) g.warning = arch_stiffness_warning(a, s.contact.kn, v.at("density"), least);
        if (text.at("reference") == "limit-analysis") {
            // whether the limit analysis of its blocks finds a thrust state at the scene's friction
            // (compare/analytic): the blocks as written, straight-sided, which stand a little thinner
            // than the annular voussoirs of the least t/R (N = 9: 0.1015 against 0.1021), and at
            // the joints' μ (thick voussoirs on joints of low μ slide apart: N = 15 at t/R 0.16,
            // μ 0.3, every engine collapses)
            const bool stands =
                oracle::collapse_multiplier(oracle::limit_blocks(s), s.gravity, Vec3::Zero(), s.contact.friction).stands_at_zero;
            o << "[reference]   # rigid-block limit analysis of these voussoirs (mu = " << s.contact.friction << "): "
              << (stands ? "a" : "no") << " thrust state under their weight";
            if (semicircular)
                o << "; t/R = " << a.thickness / a.radius << ", the least t/R of " << a.voussoirs
                  << " annular voussoirs (round intrados and extrados) is " << least;
            o << "\n";
            o << "kind = \"arch\"\nblock = \"V" << (a.voussoirs + 1) / 2 << "\"\nstands = " << (stands ? 1 : 0)
              << "\nthickness = " << a.thickness << "   # m\n";
        }
        g.extra = o.str();
    } else if (kind == "wall") {
        WallSpec w;
        w.courses = count("courses");
        w.bricks = count("bricks");
        w.brick = Vec3(v.at("brick-length"), v.at("brick-thickness"), v.at("brick-height"));
        w.bond = text.at("bond") == "english" ? WallBond::english : WallBond::running;
        w.openings = openings(text.at("opening"));
        add_wall(s, w);
        s.description = "Dry brick wall of " + std::to_string(w.courses) + " courses in " + (text.at("bond") == "english" ? "English" : "running") + " bond" +
                        (w.openings.empty() ? "" : " with " + std::to_string(w.openings.size()) + " opening(s)") +
                        " (cairn make wall)";
    } else if (kind == "colonnade") {
        ColonnadeSpec c{count("columns"), v.at("width"), v.at("height"), v.at("spacing"), v.at("beam-height")};
        if (c.columns < 2)
            throw Error("--columns 1: a colonnade needs at least 2 columns (a block on one column: cairn make column)");
        if (c.spacing < c.width)
            throw Error("--spacing " + number_format("%g", c.spacing) + " m is less than --width " +
                        number_format("%g", c.width) + " m: the columns would overlap");
        add_colonnade(s, c);
        s.description =
            "Colonnade of " + std::to_string(c.columns) + " columns under a beam on a fixed base (cairn make colonnade)";
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
        t.openings = tower_openings(text.at("opening"), t.brick_height);
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
    return g;
}

}  // namespace

std::vector<CLI::App*> add_make_commands(CLI::App& app, MakeOptions& options) {
    auto* make = app.add_subcommand("make", "write a scene file from a generator: arch, wall, column, colonnade, tower, house");
    make->require_subcommand(1);
    std::vector<CLI::App*> subs;
    for (const auto& [kind, params] : generator_params()) {
        auto* sub = make->add_subcommand(kind, "cairn make " + kind + " (lengths take m, cm or mm)");
        std::vector<Param> all = params;
        all.insert(all.end(), common_params().begin(), common_params().end());
        for (const Param& p : all) {
            options.values[kind][p.name] = p.value;
            const std::string help = std::string(p.help) + " [" + unit_text(p.unit) + "]";
            if (p.unit == Unit::openings) {
                // repeatable: the values joined by ';' (which no number contains)
                std::string& joined = options.values[kind][p.name];
                sub->add_option_function<std::vector<std::string>>(
                       std::string("--") + p.name,
                       [&joined](const std::vector<std::string>& all) {
                           joined.clear();
                           for (const auto& one : all) joined += (joined.empty() ? "" : ";") + one;
                       },
                       help)
                    ->allow_extra_args(false);
                continue;
            }
            sub->add_option(std::string("--") + p.name, options.values[kind][p.name],
                            std::string(p.help) + " [" + unit_text(p.unit) + "] (default " + p.value + ")");
        }
        sub->add_option("--out,-o", options.out, "scene file to write (default: standard output)");
        subs.push_back(sub);
    }
    return subs;
}

std::string make_scene_text(const std::string& kind, const std::map<std::string, std::string>& values,
                            std::string* warning) {
    std::vector<Param> all = generator_params().at(kind);
    all.insert(all.end(), common_params().begin(), common_params().end());
    std::map<std::string, double> v;
    std::map<std::string, std::string> text;
    std::string command = "cairn make " + kind;
    for (const Param& p : all) {
        auto it = values.find(p.name);
        const std::string value = it == values.end() ? p.value : it->second;
        if (p.unit == Unit::openings) {
            // one --opening per hole, as typed
            text[p.name] = value;
            std::size_t start = 0;
            while (start < value.size()) {
                const std::size_t end = std::min(value.find(';', start), value.size());
                command += " --" + std::string(p.name) + " " + value.substr(start, end - start);
                start = end + 1;
            }
            continue;
        }
        if (p.unit == Unit::choice) {
            const auto& names = choices(p.name);
            if (std::find(names.begin(), names.end(), value) == names.end()) {
                std::string list;
                for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
                throw Error("--" + std::string(p.name) + " " + printable(value) + ": expected one of " + list);
            }
            text[p.name] = value;
        } else {
            v[p.name] = quantity(p.name, value, p.unit);
        }
        command += " --" + std::string(p.name) + " " + value;
    }
    const Generated g = generate(kind, v, text);
    if (warning) *warning = g.warning;
    return scene_toml(g.scene, "generated by: " + command + "\n" + std::to_string(g.scene.blocks.size()) +
                                   " blocks; edit freely (docs/scenes.md)\n" +
                                   (g.warning.empty() ? "" : "warning: " + g.warning + "\n")) +
           g.extra;
}

int make_command(const std::string& kind, const MakeOptions& options) {
    std::string text, warning;
    try {
        text = make_scene_text(kind, options.values.at(kind), &warning);
        // what is written must load: the loader's own checks (overlaps at t = 0, limits)
        parse_scene(text, options.out.empty() ? "<cairn make " + kind + ">" : options.out);
    } catch (const Error& e) {
        std::cerr << "error: cairn make " << kind << ": " << e.what() << "\n";
        return kExitBadInput;
    }
    if (!warning.empty()) std::cerr << "warning: cairn make " << kind << ": " << warning << "\n";
    if (options.out.empty()) {
        std::cout << text;
        return std::cout.good() ? kExitOk : kExitFailure;
    }
    write_text_atomic(options.out, text);
    std::cerr << "cairn make " << kind << " -> " << options.out << "\n";
    return kExitOk;
}

}  // namespace cairn

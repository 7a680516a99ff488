#include "scene/scene_toml.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "geometry/hexahedron.hpp"
#include "geometry/overlap.hpp"
#include "output/number_format.hpp"

namespace cairn {

namespace {

// a number as TOML, 10 significant digits (always a float: 1e+09, 0.25, 3.0)
std::string num(double x) {
    std::string s = number_format(std::abs(x) >= 1e6 ? "%.9e" : "%.10g", x);
    if (auto e = s.find('e'); e != std::string::npos && s.find('.') != std::string::npos) {
        // drop the mantissa's trailing zeros (and its point if nothing is left after it)
        std::size_t m = e;
        while (s[m - 1] == '0') --m;
        if (s[m - 1] == '.') --m;
        s.erase(m, e - m);
    }
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}

std::string vec(const Vec3& v) { return "[" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + "]"; }

bool identity(const Quat& q) { return q.angularDistance(Quat::Identity()) == 0.0; }

}  // namespace

std::string blocks_toml(const Scene& scene, const std::string& material) {
    std::ostringstream out;
    for (const BlockDef& b : scene.blocks) {
        out << "[blocks." << b.name << "]\n";
        if (b.shape == Shape::box && identity(b.orientation)) {
            out << "size = " << vec(b.size) << "   # m\nposition = " << vec(b.position) << "   # m\n";
        } else {
            out << "shape = \"hexahedron\"\ncorners = [   # m, world\n";
            for (const Vec3& c : placed_corners(b.corners, b.position, b.orientation)) out << "  " << vec(c) << ",\n";
            out << "]\n";
        }
        out << "material = \"" << material << "\"\n";
        if (b.fixed) out << "fixed = true\n";
        out << "\n";
    }
    return out.str();
}

std::string scene_toml(const Scene& scene, const std::string& comment) {
    std::ostringstream out;
    std::istringstream lines(comment);
    for (std::string line; std::getline(lines, line);) out << "# " << line << "\n";
    if (!scene.description.empty()) out << "description = \"" << scene.description << "\"\n";
    if (scene.gravity != Vec3(0.0, 0.0, -9.81)) out << "gravity = " << vec(scene.gravity) << "   # m/s²\n";
    const RunControl& r = scene.run;
    out << "\n[run]\nduration = " << num(r.duration) << "   # s\n";
    if (r.dt) out << "dt = " << num(*r.dt) << "   # s\n";
    out << "output_interval = " << num(r.output_interval) << "   # s\n";
    if (!r.settle) out << "settle = false   # start as placed, not settled under gravity\n";
    for (const Material& m : scene.materials)
        out << "\n[materials." << m.name << "]\ndensity = " << num(m.density) << "   # kg/m³\nyoung = "
            << num(m.young) << "   # Pa\npoisson = " << num(m.poisson) << "\n";
    const ContactLaw& c = scene.contact;
    out << "\n[contact]\nkn = " << num(c.kn) << "   # N/m³\nks = " << num(c.ks) << "   # N/m³\nfriction = "
        << num(c.friction) << "\n";
    if (c.damping_rule == ContactDampingRule::ratio) out << "damping_ratio = " << num(c.damping) << "\n";
    if (c.damping_rule == ContactDampingRule::time) out << "damping_time = " << num(c.damping) << "   # s\n";
    // the scheme always: the loader's default is not the one every scene asks for
    if (c.scheme == ContactScheme::overlap)
        out << "scheme = \"overlap\"\nsubdivision = " << c.subdivision << "   # sub-contacts per edge of a face\n";
    else
        out << "scheme = \"paper\"\ngrid_spacing = " << num(c.grid_spacing) << "   # m, the hitting grid\n";
    out << "\n" << blocks_toml(scene, scene.materials.empty() ? "stone" : scene.materials.front().name);
    return out.str();
}

}  // namespace cairn

#include "mujoco_model.hpp"

#include <iomanip>
#include <sstream>

namespace cairn {

namespace {

std::string vec(const Vec3& v) {
    std::ostringstream s;
    s << std::setprecision(17) << v.x() << ' ' << v.y() << ' ' << v.z();
    return s.str();
}

std::string quat(const Quat& q) {
    std::ostringstream s;
    s << std::setprecision(17) << q.w() << ' ' << q.x() << ' ' << q.y() << ' ' << q.z();
    return s.str();
}

// the geom of a block, centred on its centre of mass, in block axes
std::string geom(const RigidBlock& b, const Scene& scene, const MujocoParameters& p, const std::string& extra) {
    std::ostringstream s;
    s << std::setprecision(17);
    s << "<geom";
    if (b.is_box) s << " type=\"box\" size=\"" << vec(b.half_extents) << "\"";
    else s << " type=\"mesh\" mesh=\"m" << b.index << "\"";
    s << " name=\"g" << b.index << "\" condim=\"3\" margin=\"0\" gap=\"0\" friction=\"" << scene.contact.friction << " 0 0\""
      << " solref=\"" << p.solref[0] << ' ' << p.solref[1] << "\" solimp=\"" << p.impedance << ' ' << p.impedance
      << " 0.001 0.5 2\" " << extra << "/>\n";
    return s.str();
}

}  // namespace

std::string mujoco_xml(const Scene& scene, const std::vector<RigidBlock>& blocks, const MujocoParameters& p) {
    std::ostringstream x;
    x << std::setprecision(17);
    x << "<mujoco model=\"cairn\">\n"
      << "<compiler angle=\"radian\" inertiafromgeom=\"false\" boundmass=\"0\" boundinertia=\"0\"/>\n"
      << "<option timestep=\"" << p.dt << "\" gravity=\"" << vec(scene.gravity) << "\" cone=\"" << p.cone
      << "\" impratio=\"" << p.impratio << "\" integrator=\"Euler\" solver=\"" << p.solver << "\" iterations=\""
      << p.iterations << "\" noslip_iterations=\"" << p.noslip_iterations << "\" tolerance=\"" << p.tolerance
      << "\" density=\"0\" viscosity=\"0\"/>\n"
      << "<size njmax=\"" << p.njmax << "\" nconmax=\"" << p.nconmax << "\"/>\n";
    // mesh vertices relative to the centre of mass, block axes
    x << "<asset>\n";
    for (const RigidBlock& b : blocks) {
        if (b.is_box) continue;
        x << "<mesh name=\"m" << b.index << "\" vertex=\"";
        for (const Vec3& c : b.corners) x << vec(c - b.com) << ' ';
        x << "\"/>\n";
    }
    x << "</asset>\n<worldbody>\n";
    for (const RigidBlock& b : blocks) {
        if (b.fixed) {
            x << geom(b, scene, p, "pos=\"" + vec(b.com_world) + "\" quat=\"" + quat(b.orientation) + "\"");
            continue;
        }
        const Mat3& I = b.inertia;
        x << "<body name=\"" << b.index << "\" pos=\"" << vec(b.com_world) << "\" quat=\"" << quat(b.orientation)
          << "\">\n<freejoint/>\n<inertial pos=\"0 0 0\" mass=\"" << b.mass << "\" fullinertia=\"" << I(0, 0)
          << ' ' << I(1, 1) << ' ' << I(2, 2) << ' ' << I(0, 1) << ' ' << I(0, 2) << ' ' << I(1, 2) << "\"/>\n"
          << geom(b, scene, p, "") << "</body>\n";
    }
    x << "</worldbody>\n</mujoco>\n";
    return x.str();
}

}  // namespace cairn

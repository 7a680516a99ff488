#include "cases/case_util.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>

#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "geometry/overlap.hpp"
#include "output/number_format.hpp"

namespace cairn::cases {

double block_mass(const Scene& scene, int b) {
    const BlockDef& d = scene.blocks.at(b);
    return mass_properties(d.corners, scene.materials.at(d.material).density).mass;
}

double bottom_area(const Scene& scene, int b) {
    const auto& c = scene.blocks.at(b).corners;
    Vec3 n = (c[2] - c[0]).cross(c[3] - c[1]);
    return 0.5 * n.norm();
}

double contact_area(const Scene& scene) {
    int a = scene.reference ? scene.reference->block : 0;
    double area = bottom_area(scene, a);
    for (size_t i = 0; i < scene.blocks.size(); ++i)
        if (scene.blocks[i].fixed) return std::min(area, bottom_area(scene, int(i)));
    return area;
}

double gravity(const Scene& scene) { return scene.gravity.norm(); }

std::string message_vector(const Vec3& v) {
    return "[" + message_number(v.x()) + ", " + message_number(v.y()) + ", " + message_number(v.z()) + "]";
}

double joint_to_block_stiffness(const Scene& scene, int b) {
    const BlockDef& d = scene.blocks.at(size_t(b));
    double lo = 1e300, hi = -1e300;
    for (const auto& c : d.corners) lo = std::min(lo, c.z()), hi = std::max(hi, c.z());
    return scene.contact.kn * (hi - lo) / scene.materials.at(size_t(d.material)).young;
}

std::string flexible_block_reason(const Scene& scene, int b, bool deformable, double limit) {
    if (!deformable) return "";
    const double r = joint_to_block_stiffness(scene, b);
    if (r <= limit) return "";
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  " is compliant against its joints (kn·h/E = %.3g, above %.3g): its vibration takes and gives back "
                  "rocking energy, which the rigid-block references leave out (docs/validation.md, \"A flexible block "
                  "rocking\")",
                  r, limit);
    return "not judged: the deformable block " + scene.blocks.at(size_t(b)).name + buf;
}

double joint_to_block_shear(const Scene& scene, int b) {
    const BlockDef& d = scene.blocks.at(size_t(b));
    double lo = 1e300, hi = -1e300;
    for (const auto& c : d.corners) lo = std::min(lo, c.z()), hi = std::max(hi, c.z());
    const Material& m = scene.materials.at(size_t(d.material));
    return scene.contact.ks * (hi - lo) * 2.0 * (1.0 + m.poisson) / m.young;
}

void show_if_flexible(const Scene& scene, const ContactKind& contact, std::vector<metrics::Metric>& metrics) {
    const int b = scene.reference->block;
    const double ratio = joint_to_block_stiffness(scene, b);   // kn·h/E
    if (!contact.deformable || ratio <= kRigidUnderDrive) return;
    char why[300];
    std::snprintf(why, sizeof why,
                  "not judged: the deformable block %s is compliant against its joints (kn·h/E = %.3g, above %.3g): "
                  "its own vibration, which the rigid sliding block leaves out, takes part in its motion; ",
                  scene.blocks.at(size_t(b)).name.c_str(), ratio, kRigidUnderDrive);
    for (auto& m : metrics)
        if (m.judged()) m = metrics::info(m.name, m.unit, m.value, m.reference, why + m.basis);
}

int free_index(const Scene& scene, int block) {
    assert(block >= 0 && size_t(block) < scene.blocks.size());   // the loader resolved the name
    int k = 0;
    for (int i = 0; i < block; ++i)
        if (!scene.blocks[i].fixed) ++k;
    return k;
}

int probe_index(const Scene& scene, const std::string& name) {
    for (size_t i = 0; i < scene.probes.size(); ++i)
        if (scene.probes[i].name == name) return int(i);
    return -1;
}

double dashpot(const Scene& scene, double stiffness, double mass) {
    switch (scene.contact.damping_rule) {
        case ContactDampingRule::ratio: return 2.0 * scene.contact.damping * std::sqrt(stiffness * mass);
        case ContactDampingRule::time: return scene.contact.damping * stiffness;
        case ContactDampingRule::none: return 0.0;
    }
    return 0.0;
}

std::vector<double> times(const std::vector<Sample>& s) {
    std::vector<double> t;
    t.reserve(s.size());
    for (const auto& x : s) t.push_back(x.t);
    return t;
}

metrics::Series probe_series(const std::vector<Sample>& s, int p, int c, bool relative) {
    metrics::Series out{times(s), {}};
    for (const auto& x : s) out.y.push_back(x.probes.at(p)[c] - (relative ? s.front().probes.at(p)[c] : 0.0));
    return out;
}

metrics::Series com_series(const std::vector<Sample>& s, int f, int c, bool relative) {
    metrics::Series out{times(s), {}};
    for (const auto& x : s)
        out.y.push_back(x.blocks.at(f).position[c] - (relative ? s.front().blocks.at(f).position[c] : 0.0));
    return out;
}

Vec3 up_direction(const Scene& scene) {
    const Vec3& g = scene.gravity;
    if (g.x() == 0.0 && g.y() == 0.0 && g.z() < 0.0) return Vec3::UnitZ();
    return -g.normalized();
}

metrics::Series rise_series(const Scene& scene, const std::vector<Sample>& s, int p, int f) {
    const Vec3 up = up_direction(scene);
    auto at = [&](const Sample& x) { return p >= 0 ? x.probes.at(size_t(p)) : x.blocks.at(size_t(f)).position; };
    metrics::Series out{times(s), {}};
    for (const auto& x : s) out.y.push_back((at(x) - at(s.front())).dot(up));
    return out;
}

metrics::Series angle_series(const std::vector<Sample>& s, int f, const Vec3& axis, const Quat& from) {
    metrics::Series out{times(s), {}};
    double prev = 0.0, offset = 0.0;
    const Quat back = from.conjugate();
    for (size_t i = 0; i < s.size(); ++i) {
        Quat q = s[i].blocks.at(f).orientation * back;
        // q and −q are one turn: the one with q_w ≥ 0, so that an unturned block reads 0, not 2π
        if (q.w() < 0.0) q.coeffs() = -q.coeffs();
        // twist of q about the axis: 2 atan2(q_v·axis, q_w)
        double a = 2.0 * std::atan2(Vec3(q.x(), q.y(), q.z()).dot(axis), q.w());
        if (i > 0) {
            while (a + offset - prev > M_PI) offset -= 2.0 * M_PI;
            while (a + offset - prev < -M_PI) offset += 2.0 * M_PI;
        }
        prev = a + offset;
        out.y.push_back(prev);
    }
    return out;
}

Vec3 rocking_axis(const Scene& scene) {
    const auto& v = scene.reference->values;
    auto get = [&](const char* k) { auto it = v.find(k); return it == v.end() ? 0.0 : it->second; };
    const Vec3 a(get("axis_x"), get("axis_y"), get("axis_z"));
    return a.norm() > 0.0 ? a.normalized() : Vec3::UnitY();
}

Vec3 rocking_axis_block(const Scene& scene) {
    return scene.blocks.at(size_t(scene.reference->block)).orientation.conjugate() * rocking_axis(scene);
}

Quat upright_orientation(const Scene& scene) {
    const BlockDef& d = scene.blocks.at(size_t(scene.reference->block));
    const Vec3 up = -scene.gravity.normalized(), axis = rocking_axis(scene), height = d.orientation * Vec3::UnitZ();
    // the signed lean of the block's height from the vertical about the axis
    const double lean = std::atan2(up.cross(height).dot(axis), up.dot(height));
    return Quat(Eigen::AngleAxisd(-lean, axis)) * d.orientation;
}

namespace {

/// the free block whose top the lowest corner of block d touches (within 1 % of d's height) and
/// lies over, or nullptr; `up` against gravity, `axis` horizontal
const BlockDef* free_block_under(const Scene& scene, const BlockDef& d, const Vec3& up, const Vec3& axis) {
    const Corners w = placed_corners(d.corners, d.position, d.orientation);
    Vec3 low = w[0];
    for (const auto& c : w)
        if (c.dot(up) < low.dot(up)) low = c;
    const double height = (w[4] - w[0]).norm();
    const Vec3 e1 = axis, e2 = up.cross(axis);
    for (const auto& b : scene.blocks) {
        if (b.fixed || &b == &d) continue;
        double top = -1e300, lo1 = 1e300, hi1 = -1e300, lo2 = 1e300, hi2 = -1e300;
        for (const auto& c : placed_corners(b.corners, b.position, b.orientation)) {
            top = std::max(top, c.dot(up));
            lo1 = std::min(lo1, c.dot(e1)), hi1 = std::max(hi1, c.dot(e1));
            lo2 = std::min(lo2, c.dot(e2)), hi2 = std::max(hi2, c.dot(e2));
        }
        const double x1 = low.dot(e1), x2 = low.dot(e2);
        if (std::abs(low.dot(up) - top) <= 0.01 * height && x1 >= lo1 && x1 <= hi1 && x2 >= lo2 && x2 <= hi2) return &b;
    }
    return nullptr;
}

/// another free block that touches block d (their gap within 1 % of d's height: a block standing
/// on it, leaning on it or beside it), or nullptr
const BlockDef* free_block_touching(const Scene& scene, const BlockDef& d) {
    const Corners w = placed_corners(d.corners, d.position, d.orientation);
    const double height = (w[4] - w[0]).norm();
    for (const auto& b : scene.blocks)
        if (!b.fixed && &b != &d &&
            overlap_depth(w, placed_corners(b.corners, b.position, b.orientation)) > -0.01 * height)
            return &b;
    return nullptr;
}

}  // namespace

void require_tilted_release(const Scene& scene, const std::string& kind) {
    const BlockDef& d = scene.blocks.at(size_t(scene.reference->block));
    const Vec3 up = -scene.gravity.normalized(), axis = rocking_axis(scene), height = d.orientation * Vec3::UnitZ();
    const double theta0 = std::abs(scene.reference->values.at("theta0"));
    const double lean = std::atan2(up.cross(height).norm(), up.dot(height));
    // 1e-3 rad: an angle written to four decimals in degrees
    char why[400] = "";
    if (std::abs(axis.dot(up)) > 1e-3)
        std::snprintf(why, sizeof why, "the rocking axis (%.4g, %.4g, %.4g) is not horizontal", axis.x(), axis.y(), axis.z());
    else if (std::abs(height.dot(axis)) > 1e-3 || std::abs(lean - theta0) > 1e-3)
        std::snprintf(why, sizeof why,
                      "block %s's height (of its axes, the one nearest its base's normal) leans %.5g rad from the "
                      "vertical%s, not theta0 = %.5g rad about the rocking axis: the oracle releases the block "
                      "leaning θ0 about that axis, its height vertical when upright",
                      d.name.c_str(), lean, std::abs(height.dot(axis)) > 1e-3 ? " and out of the plane across the axis" : "",
                      theta0);
    // the references rock the block on a fixed base: a free block under it (a column's lower drum)
    // would move with the impacts
    const BlockDef* under = why[0] ? nullptr : free_block_under(scene, d, up, axis);
    if (under)
        std::snprintf(why, sizeof why,
                      "block %s rests on free block '%s': the rocking references stand it on a fixed base (name a "
                      "block standing on a fixed block, or fix '%s')",
                      d.name.c_str(), under->name.c_str(), under->name.c_str());
    // nor anything on it or beside it: a block on its top rocks with it and then on it
    const BlockDef* touching = why[0] ? nullptr : free_block_touching(scene, d);
    if (touching)
        std::snprintf(why, sizeof why,
                      "block %s touches free block '%s': the rocking references rock one block alone on a fixed base "
                      "(leave out [reference] to compare the engines with each other, or fix '%s')",
                      d.name.c_str(), touching->name.c_str(), touching->name.c_str());
    if (why[0])
        throw Error(scene.source + ": reference.kind = \"" + kind + "\": " + why);
}

void require_alone(const Scene& scene, const std::string& kind) {
    const BlockDef& d = scene.blocks.at(size_t(scene.reference->block));
    if (const BlockDef* other = free_block_touching(scene, d))
        throw Error(scene.source + ": reference.kind = \"" + kind + "\": block " + d.name + " touches free block '" +
                    other->name + "': the " + kind +
                    " reference models one block alone on a fixed base, and a block on it, under it or beside it "
                    "shares its loads and its slip (leave out [reference] to compare the engines with each other, or "
                    "fix '" + other->name + "')");
}

oracle::HousnerBlock housner_block(const Scene& scene) { return housner_block(scene, rocking_axis_block(scene)); }

oracle::HousnerBlock housner_block(const Scene& scene, const Vec3& axis) {
    const BlockDef& d = scene.blocks.at(size_t(scene.reference->block));
    const Vec3 across = axis.cross(Vec3::UnitZ()).normalized();
    double lo = 1e300, hi = -1e300, zlo = 1e300, zhi = -1e300;
    for (const auto& c : d.corners) {
        lo = std::min(lo, c.dot(across));
        hi = std::max(hi, c.dot(across));
        zlo = std::min(zlo, c.z());
        zhi = std::max(zhi, c.z());
    }
    return {0.5 * (hi - lo), 0.5 * (zhi - zlo), gravity(scene)};
}

std::array<PlacedSide, 6> placed_sides(const BlockDef& b) {
    const Corners w = placed_corners(b.corners, b.position, b.orientation);
    const Vec3 centre = mass_properties(w, 1.0).centre;
    std::array<PlacedSide, 6> out;
    for (size_t k = 0; k < kFaceCorners.size(); ++k) {
        const auto& f = kFaceCorners[k];
        const Vec3 &c0 = w[size_t(f[0])], &c1 = w[size_t(f[1])], &c2 = w[size_t(f[2])], &c3 = w[size_t(f[3])];
        Vec3 n = (c2 - c0).cross(c3 - c1).normalized();
        if (n.dot(c0 - centre) < 0) n = -n;   // outward
        out[k] = {n, c0};
    }
    return out;
}

std::function<Vec3(double)> reference_drive(const Scene& scene) {
    const int a = scene.reference->block;
    const double m = block_mass(scene, a);
    return [&scene, a, m](double t) {
        Vec3 f = Vec3::Zero();
        for (const auto& l : scene.loads)
            if (l.block == a) f += l.factor(t) * l.force;
        return Vec3(f / m);
    };
}

void require_drive_modelled(const Scene& scene, const std::string& kind, DriveModelled modelled) {
    const std::string head = scene.source + ": reference.kind = \"" + kind + "\": ";
    if (scene.ground_motion)
        throw Error(head + "[ground_motion]: the " + kind + " reference does not model a ground motion");
    for (const auto& l : scene.loads)
        if (!modelled.loads_on_reference || l.block != scene.reference->block)
            throw Error(head + "[loads]: a load on block '" + scene.blocks.at(size_t(l.block)).name + "' is not modelled by the " +
                        kind + " reference" + (modelled.loads_on_reference ? " (only loads on its block are)" : ""));
    const BlockDef& d = scene.blocks.at(size_t(scene.reference->block));
    if (!modelled.initial_velocity && (d.velocity.norm() > 0.0 || d.angular_velocity.norm() > 0.0))
        throw Error(head + "blocks." + d.name + ".velocity/angular_velocity: the " + kind +
                    " reference releases its block at rest");
}

void require_horizontal_base(const Scene& scene, const std::string& kind) {
    const Vec3 g = scene.gravity.normalized();
    // 1e-3 rad: a plane written to four decimals in degrees
    if (g.dot(-Vec3::UnitZ()) < std::cos(1e-3))
        throw Error(scene.source + ": a " + kind + " reference needs gravity along −z (the base horizontal)");
    for (const auto& b : scene.blocks)
        if (b.fixed) {
            if ((b.orientation * Vec3::UnitZ()).z() < std::cos(1e-3))
                throw Error(scene.source + ": a " + kind + " reference needs a horizontal support; block '" + b.name +
                            "' is tilted");
            return;
        }
    throw Error(scene.source + ": a " + kind + " reference needs a fixed block as its base");
}

Quat gravity_down(const Scene& scene) {
    const Vec3 g = scene.gravity.normalized();
    if (g.dot(-Vec3::UnitZ()) >= 1.0 - 1e-15) return Quat::Identity();
    return Quat::FromTwoVectors(g, -Vec3::UnitZ());
}

namespace {

/// a block's place, orientation and speeds (a BlockDef at t = 0 or a sampled BlockState) turned by r
template <class Body>
void turn_body(Body& b, const Quat& r) {
    b.position = r * b.position;
    b.orientation = (r * b.orientation).normalized();
    b.velocity = r * b.velocity;
    b.angular_velocity = r * b.angular_velocity;
}

}  // namespace

Scene turned_scene(const Scene& scene, const Quat& r) {
    Scene out = scene;
    out.gravity = r * scene.gravity;
    for (auto& b : out.blocks) turn_body(b, r);
    for (auto& l : out.loads) l.force = r * l.force;
    if (out.ground_motion)
        for (auto& c : out.ground_motion->components) c.direction = r * c.direction;
    return out;
}

std::vector<Sample> turned_samples(const std::vector<Sample>& s, const Quat& r) {
    std::vector<Sample> out = s;
    for (auto& x : out) {
        for (auto& p : x.probes) p = r * p;
        for (auto& b : x.blocks) turn_body(b, r);
    }
    return out;
}

metrics::Metric slip_while_held(const metrics::Series& s, double t0, double t1, double tol, const std::string& basis,
                                metrics::HeldDrift* held) {
    const auto d = metrics::held_drift(s, t0, t1, 0.25 * tol);
    if (held) *held = d;
    if (d.resolved) {
        const std::string how = d.ringing > 0.25 * tol ? "the lines through its turning points" : "a straight-line fit";
        return metrics::absolute("slip while held", "m", d.drift, 0.0, tol, "drift over " + how + "; " + basis);
    }
    char why[300];
    if (d.unsteady)
        std::snprintf(why, sizeof why,
                      "not judged: it rings unsteadily by ±%.3g m (its turning points do not lie along two lines: a "
                      "response forced by a record, or a ringing that stops within the window), so a drift cannot be "
                      "told from the ringing; ",
                      d.ringing);
    else
        std::snprintf(why, sizeof why,
                      "not judged: it rings by ±%.3g m with fewer than two swings in the window, so a drift cannot be "
                      "told from the ringing (run longer); ",
                      d.ringing);
    return metrics::info("slip while held", "m", d.drift, 0.0, why + basis);
}

}  // namespace cairn::cases

#include "contact_twist.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cairn::dem {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

double disc_polar_moment(double area) { return area * area / (2.0 * kPi); }

double disc_friction_radius(double area) { return (2.0 / 3.0) * std::sqrt(area / kPi); }

double twist_spin(const SubTwist& tw, const Block& hb, const Block& tb) {
    // two rigid blocks: the pair's relative velocity over 2ρ along t2 is (ω_h − ω_t)·(t1 × t2)
    if (!hb.deformable && !tb.deformable) return (hb.spin - tb.spin).dot(tw.axis);
    return (tw.hit.velocity(hb) - tw.target.velocity(tb)).dot(tw.dir);
}

namespace {
// the weights of x + a less those of x − a on block b (face `face`): both points lie on the same
// element of the face, so the two share their nodes
NodeWeights weight_difference(const Block& b, int face, const Vec3& x, const Vec3& a) {
    if (!b.deformable) {
        // rigid: the weights are affine in the point (node_weights), their difference linear in 2a
        NodeWeights nw = node_weights(b, face, x);
        const Vec3 l = b.corner_inverse * (2.0 * a);
        nw.w = {-l.sum(), l[0], l[1], l[2]};
        return nw;
    }
    NodeWeights plus = node_weights(b, face, x + a);
    const NodeWeights minus = node_weights(b, face, x - a);
    for (int i = 0; i < plus.count; ++i) plus.w[size_t(i)] -= minus.w[size_t(i)];
    return plus;
}
}  // namespace

void update_twist(SubTwist& tw, const TwistInput& in, const TwistLaw& law, const Block& hb, int hit_face,
                  const Block& tb, int target_face, double dt, ContactTotals& tot) {
    // the pair's points: ±ρ along a tangent t1 from the centroid; a force along t2 = n × t1 per
    // unit moment 1/(2ρ); the spin is the pair's relative velocity along t2 over 2ρ (on rigid
    // blocks the relative angular velocity about n, wherever the points lie)
    Vec3 t1 = in.edge - in.edge.dot(in.normal) * in.normal;
    if (!(t1.squaredNorm() > 1e-12 * in.edge.squaredNorm()))   // an edge along the normal: any tangent
        t1 = in.normal.cross(std::abs(in.normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY());
    t1.normalize();
    const Vec3 t2 = in.normal.cross(t1);
    const double rho = 0.25 * std::sqrt(in.area);
    const double spin_old = in.lay ? 0.0 : twist_spin(tw, hb, tb);
    const double moment_before = in.lay ? 0.0 : tw.moment;
    const double damper_before = in.lay ? 0.0 : tw.damper;
    const double energy_before = in.lay ? 0.0 : tw.energy;
    tw.hit = weight_difference(hb, hit_face, in.centroid, rho * t1);
    tw.target = weight_difference(tb, target_face, in.centroid, rho * t1);
    tw.dir = t2 / (2.0 * rho);
    tw.axis = t1.cross(t2);
    const double spin_new = twist_spin(tw, hb, tb);
    if (in.lay) tw.angle = 0.0;
    const double spin = in.lay ? spin_new : 0.5 * (spin_old + spin_new);
    // the spring's stiffness ks·J follows the area (J = a²/2π): the offset is scaled so that a
    // change of area keeps ½kt·φ² (φ by √(kt_old/kt) = a_old/a), its growth by the step's mean
    double angle = tw.angle + spin * dt;
    if (!in.lay && tw.area > 0.0) {
        const double scale = tw.area / in.area;
        angle = tw.angle * scale + 0.5 * (1.0 + scale) * spin * dt;
    }
    tw.area = in.area;
    const double j = disc_polar_moment(in.area);
    const double kt = law.ks * j;
    const double m_el = -kt * angle;
    // what friction has left for the moment after the shear force took its part
    double cap = std::numeric_limits<double>::max();
    if (law.slip) {
        const double full = law.friction * in.normal_force;
        const double used = full > 0.0 ? std::min(1.0, in.shear_force / full) : 1.0;
        cap = full * disc_friction_radius(in.area) * std::sqrt(std::max(0.0, 1.0 - used * used));
    }
    double moment = 0.0, damper = 0.0;
    if (std::abs(m_el) > cap) {
        // slip: capped, the offset shrinks to match; friction took what the blocks lost less
        // what the spring kept (the leapfrog step's trapezoid of the moment times the spin)
        moment = std::copysign(cap, m_el);
        angle = kt > 0.0 ? -moment / kt : 0.0;
        tw.energy = kt > 0.0 ? 0.5 * moment * moment / kt : 0.0;
        const double taken = -0.5 * dt * (moment_before * (in.lay ? spin_new : spin_old) + moment * spin_new);
        tot.dissipated += taken - (tw.energy - energy_before);
    } else {
        // stick: spring plus dashpot, trimmed to the cap
        moment = m_el - law.damper * j * spin_new;
        if (std::abs(moment) > cap) moment = std::copysign(cap, moment);
        damper = moment - m_el;
        tw.energy = 0.5 * kt * angle * angle;
        tot.dissipated -= 0.5 * (damper_before * (in.lay ? spin_new : spin_old) + damper * spin_new) * dt;
    }
    tw.angle = angle;
    tw.moment = moment;
    tw.damper = damper;
    tot.stored += tw.energy;
}

void release_twist(SubTwist& tw, const Block& hb, const Block& tb, double dt, ContactTotals& tot) {
    if (tw.area > 0.0) {
        tot.dissipated += std::max(0.0, tw.energy);
        tot.dissipated -= 0.5 * dt * tw.moment * twist_spin(tw, hb, tb);
    }
    tw = SubTwist{};
}

void add_twist_forces(const SubTwist& tw, const Vec3& normal, std::vector<SubForce>* keep, Block& hb, Block& tb) {
    if (tw.moment == 0.0) return;
    const Vec3 f = tw.moment * tw.dir;
    if (keep) {
        keep->push_back(SubForce{tw.hit, tw.target, f, normal, tw.hit, tw.target, true});
    } else {
        tw.hit.add(hb, f);
        tw.target.add(tb, -f);
    }
}

}  // namespace cairn::dem

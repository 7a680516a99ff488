#include "world.hpp"

#include <cmath>

namespace cairn::dem {

Block make_rigid_block(const BlockDef& def, const Material& mat, double grid_spacing) {
    Block b;
    b.name = def.name;
    b.fixed = def.fixed;
    MassProperties mp = mass_properties(def.corners, mat.density);
    b.volume = mp.volume;
    b.com_in_frame = mp.centre;
    b.body.mass = mp.mass;
    b.body.inertia_body = mp.inertia;
    b.body.inv_inertia_body = mp.inertia.inverse();
    b.body.q = def.orientation.normalized();
    b.body.x = def.position + b.body.q * mp.centre;
    if (!def.fixed) {
        b.body.v = def.velocity;
        b.body.set_omega(def.angular_velocity);
    }
    for (const auto& c : def.corners) {
        b.local.push_back(c - mp.centre);
        b.r_max = std::max(b.r_max, (c - mp.centre).norm());
    }
    b.x.resize(8);
    b.v.resize(8);
    b.f.assign(8, Vec3::Zero());
    b.min_edge = 1e300;
    for (const auto& fc : kFaceCorners) {
        b.faces.push_back({fc[0], fc[1], fc[2], fc[3]});
        Quad q{def.corners[fc[0]], def.corners[fc[1]], def.corners[fc[2]], def.corners[fc[3]]};
        b.hits.push_back(hit_grid(q, grid_spacing));
        b.face_area.push_back(quad_area(q));
        for (int i = 0; i < 4; ++i) b.min_edge = std::min(b.min_edge, (q[(i + 1) % 4] - q[i]).norm());
    }
    b.update_nodes();
    b.x_at_refresh = b.body.x;
    b.q_at_refresh = b.body.q;
    return b;
}

World::World(const Scene& scene, double dt, double margin) : scene_(scene), dt_(dt) {
    for (const auto& def : scene.blocks)
        blocks_.push_back(make_rigid_block(def, scene.materials[def.material], scene.contact.grid_spacing));
    contacts_.configure(scene.contact, margin);
    contacts_.refresh(blocks_);
    force_.assign(blocks_.size(), Vec3::Zero());
    torque_.assign(blocks_.size(), Vec3::Zero());
    load_point_.resize(scene.loads.size());
    load_force_.resize(scene.loads.size());
    for (size_t i = 0; i < scene.loads.size(); ++i) {
        const auto& l = scene.loads[i];
        load_point_[i] = blocks_[l.block].world_point(l.point);
        load_force_[i] = l.factor(0.0) * l.force;
    }
    compute_forces();
}

double World::kinetic() const {
    double e = 0.0;
    for (const auto& b : blocks_)
        if (!b.fixed) e += b.body.kinetic_energy();
    return e;
}

double World::potential() const {
    double e = 0.0;
    for (const auto& b : blocks_)
        if (!b.fixed) e -= b.body.mass * scene_.gravity.dot(b.body.x);
    return e;
}

bool World::step() {
    refresh_if_due();
    kick(0.5 * dt_);
    drift();
    t_ += dt_;
    ++step_;
    compute_forces();
    kick(0.5 * dt_);
    return state_finite();
}

// stage: refresh the contact candidates every n steps, or sooner if the margin could be crossed
void World::refresh_if_due() {
    ++steps_since_refresh_;
    bool due = steps_since_refresh_ >= scene_.run.contact_interval;
    if (!due) {
        for (const auto& b : blocks_)
            if (!b.fixed && b.motion_since_refresh() > 0.5 * contacts_.margin()) {
                due = true;
                ++early_refreshes_;
                break;
            }
    }
    if (!due) return;
    contacts_.refresh(blocks_);
    steps_since_refresh_ = 0;
}

// stage: half-step momentum update from the current forces
void World::kick(double h) {
    for (size_t i = 0; i < blocks_.size(); ++i) {
        if (blocks_[i].fixed) continue;
        energy_.dissipated += dem::kick(blocks_[i].body, force_[i], torque_[i], h, scene_.damping.alpha);
    }
}

// stage: move every free block over the step
void World::drift() {
    for (auto& b : blocks_)
        if (!b.fixed) dem::drift(b.body, dt_);
}

// stage: node positions, then gravity, loads and contact forces into block resultants
void World::compute_forces() {
    for (auto& b : blocks_) {
        b.update_nodes();
        std::fill(b.f.begin(), b.f.end(), Vec3::Zero());
    }
    ContactTotals ct = contacts_.apply(blocks_, dt_);
    energy_.contact = ct.stored;
    energy_.dissipated += ct.dissipated;
    active_ = ct.active;
    for (size_t i = 0; i < blocks_.size(); ++i) {
        const Block& b = blocks_[i];
        force_[i] = b.body.mass * scene_.gravity;
        torque_[i].setZero();
        for (size_t n = 0; n < b.x.size(); ++n) {
            force_[i] += b.f[n];
            torque_[i] += (b.x[n] - b.body.x).cross(b.f[n]);
        }
    }
    for (size_t i = 0; i < scene_.loads.size(); ++i) {
        const auto& l = scene_.loads[i];
        const Block& b = blocks_[l.block];
        Vec3 p = b.world_point(l.point);
        Vec3 f = l.factor(t_) * l.force;
        // trapezoid rule for the work over the step
        energy_.external += 0.5 * (f + load_force_[i]).dot(p - load_point_[i]);
        load_point_[i] = p;
        load_force_[i] = f;
        force_[l.block] += f;
        torque_[l.block] += (p - b.body.x).cross(f);
    }
}

bool World::state_finite() const {
    for (const auto& b : blocks_)
        if (!b.body.x.allFinite() || !b.body.v.allFinite() || !b.body.L.allFinite() ||
            !b.body.q.coeffs().allFinite())
            return false;
    return std::isfinite(energy_.contact);
}

}  // namespace cairn::dem

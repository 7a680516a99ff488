#include "world.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "contact_reach.hpp"

namespace cairn::dem {

namespace {

// below this many blocks a parallel region over the blocks costs more than it saves
constexpr long kParallelBlocks = 2048;

}  // namespace

World::World(const Scene& scene, double margin) : scene_(scene), margin_(margin) {
    for (const auto& def : scene.blocks) blocks_.push_back(make_block(def, scene));
    for (const auto& p : scene.probes) probes_.push_back(locate(blocks_[p.block], p.block, p.point));
    for (const auto& l : scene.loads) loads_.push_back(locate(blocks_[l.block], l.block, l.point));
    contacts_.configure(scene.contact, margin);
    contacts_.refresh(blocks_);
    force_.assign(blocks_.size(), Vec3::Zero());
    torque_.assign(blocks_.size(), Vec3::Zero());
    loss_.assign(blocks_.size(), 0.0);
    accel_.resize(blocks_.size());
    event_.assign(blocks_.size(), 0);
    force_end_.assign(blocks_.size(), Vec3::Zero());
    torque_end_.assign(blocks_.size(), Vec3::Zero());
    accel_end_.resize(blocks_.size());
    f_end_.resize(blocks_.size());
    for (size_t i = 0; i < blocks_.size(); ++i)
        if (blocks_[i].deformable) accel_[i].assign(blocks_[i].x.size(), Vec3::Zero());
    for (size_t i = 0; i < loads_.size(); ++i) {
        const Block& b = blocks_[loads_[i].block];
        load_point_.push_back(scene.loads[i].body ? b.body.x : world_position(b, loads_[i]));
        load_force_.push_back(scene.loads[i].factor(0.0) * scene.loads[i].force);
    }
}

void World::start(double dt) {
    dt_ = dt;
    compute_forces();
}

double World::kinetic() const {
    const double h = 0.5 * dt_;
    double e = 0.0;
    std::vector<Vec3> dv;
    for (size_t i = 0; i < blocks_.size(); ++i) {
        const Block& b = blocks_[i];
        if (b.fixed) continue;
        const bool ev = event_[i] != 0;
        if (!b.deformable) {
            e += b.body.kinetic_energy() -
                 half_kick_energy(b.body, ev ? force_end_[i] : force_[i], ev ? torque_end_[i] : torque_[i], h);
            continue;
        }
        const auto& a = ev ? accel_end_[i] : accel_[i];
        dv.resize(a.size());
        for (size_t n = 0; n < a.size(); ++n) dv[n] = h * a[n];
        e += b.deformable->kinetic_energy(b.x, b.v) - b.deformable->kinetic_energy(b.x, dv);
    }
    return e;
}

double World::potential() const {
    double e = 0.0;
    for (const auto& b : blocks_) {
        if (b.fixed) continue;
        if (!b.deformable) {
            e -= b.body.mass * scene_.gravity.dot(b.body.x);
            continue;
        }
        const auto& m = b.deformable->lumped_mass();
        for (size_t n = 0; n < b.x.size(); ++n) e -= m[n] * scene_.gravity.dot(b.x[n]);
    }
    return e;
}

bool World::step() {
    refresh_if_due();
    kick(0.5 * dt_, false);
    drift();
    t_ += dt_;
    compute_forces();
    kick(0.5 * dt_, true);
    if (!inversion_.empty()) {
        failure_ = inversion_;
        return false;
    }
    if (!state_finite()) {
        failure_ = "the state is no longer finite (NaN or infinity)";
        return false;
    }
    // a penetration of a quarter of a block is no longer a contact: the blocks pass through
    // each other (kn too soft for the loads, or the step too large)
    if (last_contact_.worst_depth > kSankDepth) {
        const Block& h = blocks_[last_contact_.worst_hit];
        const Block& t = blocks_[last_contact_.worst_target];
        std::ostringstream m;
        m << "block " << h.name << " sank " << last_contact_.worst_depth * std::min(h.min_edge, t.min_edge)
          << " m into block " << t.name << ", more than a quarter of the smaller block's shortest edge ("
          << std::min(h.min_edge, t.min_edge) << " m): the contact stiffness kn is too soft for these loads, or "
          << "the time step too large";
        failure_ = m.str();
        return false;
    }
    return true;
}

// stage: refresh the contact candidates every n steps, or sooner if the margin could be crossed
void World::refresh_if_due() {
    ++steps_since_refresh_;
    const long count = long(blocks_.size());
    const double half = 0.5 * contacts_.margin();
    const bool turns = prune_ && scene_.contact.scheme == ContactScheme::overlap;
    bool early = false, turned = false;
    double fastest = 0.0;   // the largest move of a block in this step, m
    turned_.assign(blocks_.size(), 0);
#pragma omp parallel for schedule(static) reduction(|| : early, turned) reduction(max : fastest) if (count >= kParallelBlocks)
    for (long i = 0; i < count; ++i) {
        const Block& b = blocks_[size_t(i)];
        if (b.fixed) continue;
        // the check runs before this step's move: add a bound on it (speed × dt); the overlap
        // scheme also widens the candidates of a block before it turns by kRefreshTurn (the
        // refresh leaves out the sides that cannot face each other within that turn)
        const double spin = b.deformable ? 0.0 : b.body.omega().norm();   // rad/s
        double speed = 0.0;   // m/s, of the block's fastest point
        if (b.deformable)
            for (const auto& vn : b.v) speed = std::max(speed, vn.norm());
        else
            speed = b.body.v.norm() + b.r_max * spin;
        const double move = speed * dt_;
        fastest = std::max(fastest, move);
        const double turn = b.turn_since_refresh();   // rad
        // a bound on how far any point moved since the refresh, m
        const double moved = (b.body.x - b.x_at_refresh).norm() + b.r_max * turn;
        if (moved + move > half) early = true;
        if (turns && !contacts_.widened(size_t(i)) && turn + spin * dt_ > kRefreshTurn) turned = true, turned_[size_t(i)] = 1;
    }
    const bool due = steps_since_refresh_ >= scene_.run.contact_interval;
    if (early && !due) ++early_refreshes_;   // counted: a margin too small for the motion
    if (!(due || early)) {
        // a block about to turn past the pruning's bound: its pairs' left-out faces come back
        // until the next refresh (a whole refresh each step would cost more than the faces: one
        // tumbling brick in a wall refreshed all of its 300 bricks every 2 to 3 steps)
        if (turned) contacts_.widen(turned_);
        return;
    }
    // a block that moves more than half the scene's margin in one step would cross it before the
    // next check: the boxes grow by four of its steps' move until it slows down
    contacts_.set_margin(2.0 * fastest > margin_ ? 4.0 * fastest : margin_);
    contacts_.refresh(blocks_);
    steps_since_refresh_ = 0;
}

// stage: half-step velocity update from the current forces, mass damping α implicit
void World::kick(double h, bool end) {
    const double alpha = scene_.damping.alpha, damp = 1.0 / (1.0 + alpha * h);
    const long count = long(blocks_.size());
    // rigid blocks on every core, each loss kept per block; deformable blocks (parallel inside)
    // one after the other; the losses summed in block order (same bits on any thread count)
#pragma omp parallel for schedule(static) if (count >= kParallelBlocks)
    for (long i = 0; i < count; ++i) {
        Block& b = blocks_[size_t(i)];
        if (b.fixed || b.deformable) continue;
        const bool ev = end && event_[size_t(i)];
        loss_[size_t(i)] = dem::kick(b.body, ev ? force_end_[size_t(i)] : force_[size_t(i)],
                                     ev ? torque_end_[size_t(i)] : torque_[size_t(i)], h, alpha);
    }
    for (size_t i = 0; i < blocks_.size(); ++i) {
        Block& b = blocks_[i];
        if (b.fixed || !b.deformable) continue;
        const auto& a = end && event_[i] ? accel_end_[i] : accel_[i];
        for (size_t n = 0; n < b.v.size(); ++n) b.v[n] = (b.v[n] + h * a[n]) * damp;
        loss_[i] = alpha > 0.0 ? mass_damping_loss(*b.deformable, b.x, b.v, a, h, alpha) : 0.0;
    }
    for (size_t i = 0; i < blocks_.size(); ++i)
        if (!blocks_[i].fixed) energy_.dissipated += loss_[i];   // 0 when α = 0
}

// stage: move every free block over the step
void World::drift() {
    const long count = long(blocks_.size());
#pragma omp parallel for schedule(static) if (count >= kParallelBlocks)
    for (long i = 0; i < count; ++i) {
        Block& b = blocks_[size_t(i)];
        if (b.fixed) continue;
        if (b.deformable)
            for (size_t n = 0; n < b.x.size(); ++n) b.x[n] += dt_ * b.v[n];
        else
            dem::drift(b.body, dt_);
    }
}

// stage: nodes, then contact, gravity, loads and internal forces; rigid resultants or nodal
// accelerations
void World::compute_forces() {
    const long count = long(blocks_.size());
    // rigid nodes on every core; deformable blocks' poses one after the other (parallel inside)
#pragma omp parallel for schedule(static) if (count >= kParallelBlocks)
    for (long i = 0; i < count; ++i) {
        Block& b = blocks_[size_t(i)];
        if (b.deformable) continue;
        b.update_nodes();
        std::fill(b.f.begin(), b.f.end(), Vec3::Zero());
    }
    for (auto& b : blocks_) {
        if (!b.deformable) continue;
        b.update_nodes();
        std::fill(b.f.begin(), b.f.end(), Vec3::Zero());
    }
    ContactTotals ct = contacts_.apply(blocks_, dt_);
    last_contact_ = ct;
    energy_.contact = ct.stored;
    energy_.dissipated += ct.dissipated;
    active_ = ct.active;
    for (size_t i = 0; i < loads_.size(); ++i) {
        const auto& l = scene_.loads[i];
        Block& b = blocks_[loads_[i].block];
        // a body load (ground motion) acts at the centre of mass, spread like the mass
        Vec3 p = l.body ? b.body.x : world_position(b, loads_[i]);
        // settling: the loads acting at t = 0, ramped with gravity, their work not booked
        Vec3 f = settling_ ? gravity_scale_ * l.factor(0.0) * l.force : l.factor(t_) * l.force;
        if (!settling_) {
            // trapezoid rule for the work over the step
            energy_.external += 0.5 * (f + load_force_[i]).dot(p - load_point_[i]);
            load_point_[i] = p;
            load_force_[i] = f;
        }
        if (l.body && b.deformable) {
            const auto& m = b.deformable->lumped_mass();
            for (size_t n = 0; n < b.f.size(); ++n) b.f[n] += (m[n] / b.deformable->mass()) * f;
        } else {
            add_point_force(b, loads_[i], f);
        }
    }
    energy_.strain = 0.0;
    // rigid resultants on every core (each block's own sums: no shared total)
#pragma omp parallel for schedule(static) if (count >= kParallelBlocks)
    for (long i = 0; i < count; ++i) {
        Block& b = blocks_[size_t(i)];
        if (b.fixed || b.deformable) continue;
        force_[size_t(i)] = b.body.mass * gravity_scale_ * scene_.gravity;
        torque_[size_t(i)].setZero();
        for (size_t n = 0; n < b.x.size(); ++n) {
            force_[size_t(i)] += b.f[n];
            torque_[size_t(i)] += (b.x[n] - b.body.x).cross(b.f[n]);
        }
    }
    for (size_t i = 0; i < blocks_.size(); ++i) {
        Block& b = blocks_[i];
        if (b.fixed || !b.deformable) continue;
        {
            const auto& m = b.deformable->lumped_mass();
            for (size_t n = 0; n < b.x.size(); ++n) b.f[n] += m[n] * gravity_scale_ * scene_.gravity;
            energy_.strain += b.deformable->add_internal_forces(b.x, b.v, b.f);
            if (b.deformable->inverted_element() >= 0 && inversion_.empty()) inversion_ = inversion_message(i);
            energy_.dissipated += b.deformable->damping_power() * dt_;
            element_updates_ += (long long)b.deformable->element_count();
            b.deformable->accelerations(b.x, b.v, b.f, accel_[i]);
        }
    }
    add_events();
}

// stage: the end-of-step half kick's forces of the blocks touched by contact events (a point or
// sub-contact that entered or left contact inside the step, docs/dem.md, Energy): the step's
// forces plus the events' corrections, in the events' fixed order
void World::add_events() {
    const auto& events = contacts_.events();
    std::fill(event_.begin(), event_.end(), 0);
    for (const auto& e : events) {
        const size_t i = size_t(e.block);
        Block& b = blocks_[i];
        if (b.fixed) continue;
        if (!event_[i]) {
            event_[i] = 1;
            force_end_[i] = force_[i];
            torque_end_[i] = torque_[i];
            if (b.deformable) f_end_[i].assign(b.f.begin(), b.f.end());
        }
        if (b.deformable) {
            for (int k = 0; k < e.at.count; ++k) f_end_[i][size_t(e.at.node[size_t(k)])] += e.at.w[size_t(k)] * e.force;
            continue;
        }
        Vec3 p = Vec3::Zero();
        for (int k = 0; k < e.at.count; ++k) p += e.at.w[size_t(k)] * b.x[size_t(e.at.node[size_t(k)])];
        force_end_[i] += e.force;
        torque_end_[i] += (p - b.body.x).cross(e.force);
    }
    // deformable blocks: the accelerations under the node forces with the events
    for (size_t i = 0; i < blocks_.size(); ++i) {
        Block& b = blocks_[i];
        if (!event_[i] || !b.deformable) continue;
        accel_end_[i].resize(b.x.size());
        b.deformable->accelerations(b.x, b.v, f_end_[i], accel_end_[i]);
    }
}

std::string World::inversion_message(size_t i) const {
    const Block& b = blocks_[i];
    const int e = b.deformable->inverted_element();
    const auto& d = b.mesh.divisions;
    const double young = scene_.materials[size_t(scene_.blocks[i].material)].young;
    std::ostringstream m;
    m << "block " << b.name << ": element " << e << " (cell " << e % d[0] << ", " << (e / d[0]) % d[1] << ", "
      << e / (d[0] * d[1]) << " of its " << d[0] << "x" << d[1] << "x" << d[2] << " mesh) turned inside out at t = "
      << t_ << " s (det F = " << b.deformable->inverted_det()
      << " <= 0 at a Gauss point): the material is too soft for the loads (young = " << young
      << " Pa) or the time step too large";
    return m.str();
}

bool World::state_finite() const {
    for (const auto& b : blocks_) {
        if (!b.body.x.allFinite() || !b.body.v.allFinite() || !b.body.L.allFinite() ||
            !b.body.q.coeffs().allFinite())
            return false;
        if (b.deformable)
            for (size_t n = 0; n < b.x.size(); ++n)
                if (!b.x[n].allFinite() || !b.v[n].allFinite()) return false;
    }
    return std::isfinite(energy_.contact) && std::isfinite(energy_.strain);
}

}  // namespace cairn::dem

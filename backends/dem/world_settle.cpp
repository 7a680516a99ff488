// The settled start: the blocks brought to rest under gravity and the loads acting at t = 0,
// before t = 0 (docs/dem.md).
#include <algorithm>
#include <cmath>
#include <string>

#include "backend/settle.hpp"
#include "world.hpp"

namespace cairn::dem {

namespace {

double turn(const Quat& a, const Quat& b) { return 2.0 * std::acos(std::min(1.0, std::abs(a.dot(b)))); }

}  // namespace

void World::stop_blocks() {
    for (auto& b : blocks_) {
        if (b.fixed) continue;
        b.body.v.setZero();
        b.body.L.setZero();
        for (auto& v : b.v) v.setZero();
    }
}

double World::motion_energy() const {
    double e = 0.0;
    for (const auto& b : blocks_) {
        if (b.fixed) continue;
        if (!b.deformable) e += b.body.kinetic_energy();
        else e += b.deformable->kinetic_energy(b.x, b.v);
    }
    return e;
}

double World::unbalanced() const {
    const double g = scene_.gravity.norm();
    double worst = 0.0;
    for (size_t i = 0; i < blocks_.size(); ++i) {
        const Block& b = blocks_[i];
        if (b.fixed) continue;
        if (!b.deformable) {
            const double w = b.body.mass * g;
            worst = std::max({worst, force_[i].norm() / w, torque_[i].norm() / (w * b.r_max)});
            continue;
        }
        const auto& m = b.deformable->lumped_mass();
        const auto& fixed = b.deformable->fixed_nodes();
        for (size_t n = 0; n < b.f.size(); ++n)
            if (!fixed[n]) worst = std::max(worst, b.f[n].norm() / (m[n] * g));
    }
    return worst;
}

// the relaxation of one phase of settle(): steps `first` … `last` of the plan, kinetic damping,
// the unbalanced force judged at the ends of rounds; true once at rest (rep.why set on a mechanism)
bool World::relax(const settle::Schedule& plan, long first, long last, const std::vector<Block>& given,
                  SettleReport& rep) {
    double kinetic_last = 0.0;
    for (long k = first; k <= last; ++k) {
        gravity_scale_ = plan.gravity(k);
        rep.steps = k;
        if (!step()) {
            rep.why = "the settling failed: " + failure_;
            return false;
        }
        // kinetic damping: past a peak of the kinetic energy, every block stops
        const double kinetic_now = motion_energy();
        if (kinetic_now < kinetic_last) {
            stop_blocks();
            kinetic_last = 0.0;
        } else {
            kinetic_last = kinetic_now;
        }
        for (size_t i = 0; i < blocks_.size(); ++i) {
            const Block& b = blocks_[i];
            if (b.fixed) continue;
            const double move = (b.body.x - given[i].body.x).norm();
            if (move > rep.largest_move) rep.largest_move = move, rep.block = b.name;
            rep.why = settle::not_at_rest(b.name, move, turn(b.body.q, given[i].body.q), b.min_edge);
            if (!rep.why.empty()) return false;
        }
        if (plan.judged(k) && unbalanced() < settle::kResidual) return true;
    }
    return false;
}

SettleReport World::settle(double dt) {
    SettleReport rep;
    dt_ = dt;
    const double g = scene_.gravity.norm();
    if (!(g > 0.0)) {
        rep.why = "no gravity: nothing to settle";
        return rep;
    }
    // the slowest bounce of a free block on its softest side's springs sets the time scales
    double period = 0.0;
    for (const auto& b : blocks_) {
        if (b.fixed) continue;
        const double area = *std::min_element(b.side_area.begin(), b.side_area.end());
        period = std::max(period, settle::bounce_period(b.body.mass, scene_.contact.kn, area));
    }
    const settle::Schedule plan(period, dt, scene_.run.duration);

    const std::vector<Block> given = blocks_;
    const ContactSet given_contacts = contacts_;
    stop_blocks();
    // phase 1: the springs' elastic static state, no shear spring slipping (path independent)
    contacts_.allow_slip(false);
    settling_ = true;
    gravity_scale_ = 0.0;
    compute_forces();
    bool rest = relax(plan, 1, plan.cap, given, rep);
    if (rest) {
        // phase 2: the cap back on, the springs above μ·N slip to it while the blocks relax on; a
        // block the loads at t = 0 push past friction slides on (it moves): it starts from phase 1
        const std::vector<Block> elastic = blocks_;
        const ContactSet elastic_contacts = contacts_;
        rep.residual = unbalanced();
        const SettleReport before = rep;
        contacts_.allow_slip(true);
        stop_blocks();
        compute_forces();
        const long first = rep.steps + 1;
        if (relax(plan, first, std::min(plan.cap, first + settle::kSlipRounds * plan.round - 1), given, rep)) {
            rep.slip_steps = rep.steps - first + 1;
            rep.residual = unbalanced();
        } else {
            blocks_ = elastic;
            contacts_ = elastic_contacts;
            rep = before;
            rep.slip_refused = true;
        }
    } else {
        rep.residual = unbalanced();
    }
    if (rep.why.empty() && !(rep.residual < settle::kResidual))
        rep.why = "not at rest after " + std::to_string(rep.steps) + " steps (unbalanced force " +
                  std::to_string(rep.residual) + " of a block's weight)";
    settling_ = false;
    gravity_scale_ = 1.0;
    contacts_.allow_slip(true);
    rep.settled = rep.why.empty();
    if (!rep.settled) {
        blocks_ = given;
        contacts_ = given_contacts;
    } else {
        // the scene's initial velocities on the settled blocks
        for (size_t i = 0; i < blocks_.size(); ++i) {
            Block& b = blocks_[i];
            if (b.fixed) continue;
            b.body.v = given[i].body.v;
            b.body.set_omega(given[i].body.omega());
            b.v = given[i].v;
        }
        contacts_.set_margin(margin_);
        contacts_.refresh(blocks_);
    }
    energy_ = EnergyAccounts{};
    t_ = 0.0;
    steps_since_refresh_ = 0;
    early_refreshes_ = 0;
    element_updates_ = 0;
    failure_.clear();
    inversion_.clear();
    for (size_t i = 0; i < loads_.size(); ++i) {
        const Block& b = blocks_[loads_[i].block];
        load_point_[i] = scene_.loads[i].body ? b.body.x : world_position(b, loads_[i]);
    }
    return rep;
}

}  // namespace cairn::dem

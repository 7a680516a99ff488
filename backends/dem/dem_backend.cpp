#include "dem_backend.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "error.hpp"
#include "time_step.hpp"
#include "geometry/hexahedron.hpp"
#include "deformable/deformable_body.hpp"
#include "mesh.hpp"
#include "sudden_loads.hpp"
#include "world.hpp"

namespace cairn {

namespace {

/// "block A", "blocks A, B, C", or for more than six "40 blocks (A, B, C, … Z)"
std::string block_list_note(const std::vector<std::string>& names) {
    constexpr size_t kListed = 6;
    if (names.size() == 1) return "block " + names[0];
    std::string s;
    if (names.size() <= kListed) {
        for (const auto& name : names) s += (s.empty() ? "" : ", ") + name;
        return "blocks " + s;
    }
    for (size_t i = 0; i + 1 < kListed; ++i) s += names[i] + ", ";
    return std::to_string(names.size()) + " blocks (" + s + "… " + names.back() + ")";
}

/// true when something can set a block sliding: a load (ground motion included) or a block
/// thrown or spun at t = 0
bool may_slide(const Scene& scene) {
    if (!scene.loads.empty()) return true;
    for (const BlockDef& b : scene.blocks)
        if (!b.fixed && (b.velocity.squaredNorm() > 0.0 || b.angular_velocity.squaredNorm() > 0.0)) return true;
    return false;
}

/// the scene with its blocks in an order set by their geometry (their centres at t = 0, by z, then
/// y, then x; the scene's order only between blocks centred at one point), the block indices of
/// loads, probes and the reference renumbered; `to_scene[k]` is the scene index of block k,
/// `from_scene[i]` the index of the scene's block i. The
/// engine sums forces and contacts in block order, so the scene's order (its blocks' names) would
/// otherwise set the last bits of every sum, which rocking impacts grow into millimetres
Scene canonical_order(const Scene& scene, std::vector<int>& to_scene, std::vector<int>& from_scene) {
    const size_t n = scene.blocks.size();
    std::vector<Vec3> centre(n);
    for (size_t i = 0; i < n; ++i) {
        const BlockDef& b = scene.blocks[i];
        centre[i] = b.position + b.orientation * mass_properties(b.corners, 1.0).centre;
    }
    to_scene.resize(n);
    for (size_t i = 0; i < n; ++i) to_scene[i] = int(i);
    std::stable_sort(to_scene.begin(), to_scene.end(), [&](int a, int b) {
        const Vec3 &p = centre[size_t(a)], &q = centre[size_t(b)];
        if (p.z() != q.z()) return p.z() < q.z();
        if (p.y() != q.y()) return p.y() < q.y();
        return p.x() < q.x();
    });
    from_scene.assign(n, 0);
    for (size_t k = 0; k < n; ++k) from_scene[size_t(to_scene[k])] = int(k);
    Scene out = scene;
    for (size_t k = 0; k < n; ++k) out.blocks[k] = scene.blocks[size_t(to_scene[k])];
    for (auto& l : out.loads) l.block = from_scene[size_t(l.block)];
    for (auto& p : out.probes) p.block = from_scene[size_t(p.block)];
    if (out.reference) out.reference->block = from_scene[size_t(out.reference->block)];
    return out;
}

class DemBackend : public Backend {
public:
    std::string name() const override { return "dem"; }
    std::string engine_version() const override { return std::string("cairn dem ") + CAIRN_VERSION; }

    void build(const Scene& scene, const RunOptions& options) override {
        scene_ = scene;
        for (const auto& [key, s] : scene_.backend_settings["dem"])
            throw Error(s.origin + ": backends.dem." + key + ": unknown setting of backend dem (it has none)");
        dem::check_build_size(scene_, options.limits);
        double min_edge = 1e300;
        for (const auto& def : scene_.blocks) min_edge = std::min(min_edge, shortest_edge(def.corners));
        margin_ = scene_.run.contact_margin ? *scene_.run.contact_margin : 0.05 * min_edge;
        world_.reset();
        ordered_ = canonical_order(scene_, to_scene_, from_scene_);
        world_ = std::make_unique<dem::World>(ordered_, margin_);
        world_->record_contacts(options.record_contacts);
        contact_critical_ = dem::contact_critical_step(world_->blocks(), scene_.contact, margin_);
        element_critical_ = dem::element_critical_step(world_->blocks());
        critical_ = contact_critical_;
        if (element_critical_ > 0.0 && (critical_ == 0.0 || element_critical_ < critical_)) critical_ = element_critical_;
        if (scene_.run.dt) {
            dt_ = *scene_.run.dt;
        } else {
            double dt_c = scene_.run.dt_safety * contact_critical_;
            double dt_e = scene_.run.element_dt_safety * element_critical_;
            dt_ = dt_c > 0.0 && (dt_e == 0.0 || dt_c < dt_e) ? dt_c : dt_e;
            if (!(dt_ > 0.0))
                throw Error(scene_.source + ": run.dt = \"auto\": no positive critical step to derive a step from "
                            "(contact.kn = " + message_number(scene_.contact.kn) + " gives " +
                            message_number(contact_critical_) + " s, the elements " + message_number(element_critical_) +
                            " s); give run.dt, or a stiffness whose critical step is not 0");
        }
        if (scene_.run.settle) settle_ = world_->settle(dt_);
        world_->start(dt_);
    }

    double time_step() const override { return dt_; }
    double critical_step() const override { return critical_; }

    StepStatus step() override {
        if (world_->step()) return StepStatus::ok;
        failure_ = world_->failure();
        return StepStatus::unstable;
    }

    Sample sample() const override {
        Sample s;
        s.t = world_->time();
        const auto& blocks = world_->blocks();
        for (size_t i = 0; i < scene_.probes.size(); ++i) s.probes.push_back(world_->probe(int(i)));
        for (size_t i = 0; i < scene_.blocks.size(); ++i) {
            const auto& b = blocks[size_t(from_scene_[i])];   // in the scene's order
            if (b.fixed) continue;
            BlockState st;
            st.position = b.body.x;
            st.orientation = b.body.q;
            if (b.deformable) {
                b.deformable->motion(b.x, b.v, st.velocity, st.angular_velocity);
            } else {
                st.velocity = b.body.v;
                st.angular_velocity = b.body.omega();
            }
            s.blocks.push_back(st);
        }
        s.energy.kinetic = world_->kinetic();
        s.energy.potential = world_->potential();
        s.energy.contact = world_->energy().contact;
        s.energy.strain = world_->energy().strain;
        s.energy.dissipated = world_->energy().dissipated;
        s.energy.external = world_->energy().external;
        s.contacts = world_->active_contacts();
        return s;
    }

    std::string failure() const override { return failure_; }

    std::vector<ContactPoint> contact_points() const override {
        auto points = world_->contact_points();
        for (auto& p : points) {
            if (p.block_a >= 0) p.block_a = to_scene_[size_t(p.block_a)];
            if (p.block_b >= 0) p.block_b = to_scene_[size_t(p.block_b)];
        }
        return points;
    }

    BlockMesh block_mesh(int block) const override {
        BlockMesh m;
        const auto& b = world_->blocks()[size_t(from_scene_.at(size_t(block)))];
        if (!b.deformable) return m;
        m.nodes = b.x;
        m.velocities = b.v;
        m.elements = b.mesh.elements;
        return m;
    }

    std::vector<std::string> notes() const override {
        std::vector<std::string> n;
        auto num = [](double v) {
            std::ostringstream o;
            o.precision(6);
            o << v;
            return o.str();
        };
        n.push_back("integrator: central differences (kick-drift-kick); rigid blocks rotate by implicit midpoint");
        // the free blocks' models, blocks of one model in one note (a generated wall of 10⁴ bricks
        // gets one line, not 10⁴), in the order each model first appears
        std::vector<std::pair<std::string, std::vector<std::string>>> models;
        for (const auto& b : scene_.blocks) {
            if (b.fixed) continue;
            std::string m = to_string(b.model);
            if (b.model == BlockModel::deformable)
                m += ", " + std::to_string(b.mesh.divisions[0]) + "x" + std::to_string(b.mesh.divisions[1]) + "x" +
                     std::to_string(b.mesh.divisions[2]) + " hex8 (St. Venant-Kirchhoff, 2x2x2 Gauss), mass " +
                     to_string(b.mesh.mass);
            auto it = std::find_if(models.begin(), models.end(), [&](const auto& e) { return e.first == m; });
            if (it == models.end()) models.push_back({m, {b.name}});
            else it->second.push_back(b.name);
        }
        for (const auto& [model, names] : models) n.push_back(block_list_note(names) + ": " + model);
        n.push_back("critical step of the contact springs (s): " + num(contact_critical_));
        if (element_critical_ > 0.0) n.push_back("critical step of the elements (s): " + num(element_critical_));
        n.push_back("time step (s): " + num(dt_) + (scene_.run.dt ? " (given)" : " (auto)"));
        if (critical_ > 0.0 && dt_ > critical_)
            n.push_back("warning: the time step exceeds the critical step estimate; the run may blow up");
        n.push_back("broad-phase margin (m): " + num(margin_));
        n.push_back("contact refresh interval (steps): " + std::to_string(scene_.run.contact_interval));
        if (!scene_.run.settle)
            n.push_back("start: as given (run.settle = false)");
        else if (settle_.settled)
            n.push_back("start: settled under gravity and the loads at t = 0 in " + std::to_string(settle_.steps) +
                        " steps (" +
                        (settle_.slip_refused ? std::string("elastic: with friction on, the loads at t = 0 moved a block")
                                              : std::to_string(settle_.slip_steps) + " of them with friction slipping") +
                        "; largest move " + num(settle_.largest_move) + " m, block " + settle_.block +
                        "; unbalanced force " + num(settle_.residual) + " of a block's weight)");
        else
            n.push_back("start: as given, not settled (" + settle_.why + ")");
        if (world_ && world_->early_refreshes() > 0)
            // not a warning: the early refresh keeps every pair (the results do not change), it
            // only costs a refresh; the note says how to save them
            n.push_back("contact pairs refreshed early (steps): " + std::to_string(world_->early_refreshes()) +
                        " (a block moved more than half the margin within the interval; the pairs are "
                        "kept, each costs a refresh: a larger run.contact_margin or smaller "
                        "run.contact_interval saves them)");
        n.push_back(std::string("contact damping: ") + to_string(scene_.contact.damping_rule) + " " +
                    num(scene_.contact.damping));
        const bool undamped = scene_.contact.damping_rule == ContactDampingRule::none || !(scene_.contact.damping > 0.0);
        // the contact springs' period 2π/ω is π times their critical step 2/ω
        if (const auto sudden = undamped ? dem::first_sudden_load(scene_, M_PI * contact_critical_) : std::nullopt) {
            const LoadDef& l = scene_.loads.at(size_t(sudden->load));
            n.push_back("warning: undamped contact, and a load on block " + scene_.blocks.at(size_t(l.block)).name +
                        (l.body ? " (ground motion)" : "") + " changes faster than the contact springs' period (" +
                        num(M_PI * contact_critical_) + " s) at t = " + num(sudden->time) +
                        " s: the springs ring without end after it, and the ringing can ratchet a block along "
                        "below friction; contact.damping_ratio = 0.05 lets it die out (docs/dem.md, Holding under loads)");
        }
        if (undamped && scene_.contact.friction > 0.0 && may_slide(scene_))
            n.push_back("warning: undamped contact: elastic-Coulomb joints can flutter while blocks slide on one another "
                        "or twist on a face, and the blocks then hop by millimetres whatever the time step "
                        "(docs/dem.md, Flutter of undamped sliding contact); contact.damping_ratio = 0.01 kept a pushed "
                        "row of blocks down, a block spinning on its base needs 0.6");
        return n;
    }

private:
    Scene scene_;                 ///< as given
    Scene ordered_;               ///< its blocks in canonical_order, as the world holds them
    std::vector<int> to_scene_;   ///< scene index of the world's block k
    std::vector<int> from_scene_; ///< world index of the scene's block i
    std::unique_ptr<dem::World> world_;
    dem::SettleReport settle_;
    double dt_ = 0.0, critical_ = 0.0, contact_critical_ = 0.0, element_critical_ = 0.0, margin_ = 0.0;
    std::string failure_;
};

}  // namespace

namespace {

/// the rotational inertia of block b's mesh as a deformable body assembles it (its mass scheme)
Mat3 assembled_inertia(const Scene& scene, int b) {
    const BlockDef& d = scene.blocks.at(size_t(b));
    const dem::Mesh mesh = dem::make_mesh(d.corners, d.mesh.divisions);
    const std::vector<char> fixed(mesh.nodes.size(), 0);
    // on the heap, as the engine builds it (aligned members)
    const auto body = std::make_shared<dem::DeformableBody>(mesh, scene.materials.at(size_t(d.material)),
                                                            d.mesh.mass, 0.0, fixed);
    return body->inertia();
}

}  // namespace

BackendInfo dem_backend_info() {
    BackendInfo info;
    info.name = "dem";
    info.description = "in-house discrete element engine (the paper's contact law), rigid or deformable hex8 blocks";
    info.capabilities = {
        {Feature::penalty_stiffness, Support::exact, "kn integrated over each face's overlap (scheme overlap, the default), or kn·a per hitting point (scheme paper: corners + virtual grid)"},
        {Feature::normal_damping, Support::exact, "dashpot per sub-contact or hitting point (ratio ζ or time γ)"},
        {Feature::elastic_stick, Support::exact, "shear spring from a stored stick anchor per sub-contact or hitting point"},
        {Feature::friction_shape, Support::exact, "Coulomb disc per sub-contact or hitting point"},
        {Feature::twist_friction, Support::approximate,
         "each sub-contact's friction at its sub-cell's centre plus its own torsion spring (a disc of its area): a "
         "square face under uniform weight holds a twist with 0.993 (subdivision 4), 0.997 (8), 0.984 (1) of the "
         "mu·W·a·0.383 of friction spread over it; "
         "scheme paper: 1.05 (grid 0.1 m on a 0.4 m face), 1.02 (0.05 m)"},
        {Feature::mass_damping, Support::exact, "α·M, implicit in the kick"},
        {Feature::stiffness_damping, Support::exact, "deformable blocks: strain-rate (Kelvin-Voigt) β·C:Ė; rigid blocks have none"},
        {Feature::deformable_blocks, Support::exact, "hex8 St. Venant-Kirchhoff, total Lagrangian; lumped, consistent, barycentre or corrected mass"},
        {Feature::general_hexahedra, Support::exact, "planar-faced convex hexahedra"},
        {Feature::held_at_rest, Support::exact,
         "penalty springs and stick anchors reach a static state and keep it (settled start): a 31-voussoir arch, "
         "R = 6 m, t/R = 0.15, kn 1e10, moves its crown by 2e-8 m in 1.5 s"},
    };
    info.contact = ContactModel::penalty;
    info.solver = "penalty springs per hitting point (corners and a virtual grid), elastic-Coulomb shear";
    info.make = [] { return std::make_unique<DemBackend>(); };
    info.block_inertia = assembled_inertia;
    return info;
}

}  // namespace cairn

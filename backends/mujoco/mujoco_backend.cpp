#include "mujoco/mujoco_backend.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "applied_loads.hpp"
#include "backend/settle.hpp"
#include "engine_settings.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "mujoco_collision.hpp"
#include "mujoco_model.hpp"
#include "rigid_blocks.hpp"

namespace cairn {

std::vector<FeatureSupport> mujoco_capabilities();

namespace {

// MuJoCo reports fatal errors through mju_user_error (default: exit); we jump back instead
thread_local std::jmp_buf* g_error_jump = nullptr;
thread_local std::string g_error_text;
void on_error(const char* msg) {
    g_error_text = msg;
    if (g_error_jump) std::longjmp(*g_error_jump, 1);
}
void on_warning(const char* msg) { g_error_text = msg; }

// matched mode: constant impedance d of the normal rows. MuJoCo's soft constraint adds to the
// spring a share of the rigid constraint force that grows with d; with the static penetration
// calibrated exactly, that share lengthens the period by about 2d/(1-d) for four contacts on a
// face (docs/backends.md), so d is kept small: 1e-3 gives +0.2 %
constexpr double kMatchedImpedance = 1e-3;
// impedance of rigid contacts and of matched-mode friction rows
constexpr double kFrictionImpedance = 0.99;
// friction rows' impratio over that impedance: a held block creeps at v = (1-d)·τ·a/(2·impratio),
// a velocity that does not shrink with the block (a 4 cm column crept 0.9 mm at impratio 1)
constexpr double kFrictionImpratio = 100.0;

// rows MuJoCo 2.2.2 could allocate here (its constraint arrays grow with njmax², docs/engines.md)
constexpr int kMaxRows = 10000;

class MujocoBackend : public Backend {
public:
    ~MujocoBackend() override { clear(); }
    std::string name() const override { return "mujoco"; }
    std::string engine_version() const override { return std::string("MuJoCo ") + mj_versionString(); }
    void build(const Scene& scene, const RunOptions& options) override;
    double time_step() const override { return dt_; }
    double critical_step() const override { return 0.0; }
    StepStatus step() override;
    Sample sample() const override;
    std::string failure() const override { return failure_; }
    std::vector<std::string> notes() const override { return notes_; }
    std::vector<ContactPoint> contact_points() const override;

private:
    void clear() {
        if (d_) mj_deleteData(d_);
        if (m_) mj_deleteModel(m_);
        d_ = nullptr;
        m_ = nullptr;
    }
    Quat orientation(int body) const {
        const mjtNum* q = d_->xquat + 4 * body;
        return Quat(q[0], q[1], q[2], q[3]);
    }
    Vec3 com(int body) const {
        const mjtNum* p = d_->xipos + 3 * body;
        return {p[0], p[1], p[2]};
    }
    Vec3 point(int block, const Vec3& p) const {
        const RigidBlock& b = blocks_[block];
        if (b.fixed) return block_point_world(b, b.com_world, b.orientation, p);
        return block_point_world(b, com(body_[block]), orientation(body_[block]), p);
    }
    Vec3 point_velocity(int block, const Vec3& world_point) const;
    void matched_step();
    /// matched contact, run.settle: the blocks brought to rest on their springs under gravity and
    /// the loads acting at t = 0 before t = 0 as dem does (docs/dem.md, "Settled start": gravity
    /// and those loads ramped, MuJoCo's friction on throughout, kinetic damping,
    /// rounds of a fixed count of steps); the fresh data restored if a block moves as a mechanism
    /// or does not come to rest. Leaves every velocity 0 and notes which start was taken
    void settle_matched();
    /// the loads × scale at their material points, as MuJoCo's applied body forces (N, N·m)
    void apply_loads(const std::vector<AppliedLoad>& loads, double scale);
    void calibrate_contacts();
    PointSpring pair_spring(const mjContact& c) const;
    double depth_scale(const mjContact& c) const;

    Scene scene_;
    std::vector<RigidBlock> blocks_;
    std::vector<int> body_;          // MuJoCo body id per block (0 for fixed blocks)
    std::vector<int> geom_block_;    // block index per MuJoCo geom id
    MujocoHexahedra hexahedra_;      // the same for the hexahedron collider
    double impedance_ = 0.0;         // solimp d of every contact
    double friction_damping_ = 0.0;  // matched mode: B of the friction rows, 1/s
    mjModel* m_ = nullptr;
    mjData* d_ = nullptr;
    bool matched_ = false;
    double dt_ = 0.0;
    bool stiff_step_ = false;   // dt = auto shortened below the default for the matched springs
    double external_work_ = 0.0;
    std::string failure_;
    std::vector<std::string> notes_;
};

Vec3 MujocoBackend::point_velocity(int block, const Vec3& p) const {
    int body = body_[block];
    if (body == 0) return Vec3::Zero();
    const mjtNum* qv = d_->qvel + m_->jnt_dofadr[m_->body_jntadr[body]];
    Vec3 w = orientation(body) * Vec3(qv[3], qv[4], qv[5]);   // free joint: local angular velocity
    return Vec3(qv[0], qv[1], qv[2]) + w.cross(p - com(body));
}

void MujocoBackend::build(const Scene& scene, const RunOptions& options) {
    clear();
    scene_ = scene;
    notes_.clear();
    failure_.clear();
    external_work_ = 0.0;
    EngineSettings settings(scene_, "mujoco");
    matched_ = contact_mode(settings, options) == "matched";
    MujocoParameters p;
    p.cone = settings.word("cone", "elliptic", {"pyramidal", "elliptic"});
    // Newton converges in a few iterations; CG steps a 39-brick wall 1.6 to 2.8 times faster with
    // rocking amplitudes within 0.3 % of Newton's (docs/backends.md, "MuJoCo's solver")
    p.solver = settings.word("solver", "Newton", {"Newton", "CG", "PGS"});
    p.iterations = static_cast<int>(settings.integer("iterations", 100, 1));
    p.tolerance = settings.number("tolerance", 1e-10, 0.0);
    p.noslip_iterations = static_cast<int>(settings.integer("noslip_iterations", 0, 0));
    p.impedance = settings.number("impedance", matched_ ? kMatchedImpedance : kFrictionImpedance, 1e-4);
    p.solref[0] = settings.number("timeconst", 0.002, 0.0);
    p.solref[1] = settings.number("dampratio", 1.0, 0.0);
    // impratio is MuJoCo's for elliptic cones (a pyramid's rows mix normal and friction)
    const double friction_impratio = settings.number("impratio", p.cone == "elliptic" ? kFrictionImpratio : 1.0, 1.0);
    settings.finish();
    if (p.impedance > 0.9999) throw Error("mujoco setting 'impedance' must be at most 0.9999");
    blocks_ = rigid_blocks(scene_, "mujoco");
    dt_ = engine_time_step(scene_);
    // matched springs stiffer than the default step resolves (ω·dt above 1: small blocks, a stiff
    // kn) blow MuJoCo's semi-implicit step up; dt = auto then takes 1/ω
    const double omega = matched_ ? matched_spring_omega(scene_, blocks_) : 0.0;
    stiff_step_ = !scene_.run.dt && omega * dt_ > 1.0;
    if (stiff_step_) dt_ = 1.0 / omega;
    p.dt = dt_;

    // constraint storage: 4 contacts per touching pair (candidates from inflated bounds), and
    // 4 rows per contact (pyramid) or 3 (elliptic)
    std::vector<Aabb> bounds;
    for (const RigidBlock& b : blocks_) {
        Aabb box;
        for (const Vec3& c : b.corners) box.add(b.com_world + b.orientation * (c - b.com));
        box.inflate(0.01);
        bounds.push_back(box);
    }
    int pairs = 0;
    for (size_t i = 0; i < blocks_.size(); ++i)
        for (size_t j = i + 1; j < blocks_.size(); ++j)
            if (!(blocks_[i].fixed && blocks_[j].fixed) && bounds[i].overlaps(bounds[j])) ++pairs;
    p.nconmax = std::max(100, 8 * pairs);
    p.njmax = std::max(500, p.nconmax * (p.cone == "pyramidal" ? 4 : 3));
    if (p.njmax > kMaxRows) {
        std::ostringstream e;
        e << "backend mujoco: " << blocks_.size() << " blocks with " << pairs << " touching pairs need about "
          << p.njmax << " constraint rows; MuJoCo 2.2.2 cannot allocate more than about " << kMaxRows
          << " (its constraint storage grows with the square of njmax): use the bullet or ode backend";
        throw Error(e.str());
    }

    if (matched_ && p.cone != "elliptic")
        throw Error("mujoco: the matched contact mode is calibrated for cone = \"elliptic\" only "
                    "(a pyramid's edges share the normal force in a way that depends on mu)");
    if (matched_) {
        // friction rows keep the rigid mode's impedance: R_friction = R_normal / impratio
        const double d = p.impedance, df = kFrictionImpedance;
        p.impratio = ((1.0 - d) / d) / ((1.0 - df) / df) * friction_impratio;
    } else {
        p.impratio = friction_impratio;
    }
    impedance_ = p.impedance;
    friction_damping_ = 2.0 / (kFrictionImpedance * std::max(p.solref[0], 2.0 * p.dt));

    std::string xml = mujoco_xml(scene_, blocks_, p);
    mjVFS vfs;
    mj_defaultVFS(&vfs);
    mj_makeEmptyFileVFS(&vfs, "cairn.xml", static_cast<int>(xml.size()));
    std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "cairn.xml")], xml.data(), xml.size());
    char error[1000] = "";
    mju_user_error = on_error;
    mju_user_warning = on_warning;
    std::jmp_buf jump;
    g_error_jump = &jump;
    if (setjmp(jump) != 0) {
        g_error_jump = nullptr;
        mj_deleteVFS(&vfs);
        throw Error("backend mujoco: " + g_error_text + " (scene with " + std::to_string(blocks_.size()) + " blocks)");
    }
    m_ = mj_loadXML("cairn.xml", &vfs, error, sizeof(error));
    mj_deleteVFS(&vfs);
    if (!m_) {
        g_error_jump = nullptr;
        throw Error(std::string("backend mujoco: the generated model does not load: ") + error);
    }
    d_ = mj_makeData(m_);
    g_error_jump = nullptr;
    if (!d_) throw Error("backend mujoco: could not allocate the simulation data");

    geom_block_.assign(m_->ngeom, -1);
    for (const RigidBlock& b : blocks_) {
        int g = mj_name2id(m_, mjOBJ_GEOM, ("g" + std::to_string(b.index)).c_str());
        if (g >= 0) geom_block_[g] = b.index;
    }
    install_hexahedron_collider();
    hexahedra_.model = m_;
    // box-box pairs go through cairn's collider in both modes: MuJoCo 2.2.2's box-box collider
    // gives phantom deep points for equal boxes face on face, which launched a brick of a wall at
    // rest in rigid mode
    hexahedra_.box_depth_scale = matched_ ? 1.0 : 0.5;
    hexahedra_.geom_block.assign(m_->ngeom, nullptr);
    for (int g = 0; g < m_->ngeom; ++g)
        if (geom_block_[g] >= 0) hexahedra_.geom_block[g] = &blocks_[geom_block_[g]];
    CurrentHexahedra current(&hexahedra_);
    body_.assign(blocks_.size(), 0);
    int next = 1;
    for (const RigidBlock& b : blocks_)
        if (!b.fixed) body_[b.index] = next++;
    // matched contact is penalty springs: blocks placed at rest start on them settled, as on dem
    if (matched_ && scene_.run.settle) settle_matched();
    for (const RigidBlock& b : blocks_) {
        if (b.fixed) continue;
        next = body_[b.index];
        mjtNum* qv = d_->qvel + m_->jnt_dofadr[m_->body_jntadr[next]];
        const BlockDef& def = scene_.blocks[b.index];
        Vec3 w_local = b.orientation.conjugate() * def.angular_velocity;
        for (int k = 0; k < 3; ++k) {
            qv[k] = def.velocity[k];
            qv[3 + k] = w_local[k];
        }
    }
    mj_forward(m_, d_);

    std::ostringstream n;
    auto note = [&](std::ostringstream& s) { notes_.push_back(s.str()); s.str(""); };
    n << "contact_mode: " << (matched_ ? "matched" : "rigid");
    note(n);
    n << "time_step: " << dt_ << " s"
      << (scene_.run.dt ? ""
          : stiff_step_ ? " (dt = auto: 1/omega of the stiffest matched spring, below the engine default 1e-4 s)"
                        : " (dt = auto: engine default 1e-4 s)");
    note(n);
    n << "solver: " << p.solver << ", " << p.iterations << " iterations, tolerance " << p.tolerance
      << ", Euler integrator, "
      << p.cone << " friction cone, margin 0, njmax " << p.njmax << ", nconmax " << p.nconmax;
    note(n);
    if (matched_)
        n << "matched contact: direct solref (-k, -b) set on every contact after collision from its pair: "
             "kn*A/4 and c/4 per contact (A = smaller area of the two faces most aligned with the contact "
             "normal, c from the pair's reduced mass) times MuJoCo's (1-d)*invweight of the two bodies, "
             "impedance d " << p.impedance
          << " (static penetration exact, period of kn*A long by about " << 2.0 * p.impedance / (1.0 - p.impedance) * 100
          << " %); friction rows impedance " << kFrictionImpedance << ", stiffened by " << friction_impratio
          << " (impratio " << p.impratio << ") and damping " << friction_damping_ << " 1/s";
    else
        n << "rigid contact: solref " << p.solref[0] << " " << p.solref[1] << ", solimp " << p.impedance << " "
          << p.impedance << " 0.001, impratio " << p.impratio;
    note(n);
    n << "collision: every pair of blocks, box-box included, through cairn's face-clipping collider (MuJoCo "
         "2.2.2's box-box collider gives duplicate and phantom deep points for equal boxes face on face)";
    note(n);
    n << "friction: mu " << scene_.contact.friction << ", " << p.cone
      << " cone; soft constraint: a block held by friction creeps at (1-d)*timeconst*a/(2*k) for a shear "
         "acceleration a (friction rows' impedance d " << kFrictionImpedance << ", stiffened by k = " << friction_impratio
      << "); no elastic stick before slip"
      << "; a sliding block rises off its base (MuJoCo's convex model: slip comes with normal motion), by more "
         "the faster it slides"
      << (matched_ ? ": the elliptic cone's middle zone pushes the contact apart, which on undamped springs "
                     "grows into hops (a cube thrown at 1 m/s slid 8-13 % too far, one at 4 m/s rose 60 mm)"
                   : " (a cube thrown at 1 m/s rose 0.7 mm, at 4 m/s 6.5 mm); a block riding on a sliding "
                     "block can slip when they hop (docs/backends.md, \"A block riding on a pushed block\")");
    note(n);
    if (scene_.contact.restitution > 0) {
        n << "restitution: ignored (MuJoCo has no restitution coefficient; solref sets the bounce)";
        note(n);
    }
    if (scene_.damping.alpha > 0) {
        n << "mass-proportional damping: velocities scaled by exp(-alpha*dt) after each step";
        note(n);
    }
    for (const auto& line : rigid_engine_notes(scene_)) notes_.push_back(line);
    for (const RigidBlock& b : blocks_)
        if (!b.is_box) {
            n << "general hexahedra: mesh geoms; box-mesh and mesh-mesh pairs collide through cairn's "
                 "face-clipping collider (up to 4 points; MuJoCo 2.2.2's mesh collider gives one)";
            note(n);
            break;
        }
}

void MujocoBackend::settle_matched() {
    using namespace settle;   // dem's schedule and verdicts
    const Vec3 g0(m_->opt.gravity[0], m_->opt.gravity[1], m_->opt.gravity[2]);
    const double g = g0.norm();
    if (!(g > 0.0)) return;
    double period = 0.0;
    std::vector<double> min_edge(blocks_.size(), 0.0), r_max(blocks_.size(), 0.0);
    for (const RigidBlock& b : blocks_) {
        if (b.fixed) continue;
        const double area = *std::min_element(b.face_areas.begin(), b.face_areas.end());
        period = std::max(period, bounce_period(b.mass, scene_.contact.kn, area));
        min_edge[b.index] = shortest_edge(b.corners);
        for (const Vec3& c : b.corners) r_max[b.index] = std::max(r_max[b.index], (c - b.com).norm());
    }
    const Schedule plan(period, dt_, scene_.run.duration);
    const std::vector<mjtNum> qpos0(d_->qpos, d_->qpos + m_->nq);
    std::string why;
    bool rest = false;
    long steps = 0;
    double kinetic_last = 0.0, residual = 0.0;
    // the loads acting at t = 0 settle with gravity, ramped as it is
    std::vector<AppliedLoad> loads;
    applied_loads(scene_, 0.0, loads);
    for (long k = 1; k <= plan.cap && why.empty() && !rest; ++k) {
        for (int i = 0; i < 3; ++i) m_->opt.gravity[i] = plan.gravity(k) * g0[i];
        apply_loads(loads, plan.gravity(k));
        matched_step();
        mj_kinematics(m_, d_);
        steps = k;
        if (d_->warning[mjWARN_BADQACC].number > 0 || d_->warning[mjWARN_BADQPOS].number > 0 ||
            d_->warning[mjWARN_BADQVEL].number > 0 || d_->warning[mjWARN_CNSTRFULL].number > 0 ||
            d_->warning[mjWARN_CONTACTFULL].number > 0) {
            why = "the settling failed (MuJoCo warning)";
            break;
        }
        double kinetic = 0.0;
        residual = 0.0;
        for (const RigidBlock& b : blocks_) {
            if (b.fixed) continue;
            const int body = body_[b.index];
            const mjtNum* qv = d_->qvel + m_->jnt_dofadr[m_->body_jntadr[body]];
            const mjtNum* qa = d_->qacc + m_->jnt_dofadr[m_->body_jntadr[body]];
            const mjtNum* in = m_->body_inertia + 3 * body;
            for (int i = 0; i < 3; ++i) kinetic += 0.5 * (b.mass * qv[i] * qv[i] + in[i] * qv[3 + i] * qv[3 + i]);
            residual = std::max({residual, Vec3(qa[0], qa[1], qa[2]).norm() / g,
                                 Vec3(qa[3], qa[4], qa[5]).norm() * r_max[b.index] / g});
            const mjtNum* q = d_->qpos + m_->jnt_qposadr[m_->body_jntadr[body]];
            const mjtNum* q0 = qpos0.data() + m_->jnt_qposadr[m_->body_jntadr[body]];
            const double move = Vec3(q[0] - q0[0], q[1] - q0[1], q[2] - q0[2]).norm();
            const double dot = std::abs(q[3] * q0[3] + q[4] * q0[4] + q[5] * q0[5] + q[6] * q0[6]);
            if (why.empty()) why = not_at_rest(b.name, move, 2.0 * std::acos(std::min(1.0, dot)), min_edge[b.index]);
        }
        // kinetic damping: past a peak of the kinetic energy, every block stops
        if (kinetic < kinetic_last) {
            mju_zero(d_->qvel, m_->nv);
            kinetic_last = 0.0;
        } else {
            kinetic_last = kinetic;
        }
        if (plan.judged(k)) rest = residual < kResidual;
    }
    for (int i = 0; i < 3; ++i) m_->opt.gravity[i] = g0[i];
    std::ostringstream n;
    if (rest) {
        mju_zero(d_->qvel, m_->nv);
        d_->time = 0.0;
        n << "start: settled under gravity and the loads at t = 0 in " << steps << " steps (matched springs; unbalanced acceleration "
          << residual << " g)";
    } else {
        if (why.empty()) why = "not at rest after " + std::to_string(steps) + " steps";
        mj_resetData(m_, d_);
        n << "start: as given, not settled (" << why << ")";
    }
    notes_.push_back(n.str());
}

void MujocoBackend::apply_loads(const std::vector<AppliedLoad>& loads, double scale) {
    // xfrc_applied persists, so it is rewritten every step
    std::memset(d_->xfrc_applied, 0, sizeof(mjtNum) * 6 * m_->nbody);
    for (const AppliedLoad& l : loads) {
        const int body = body_[l.block];
        const Vec3 f = scale * l.force;
        const Vec3 torque = (point(l.block, l.point) - com(body)).cross(f);
        for (int k = 0; k < 3; ++k) {
            d_->xfrc_applied[6 * body + k] += f[k];
            d_->xfrc_applied[6 * body + 3 + k] += torque[k];
        }
    }
}

StepStatus MujocoBackend::step() {
    CurrentHexahedra current(&hexahedra_);
    const double t = d_->time;
    std::vector<AppliedLoad> loads;
    applied_loads(scene_, t, loads);
    apply_loads(loads, 1.0);
    auto velocity = [&](int block, const Vec3& p) { return point_velocity(block, point(block, p)); };
    const double p0 = cairn::load_power(loads, velocity);
    if (matched_) matched_step();
    else mj_step(m_, d_);
    // mj_step computes positions before it integrates: bring the poses to the new qpos
    mj_kinematics(m_, d_);
    if (scene_.damping.alpha > 0) {
        const double k = std::exp(-scene_.damping.alpha * dt_);
        for (int i = 0; i < m_->nv; ++i) d_->qvel[i] *= k;
    }
    const double p1 = cairn::load_power(loads, velocity);
    external_work_ += 0.5 * (p0 + p1) * dt_;
    if (d_->warning[mjWARN_BADQACC].number > 0 || d_->warning[mjWARN_BADQPOS].number > 0 ||
        d_->warning[mjWARN_BADQVEL].number > 0) {
        failure_ = "MuJoCo reset the simulation after a bad number at t = " + std::to_string(d_->time) + " s";
        return StepStatus::unstable;
    }
    if (d_->warning[mjWARN_CNSTRFULL].number > 0 || d_->warning[mjWARN_CONTACTFULL].number > 0) {
        failure_ = "MuJoCo constraint storage full at t = " + std::to_string(d_->time) + " s (njmax " +
                   std::to_string(m_->njmax) + ", nconmax " + std::to_string(m_->nconmax) + ")";
        return StepStatus::unstable;
    }
    return StepStatus::ok;
}

PointSpring MujocoBackend::pair_spring(const mjContact& c) const {
    const RigidBlock& a = blocks_[geom_block_[c.geom1]];
    const RigidBlock& b = blocks_[geom_block_[c.geom2]];
    auto block_orientation = [&](const RigidBlock& x) { return x.fixed ? x.orientation : orientation(body_[x.index]); };
    // MuJoCo's normal points from geom 1 to geom 2
    const Vec3 n(c.frame[0], c.frame[1], c.frame[2]);
    return matched_point_spring(scene_, a, block_orientation(a), b, block_orientation(b), n);
}

double MujocoBackend::depth_scale(const mjContact& c) const {
    // the overlap over the contact distance: a box-box pair reports box_depth_scale of its overlap
    // (rigid mode: half, MuJoCo 2.2.2's own box-box convention; matched mode: all of it)
    const bool box_box = m_->geom_type[c.geom1] == mjGEOM_BOX && m_->geom_type[c.geom2] == mjGEOM_BOX;
    return box_box ? 1.0 / hexahedra_.box_depth_scale : 1.0;
}

void MujocoBackend::calibrate_contacts() {
    // at rest each normal row balances R f = K d r (R = (1-d)/d w, w = the rows' invweight:
    // MuJoCo's body_invweight0 of both bodies) and its reference damping adds B v: solref
    // (-(1-d) w k, -(1-d) w c) makes f = k r + c v per contact with the pair's own k and c
    const double d = impedance_;
    for (int i = 0; i < d_->ncon; ++i) {
        mjContact& c = d_->contact[i];
        PointSpring s = pair_spring(c);
        int b1 = m_->geom_bodyid[c.geom1], b2 = m_->geom_bodyid[c.geom2];
        double w = m_->body_invweight0[2 * b1] + m_->body_invweight0[2 * b2];
        c.solref[0] = -(1.0 - d) * w * s.stiffness * depth_scale(c);
        c.solref[1] = -(1.0 - d) * w * s.damping;
    }
}

void MujocoBackend::matched_step() {
    // mj_step's pipeline (MuJoCo 2.2.2: mj_checkPos, mj_checkVel, mj_forward, mj_checkAcc,
    // mj_Euler; no sensors) with each contact's solref set between collision and constraint
    // assembly, and the friction rows' damping set before the reference accelerations
    mj_checkPos(m_, d_);
    mj_checkVel(m_, d_);
    mj_kinematics(m_, d_);
    mj_comPos(m_, d_);
    mj_camlight(m_, d_);
    mj_tendon(m_, d_);
    mj_crb(m_, d_);
    mj_factorM(m_, d_);
    mj_collision(m_, d_);
    calibrate_contacts();
    mj_makeConstraint(m_, d_);
    for (int i = 0; i < d_->ncon; ++i) {
        const mjContact& c = d_->contact[i];
        if (c.efc_address < 0) continue;
        for (int j = 1; j < c.dim; ++j) d_->efc_KBIP[4 * (c.efc_address + j) + 1] = friction_damping_;
    }
    mj_transmission(m_, d_);
    mj_projectConstraint(m_, d_);
    mj_fwdVelocity(m_, d_);
    mj_fwdActuation(m_, d_);
    mj_fwdAcceleration(m_, d_);
    mj_fwdConstraint(m_, d_);
    mj_checkAcc(m_, d_);
    mj_Euler(m_, d_);
}

Sample MujocoBackend::sample() const {
    Sample s;
    s.t = d_->time;
    for (const RigidBlock& b : blocks_) {
        if (b.fixed) continue;
        int body = body_[b.index];
        const mjtNum* qv = d_->qvel + m_->jnt_dofadr[m_->body_jntadr[body]];
        BlockState st;
        st.position = com(body);
        st.orientation = orientation(body).normalized();
        st.velocity = Vec3(qv[0], qv[1], qv[2]);
        st.angular_velocity = st.orientation * Vec3(qv[3], qv[4], qv[5]);
        add_block_state(s, b, st, scene_.gravity);
    }
    for (const ProbeDef& p : scene_.probes) s.probes.push_back(point(p.block, p.point));
    s.energy.external = external_work_;
    s.contacts = d_->ncon;
    if (matched_)
        for (int i = 0; i < d_->ncon; ++i) {
            const mjContact& c = d_->contact[i];
            if (c.dist >= 0) continue;
            const double overlap = depth_scale(c) * c.dist;
            s.energy.contact += 0.5 * pair_spring(c).stiffness * overlap * overlap;
        }
    return s;
}

// the contacts of the last step with the constraint forces MuJoCo found for them
std::vector<ContactPoint> MujocoBackend::contact_points() const {
    // geom -> block: the world body's geoms are the fixed blocks in scene order (as written in the
    // model), every other geom is its body's block
    std::vector<int> block_of_geom(size_t(m_->ngeom), -1);
    size_t next_fixed = 0;
    std::vector<int> fixed;
    for (const RigidBlock& b : blocks_)
        if (b.fixed) fixed.push_back(b.index);
    for (int g = 0; g < m_->ngeom; ++g) {
        const int body = m_->geom_bodyid[g];
        if (body == 0) {
            if (next_fixed < fixed.size()) block_of_geom[g] = fixed[next_fixed++];
            continue;
        }
        for (size_t k = 0; k < blocks_.size(); ++k)
            if (!blocks_[k].fixed && body_[k] == body) block_of_geom[g] = int(k);
    }
    std::vector<ContactPoint> out;
    for (int i = 0; i < d_->ncon; ++i) {
        const mjContact& c = d_->contact[i];
        mjtNum f[6];
        mj_contactForce(m_, d_, i, f);   // in the contact frame: normal, then the two tangents
        const Vec3 n(c.frame[0], c.frame[1], c.frame[2]);   // from geom 1 towards geom 2
        const Vec3 t1(c.frame[3], c.frame[4], c.frame[5]), t2(c.frame[6], c.frame[7], c.frame[8]);
        ContactPoint p;
        p.position = Vec3(c.pos[0], c.pos[1], c.pos[2]);
        p.normal = n;
        // the force pushes geom 2 along the normal: geom 2 is block a
        p.normal_force = f[0] * n;
        p.shear_force = f[1] * t1 + f[2] * t2;
        p.block_a = block_of_geom[c.geom2];
        p.block_b = block_of_geom[c.geom1];
        out.push_back(p);
    }
    return out;
}

}  // namespace

BackendInfo mujoco_backend_info() {
    BackendInfo info;
    info.name = "mujoco";
    info.description = "MuJoCo 2.2.2 rigid bodies (soft constraints); contact rigid or matched (calibrated solref)";
    info.capabilities = mujoco_capabilities();
    info.solver = "solref 0.002, elliptic cone";
    info.make = [] { return std::make_unique<MujocoBackend>(); };
    return info;
}

}  // namespace cairn

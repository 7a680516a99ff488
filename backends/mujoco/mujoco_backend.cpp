#include "mujoco/mujoco_backend.hpp"

#include <mujoco/mujoco.h>

#include <cmath>
#include <csetjmp>
#include <cstring>
#include <sstream>

#include "engine_settings.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"
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

// rows MuJoCo 2.2.2 could allocate here (its constraint arrays grow with njmax², engines.md)
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

    Scene scene_;
    std::vector<RigidBlock> blocks_;
    std::vector<int> body_;          // MuJoCo body id per block (0 for fixed blocks)
    std::vector<double> spring_;     // matched mode: per-point spring kn·A/4 per block, N/m
    mjModel* m_ = nullptr;
    mjData* d_ = nullptr;
    bool matched_ = false;
    double dt_ = 0.0;
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
    p.cone = settings.word("cone", matched_ ? "elliptic" : "pyramidal", {"pyramidal", "elliptic"});
    p.iterations = static_cast<int>(settings.integer("iterations", 100, 1));
    p.tolerance = settings.number("tolerance", 1e-10, 0.0);
    p.noslip_iterations = static_cast<int>(settings.integer("noslip_iterations", 0, 0));
    p.impedance = settings.number("impedance", matched_ ? 0.9 : 0.99, 1e-4);
    p.solref[0] = settings.number("timeconst", 0.002, 0.0);
    p.solref[1] = settings.number("dampratio", 1.0, 0.0);
    settings.finish();
    if (p.impedance > 0.9999) throw Error("mujoco setting 'impedance' must be at most 0.9999");
    dt_ = p.dt = engine_time_step(scene_);
    blocks_ = rigid_blocks(scene_, "mujoco");

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
        // a per-geom direct solref (-S, -B): at rest MuJoCo balances R f = S r / d on each normal
        // row with R = (1 - d)/d * w; the static penetration of a face-on-face pair (4 contacts)
        // is mg/(kn A) for S = (1 - d) * kCalibration * kn A / (4 m). kCalibration = 2 was measured
        // (MuJoCo 2.2.2: a 1 m and a 0.5 m cube, d = 0.5 ... 0.9; tests pin it)
        constexpr double kCalibration = 2.0;
        const double imp = p.impedance;
        p.block_solref.resize(blocks_.size());
        std::array<double, 2> shared{0.0, 0.0};
        for (const RigidBlock& b : blocks_) {
            if (b.fixed) continue;
            PointSpring s = matched_point_spring(scene_, b, nullptr);
            double stiffness = (1.0 - imp) * kCalibration * s.stiffness / b.mass;
            double omega = std::sqrt(stiffness / imp);
            double zeta = 4.0 * s.damping / (2.0 * std::sqrt(4.0 * s.stiffness * b.mass));
            p.block_solref[b.index] = {-stiffness, -2.0 * zeta * omega * imp};
            if (shared[0] == 0.0) shared = p.block_solref[b.index];
        }
        // a fixed block takes the first free block's values (MuJoCo averages a pair's solref)
        for (const RigidBlock& b : blocks_)
            if (b.fixed) p.block_solref[b.index] = shared;
    }

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

    body_.assign(blocks_.size(), 0);
    int next = 1;
    for (const RigidBlock& b : blocks_) {
        if (b.fixed) continue;
        body_[b.index] = next;
        mjtNum* qv = d_->qvel + m_->jnt_dofadr[m_->body_jntadr[next]];
        const BlockDef& def = scene_.blocks[b.index];
        Vec3 w_local = b.orientation.conjugate() * def.angular_velocity;
        for (int k = 0; k < 3; ++k) {
            qv[k] = def.velocity[k];
            qv[3 + k] = w_local[k];
        }
        ++next;
    }
    mj_forward(m_, d_);

    std::ostringstream n;
    auto note = [&](std::ostringstream& s) { notes_.push_back(s.str()); s.str(""); };
    n << "contact_mode: " << (matched_ ? "matched" : "rigid");
    note(n);
    n << "time_step: " << dt_ << " s" << (scene_.run.dt ? "" : " (dt = auto: engine default 1e-4 s)");
    note(n);
    n << "solver: Newton, " << p.iterations << " iterations, tolerance " << p.tolerance << ", Euler integrator, "
      << p.cone << " friction cone, margin 0, njmax " << p.njmax << ", nconmax " << p.nconmax;
    note(n);
    if (matched_)
        n << "matched contact: direct solref per geom so the static penetration of a face-on-face pair is "
             "mg/(kn*A) (4 contacts assumed), impedance " << p.impedance
          << "; the contact frequency is MuJoCo's, not sqrt(kn*A/m); pair values are averaged by MuJoCo";
    else
        n << "rigid contact: solref " << p.solref[0] << " " << p.solref[1] << ", solimp " << p.impedance << " "
          << p.impedance << " 0.001";
    note(n);
    n << "friction: mu " << scene_.contact.friction << ", " << p.cone
      << " cone; soft constraint: a block held by friction creeps slowly; no elastic stick before slip";
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
            n << "general hexahedra: mesh geoms (convex hull); MuJoCo 2.2.2 gives one contact per mesh pair";
            note(n);
            break;
        }
}

StepStatus MujocoBackend::step() {
    // loads at their material points: xfrc_applied persists, so it is rewritten every step
    std::memset(d_->xfrc_applied, 0, sizeof(mjtNum) * 6 * m_->nbody);
    const double t = d_->time;
    double p0 = 0.0;
    for (const LoadDef& l : scene_.loads) {
        double f = l.factor(t);
        int body = body_[l.block];
        if (f == 0.0 || body == 0) continue;
        Vec3 p = point(l.block, l.point);
        Vec3 force = f * l.force;
        Vec3 torque = (p - com(body)).cross(force);
        for (int k = 0; k < 3; ++k) {
            d_->xfrc_applied[6 * body + k] += force[k];
            d_->xfrc_applied[6 * body + 3 + k] += torque[k];
        }
        p0 += force.dot(point_velocity(l.block, p));
    }
    mj_step(m_, d_);
    if (scene_.damping.alpha > 0) {
        const double k = std::exp(-scene_.damping.alpha * dt_);
        for (int i = 0; i < m_->nv; ++i) d_->qvel[i] *= k;
    }
    double p1 = 0.0;
    for (const LoadDef& l : scene_.loads) {
        double f = l.factor(t);
        if (f == 0.0 || body_[l.block] == 0) continue;
        p1 += f * l.force.dot(point_velocity(l.block, point(l.block, l.point)));
    }
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
            int b1 = m_->geom_bodyid[c.geom1], b2 = m_->geom_bodyid[c.geom2];
            int body = b1 != 0 ? b1 : b2;
            for (size_t k = 0; k < blocks_.size(); ++k)
                if (body_[k] == body) {
                    PointSpring sp = matched_point_spring(scene_, blocks_[k], nullptr);
                    s.energy.contact += 0.5 * sp.stiffness * c.dist * c.dist;
                    break;
                }
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
    info.make = [] { return std::make_unique<MujocoBackend>(); };
    return info;
}

}  // namespace cairn

#include "ode/ode_backend.hpp"

#include <ode/ode.h>

#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <deque>
#include <stdexcept>
#include <memory>
#include <sstream>

#include "applied_loads.hpp"
#include "engine_settings.hpp"
#include "error.hpp"
#include "hexahedron_contact.hpp"
#include "output/number_format.hpp"
#include "rigid_blocks.hpp"
#include "rigid_sample.hpp"

namespace cairn {

std::vector<FeatureSupport> ode_capabilities();

namespace {

// collision data of one general hexahedron, kept alive for ODE (it does not copy)
struct ConvexData {
    std::array<dReal, 6 * 4> planes;     // n·x = d per face
    std::array<dReal, 8 * 3> points;     // corners relative to the centre of mass, block axes
    std::array<unsigned, 6 * 5> polygons;  // 4, i0..i3 per face, counter-clockwise from outside
};

// ODE 0.16 calls exit(1) after its error handler and abort() after its debug (internal error)
// handler returns (ode/src/error.cpp), so a handler must not return. The library is C++ built
// with exceptions (it links the C++ personality routine and has .gcc_except_table): an exception
// unwinds its frames, where a longjmp would skip their destructors. The world it leaves behind
// may be half-stepped and keeps whatever ODE had allocated for that step, so the backend never
// touches it again (see abandon_world)
struct OdeFault : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] void throw_ode_fault(int errnum, const char* msg, va_list ap) {
    char text[512];
    std::vsnprintf(text, sizeof text, msg, ap);
    throw OdeFault("ODE internal error " + std::to_string(errnum) + ": " + text);
}

// ODE's messages are warnings it carries on from (its direct solver's "LCP internal error": the
// step's LCP was not solved). Printed to stderr by default, where a report never shows them; the
// stepping backend (one per thread at a time) counts them instead and reports them in its notes
struct OdeMessages {
    long count = 0;
    std::string first;   // the first message's text
    double first_time = 0.0;   // s, the start of the step that raised it
};
thread_local OdeMessages* stepping_messages = nullptr;

void count_ode_message(int errnum, const char* msg, va_list ap) {
    char text[512];
    std::vsnprintf(text, sizeof text, msg, ap);
    if (!stepping_messages) {
        std::fprintf(stderr, "ODE message %d: %s\n", errnum, text);   // outside a step: as ODE prints it
        return;
    }
    if (stepping_messages->count++ == 0) stepping_messages->first = "ODE message " + std::to_string(errnum) + ": " + text;
}

class OdeBackend : public Backend {
public:
    OdeBackend() {
        static const bool initialised = [] {
            dInitODE2(0);
            dSetErrorHandler(&throw_ode_fault);
            dSetDebugHandler(&throw_ode_fault);
            dSetMessageHandler(&count_ode_message);
            return true;
        }();
        (void)initialised;
    }
    ~OdeBackend() override { clear(); }
    std::string name() const override { return "ode"; }
    std::string engine_version() const override {
        return std::string("ODE 0.16 (") + dGetConfiguration() + ")";
    }
    void build(const Scene& scene, const RunOptions& options) override;
    double time_step() const override { return dt_; }
    double critical_step() const override { return 0.0; }
    StepStatus step() override;
    Sample sample() const override;
    std::string failure() const override { return failure_; }
    std::vector<std::string> notes() const override;
    std::vector<ContactPoint> contact_points() const override;

private:
    static void near_callback(void* self, dGeomID a, dGeomID b);
    void collide(dGeomID a, dGeomID b);
    Vec3 trial_slip(dBodyID a, dBodyID b, const dContactGeom& g) const;
    void clear();
    Vec3 com(int block) const;
    Quat orientation(int block) const;
    Corners world_corners(const RigidBlock& b) const;
    double load_power() const;
    void abandon_world();
    void forget_world();   // drop every handle into ODE without calling it

    Scene scene_;
    std::vector<RigidBlock> blocks_;
    std::vector<std::unique_ptr<ConvexData>> convex_;
    std::vector<dBodyID> bodies_;   // per block, null for fixed blocks
    std::vector<dGeomID> geoms_;    // per block
    dWorldID world_ = nullptr;
    dSpaceID space_ = nullptr;
    dJointGroupID contacts_ = nullptr;
    bool matched_ = false;
    bool quickstep_ = false;
    double dt_ = 0.0;
    double t_ = 0.0;
    double external_work_ = 0.0;
    double contact_energy_ = 0.0;
    int contact_count_ = 0;
    // the last step's contacts, kept when RunOptions::record_contacts: geometry, blocks (a, b),
    // whether a is fixed (ODE then reports the force on b), and the joint's force feedback
    bool record_contacts_ = false;
    struct Recorded { dContactGeom geom; int a, b; bool a_fixed; };
    std::vector<Recorded> recorded_;
    std::deque<dJointFeedback> feedback_;   // a deque: joints keep pointers to its elements
    bool faulted_ = false;   // an ODE error stopped the run; the world is abandoned
    Sample frozen_;          // the last state before the fault
    std::string failure_;
    std::vector<std::string> notes_;
    OdeMessages messages_;   // ODE's messages since the build
};

void OdeBackend::clear() {
    if (contacts_) dJointGroupDestroy(contacts_);
    if (space_) dSpaceDestroy(space_);   // destroys the geoms it holds
    if (world_) dWorldDestroy(world_);   // destroys the bodies
    forget_world();
}

void OdeBackend::forget_world() {
    contacts_ = nullptr;
    space_ = nullptr;
    world_ = nullptr;
    bodies_.clear();
    geoms_.clear();
    convex_.clear();
}

Vec3 OdeBackend::com(int block) const {
    const dBodyID b = bodies_[block];
    if (!b) return blocks_[block].com_world;
    const dReal* p = dBodyGetPosition(b);
    return {p[0], p[1], p[2]};
}

Corners OdeBackend::world_corners(const RigidBlock& b) const {
    Corners w;
    for (int i = 0; i < 8; ++i) w[i] = block_point_world(b, com(b.index), orientation(b.index), b.corners[i]);
    return w;
}

Quat OdeBackend::orientation(int block) const {
    const dBodyID b = bodies_[block];
    if (!b) return blocks_[block].orientation;
    const dReal* q = dBodyGetQuaternion(b);
    return Quat(q[0], q[1], q[2], q[3]);
}

void OdeBackend::build(const Scene& scene, const RunOptions& options) {
    clear();
    scene_ = scene;
    notes_.clear();
    messages_ = OdeMessages{};
    failure_.clear();
    faulted_ = false;
    t_ = external_work_ = contact_energy_ = 0.0;
    contact_count_ = 0;
    EngineSettings settings(scene_, "ode");
    matched_ = contact_mode(settings, options) == "matched";
    record_contacts_ = options.record_contacts;
    // QuickStep by default: dWorldStep's direct LCP lets a block creep near its friction limit
    // (a cube on a 45 degree slope at mu = 1.1 slides 32 mm in 1 s; docs/backends.md)
    std::string stepper = settings.word("stepper", "quickstep", {"auto", "step", "quickstep"});
    // 200 iterations: at 50 the top cube of a stack pushed at 0.83 of its friction limit crept
    // 39 µm/s (0.25 µm/s at 200, 0.13 µm/s at 1000), and a column leaned early (docs/backends.md)
    const long long iterations = settings.integer("iterations", 200, 1);
    const double max_correcting = settings.number("max_correcting_vel", 0.01, 0.0);
    const double erp = settings.number("erp", 0.2, 0.0);
    const double cfm = settings.number("cfm", 1e-10, 0.0);
    settings.finish();
    dt_ = engine_time_step(scene_);
    blocks_ = rigid_blocks(scene_, "ode");
    int free_blocks = 0;
    for (const auto& b : blocks_) free_blocks += b.fixed ? 0 : 1;
    quickstep_ = stepper == "quickstep" || (stepper == "auto" && free_blocks > 10);

    // a fresh world per build; QuickStep's constraint shuffling draws from dRand: seed it
    dRandSetSeed(0);
    world_ = dWorldCreate();
    space_ = dHashSpaceCreate(nullptr);
    contacts_ = dJointGroupCreate(0);
    dWorldSetGravity(world_, scene_.gravity.x(), scene_.gravity.y(), scene_.gravity.z());
    dWorldSetAutoDisableFlag(world_, 0);
    dWorldSetERP(world_, erp);
    dWorldSetCFM(world_, cfm);
    dWorldSetQuickStepNumIterations(world_, static_cast<int>(iterations));
    dWorldSetContactSurfaceLayer(world_, 0.0);
    // rigid: a small correcting velocity stops ERP from launching the block; matched: the soft
    // ERP/CFM row is the spring and must not be capped
    dWorldSetContactMaxCorrectingVel(world_, matched_ ? dInfinity : max_correcting);

    for (const RigidBlock& b : blocks_) {
        dGeomID g;
        if (b.is_box) {
            g = dCreateBox(space_, 2 * b.half_extents.x(), 2 * b.half_extents.y(), 2 * b.half_extents.z());
        } else {
            auto c = std::make_unique<ConvexData>();
            for (int i = 0; i < 8; ++i)
                for (int k = 0; k < 3; ++k) c->points[3 * i + k] = b.corners[i][k] - b.com[k];
            for (int f = 0; f < 6; ++f) {
                const auto& fc = kFaceCorners[f];
                Vec3 p0 = b.corners[fc[0]] - b.com;
                Vec3 n = ((b.corners[fc[1]] - b.corners[fc[0]]).cross(b.corners[fc[3]] - b.corners[fc[0]]))
                             .normalized();
                for (int k = 0; k < 3; ++k) c->planes[4 * f + k] = n[k];
                c->planes[4 * f + 3] = n.dot(p0);
                c->polygons[5 * f] = 4;
                for (int k = 0; k < 4; ++k) c->polygons[5 * f + 1 + k] = static_cast<unsigned>(fc[k]);
            }
            g = dCreateConvex(space_, c->planes.data(), 6, c->points.data(), 8, c->polygons.data());
            convex_.push_back(std::move(c));
        }
        dGeomSetData(g, reinterpret_cast<void*>(static_cast<intptr_t>(b.index)));
        // geometry frame: block axes at the centre of mass (a box is centred on it)
        Mat3 r = b.orientation.toRotationMatrix();
        dMatrix3 rm;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) rm[4 * i + j] = r(i, j);
            rm[4 * i + 3] = 0.0;
        }
        dBodyID body = nullptr;
        if (b.fixed) {
            dGeomSetPosition(g, b.com_world.x(), b.com_world.y(), b.com_world.z());
            dGeomSetRotation(g, rm);
        } else {
            body = dBodyCreate(world_);
            dMass m;
            const Mat3& I = b.inertia;
            dMassSetParameters(&m, b.mass, 0, 0, 0, I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2));
            dBodySetMass(body, &m);
            dBodySetPosition(body, b.com_world.x(), b.com_world.y(), b.com_world.z());
            dBodySetRotation(body, rm);
            const BlockDef& d = scene_.blocks[b.index];
            dBodySetLinearVel(body, d.velocity.x(), d.velocity.y(), d.velocity.z());
            dBodySetAngularVel(body, d.angular_velocity.x(), d.angular_velocity.y(), d.angular_velocity.z());
            dBodySetAutoDisableFlag(body, 0);
            dGeomSetBody(g, body);
        }
        bodies_.push_back(body);
        geoms_.push_back(g);
    }

    std::ostringstream n;
    auto note = [&](std::ostringstream& s) { notes_.push_back(s.str()); s.str(""); };
    n << "contact_mode: " << (matched_ ? "matched" : "rigid");
    note(n);
    n << "time_step: " << dt_ << " s" << (scene_.run.dt ? "" : " (dt = auto: engine default 1e-4 s)");
    note(n);
    n << "stepper: " << (quickstep_ ? "dWorldQuickStep, " + std::to_string(iterations) + " iterations"
                                    : std::string("dWorldStep (direct LCP)"))
      << (stepper == "auto" ? " (auto: dWorldStep up to 10 free blocks)" : "");
    note(n);
    if (matched_)
        n << "matched contact: kn*A/4 per contact (A = smaller area of the two faces most aligned with the contact normal) as soft_erp = "
             "h*k/(h*k+c), soft_cfm = 1/(h*k+c); no correcting-velocity cap";
    else
        n << "rigid contact: erp " << erp << ", cfm " << cfm << ", contact max correcting velocity "
          << max_correcting << " m/s, restitution " << scene_.contact.restitution;
    note(n);
    n << "friction: dContactApprox1, mu " << scene_.contact.friction
      << " per contact in two directions (pyramid), the first along the contact's trial sliding velocity "
         "(dContactFDir1); no elastic stick before slip";
    note(n);
    if (scene_.damping.alpha > 0) {
        n << "mass-proportional damping: velocities scaled by exp(-alpha*dt) after each step";
        note(n);
    }
    n << "auto-disable: off";
    note(n);
    for (const auto& line : rigid_engine_notes(scene_)) notes_.push_back(line);
    for (const auto& b : blocks_)
        if (!b.is_box) {
            n << "general hexahedra: dCreateConvex (" << dGetConfiguration() << ")";
            note(n);
            break;
        }
}

// the last step's contact joints with the forces they applied
std::vector<ContactPoint> OdeBackend::contact_points() const {
    std::vector<ContactPoint> out;
    if (faulted_) return out;   // the step that faulted has no trustworthy forces
    for (size_t i = 0; i < recorded_.size(); ++i) {
        const Recorded& r = recorded_[i];
        ContactPoint c;
        c.position = Vec3(r.geom.pos[0], r.geom.pos[1], r.geom.pos[2]);
        c.normal = Vec3(r.geom.normal[0], r.geom.normal[1], r.geom.normal[2]);   // moves geom 1 (a) out
        const dJointFeedback& f = feedback_[i];
        // f1 is the force on the joint's first body: a, or b when a is fixed (ODE swaps them)
        Vec3 force_on_a(f.f1[0], f.f1[1], f.f1[2]);
        if (r.a_fixed) force_on_a = -force_on_a;
        c.normal_force = force_on_a.dot(c.normal) * c.normal;
        c.shear_force = force_on_a - c.normal_force;
        c.block_a = r.a;
        c.block_b = r.b;
        out.push_back(c);
    }
    return out;
}

void OdeBackend::near_callback(void* self, dGeomID a, dGeomID b) {
    static_cast<OdeBackend*>(self)->collide(a, b);
}

// relative velocity of body a against body b at the contact, tangential, after this step's
// gravity and loads but before any contact force, m/s
Vec3 OdeBackend::trial_slip(dBodyID a, dBodyID b, const dContactGeom& g) const {
    Vec3 v = Vec3::Zero();
    for (int side = 0; side < 2; ++side) {
        dBodyID body = side == 0 ? a : b;
        if (!body) continue;
        dVector3 pv;
        dBodyGetPointVel(body, g.pos[0], g.pos[1], g.pos[2], pv);
        const dReal* f = dBodyGetForce(body);
        dMass m;
        dBodyGetMass(body, &m);
        Vec3 trial = Vec3(pv[0], pv[1], pv[2]) + dt_ * (Vec3(f[0], f[1], f[2]) / m.mass + scene_.gravity);
        v += side == 0 ? trial : Vec3(-trial);
    }
    const Vec3 n(g.normal[0], g.normal[1], g.normal[2]);
    return v - v.dot(n) * n;
}

void OdeBackend::collide(dGeomID ga, dGeomID gb) {
    dBodyID ba = dGeomGetBody(ga), bb = dGeomGetBody(gb);
    if (!ba && !bb) return;   // two fixed blocks
    constexpr int kMax = 4;
    dContact c[kMax];
    const auto& a = blocks_[reinterpret_cast<intptr_t>(dGeomGetData(ga))];
    const auto& b = blocks_[reinterpret_cast<intptr_t>(dGeomGetData(gb))];
    int n = 0;
    if (a.is_box && b.is_box) {
        n = dCollide(ga, gb, kMax, &c[0].geom, sizeof(dContact));
    } else {
        // ODE's convex-convex collider gives one point per face-on-face pair (a hinge) and a zero
        // normal for exactly touching faces: cairn's face-clipping collider instead
        for (const HexContact& h : hexahedron_contacts(world_corners(a), world_corners(b), kMax)) {
            dContactGeom& g = c[n++].geom;
            for (int k = 0; k < 3; ++k) {
                g.pos[k] = h.position[k];
                g.normal[k] = h.normal[k];
            }
            g.depth = h.depth;
            g.g1 = ga;
            g.g2 = gb;
            g.side1 = g.side2 = -1;
        }
    }
    if (n == 0) return;
    const Quat qa = orientation(int(a.index)), qb = orientation(int(b.index));
    for (int i = 0; i < n; ++i) {
        PointSpring s;
        // ODE's normal points into geom 1 (block a)
        const Vec3 normal(c[i].geom.normal[0], c[i].geom.normal[1], c[i].geom.normal[2]);
        if (matched_) s = matched_point_spring(scene_, a, qa, b, qb, -normal);
        dSurfaceParameters& sp = c[i].surface;
        sp.mode = dContactApprox1;
        sp.mu = scene_.contact.friction;
        // dContactApprox1 clamps each friction direction at mu N separately (a pyramid): turned
        // along the sliding the contact would have without friction, it limits that sliding at
        // mu N in every direction
        Vec3 t = trial_slip(ba, bb, c[i].geom);
        if (t.norm() > 1e-12) {
            sp.mode |= dContactFDir1;
            t.normalize();
            for (int k = 0; k < 3; ++k) c[i].fdir1[k] = t[k];
        }
        if (scene_.contact.restitution > 0) {
            sp.mode |= dContactBounce;
            sp.bounce = scene_.contact.restitution;
            sp.bounce_vel = 0.0;
        }
        if (matched_) {
            sp.mode |= dContactSoftERP | dContactSoftCFM;
            const double denom = dt_ * s.stiffness + s.damping;
            sp.soft_erp = dt_ * s.stiffness / denom;
            sp.soft_cfm = 1.0 / denom;
            contact_energy_ += 0.5 * s.stiffness * c[i].geom.depth * c[i].geom.depth;
        }
        dJointID j = dJointCreateContact(world_, contacts_, &c[i]);
        dJointAttach(j, ba, bb);
        if (record_contacts_) {
            feedback_.emplace_back();
            dJointSetFeedback(j, &feedback_.back());
            recorded_.push_back({c[i].geom, int(a.index), int(b.index), ba == nullptr});
        }
        ++contact_count_;
    }
}

double OdeBackend::load_power() const {
    std::vector<AppliedLoad> loads;
    applied_loads(scene_, t_, loads);
    return cairn::load_power(loads, [&](int block, const Vec3& point) {
        Vec3 p = block_point_world(blocks_[block], com(block), orientation(block), point);
        dVector3 v;
        dBodyGetPointVel(bodies_[block], p.x(), p.y(), p.z(), v);
        return Vec3(v[0], v[1], v[2]);
    });
}

void OdeBackend::abandon_world() {
    // keep what was last sampled, then let go of the world without another call into it: a
    // destroy on a half-stepped world (a space still locked by its collide) could fault again
    frozen_ = sample();
    forget_world();
    faulted_ = true;
}

std::vector<std::string> OdeBackend::notes() const {
    std::vector<std::string> n = notes_;
    if (messages_.count > 0)
        n.push_back("warning: ODE reported " + std::to_string(messages_.count) + " message(s) while stepping (first at t = " +
                    number_format("%.6g", messages_.first_time) + " s: " + messages_.first + "). \"LCP internal error\" is dWorldStep's direct solver failing on a step: "
                    "with many redundant frictional contacts it can return forces that let a structure fall (a "
                    "25-voussoir arch falls on dWorldStep at cfm 1e-10 and stands at cfm 1e-6 or on QuickStep; "
                    "docs/backends.md)");
    return n;
}

StepStatus OdeBackend::step() {
    if (faulted_) return StepStatus::unstable;
    // loads at their material points (ODE clears accumulated forces after each step)
    std::vector<AppliedLoad> loads;
    applied_loads(scene_, t_, loads);
    for (const AppliedLoad& l : loads) {
        Vec3 p = block_point_world(blocks_[l.block], com(l.block), orientation(l.block), l.point);
        dBodyAddForceAtPos(bodies_[l.block], l.force.x(), l.force.y(), l.force.z(), p.x(), p.y(), p.z());
    }
    double p0 = load_power();
    contact_energy_ = 0.0;
    contact_count_ = 0;
    recorded_.clear();
    feedback_.clear();
    stepping_messages = &messages_;
    const long messages_before = messages_.count;
    try {
        dSpaceCollide(space_, this, &OdeBackend::near_callback);
        if (quickstep_) dWorldQuickStep(world_, dt_);
        else dWorldStep(world_, dt_);
        stepping_messages = nullptr;
    } catch (const OdeFault& e) {
        stepping_messages = nullptr;
        failure_ = std::string(e.what()) + " at t = " + std::to_string(t_) + " s";
        abandon_world();
        return StepStatus::unstable;
    }
    dJointGroupEmpty(contacts_);
    if (messages_before == 0 && messages_.count > 0) messages_.first_time = t_;
    t_ += dt_;
    if (scene_.damping.alpha > 0) {
        const double k = std::exp(-scene_.damping.alpha * dt_);
        for (dBodyID b : bodies_) {
            if (!b) continue;
            const dReal* v = dBodyGetLinearVel(b);
            const dReal* w = dBodyGetAngularVel(b);
            dBodySetLinearVel(b, k * v[0], k * v[1], k * v[2]);
            dBodySetAngularVel(b, k * w[0], k * w[1], k * w[2]);
        }
    }
    external_work_ += 0.5 * (p0 + load_power()) * dt_;
    failure_ = non_finite_block(blocks_, t_, [&](int i) { return com(i); });
    return failure_.empty() ? StepStatus::ok : StepStatus::unstable;
}

Sample OdeBackend::sample() const {
    if (faulted_) return frozen_;
    Sample s = rigid_sample(
        t_, blocks_, scene_,
        [&](const RigidBlock& b) {
            BlockState st;
            st.position = com(b.index);
            st.orientation = orientation(b.index).normalized();
            const dReal* v = dBodyGetLinearVel(bodies_[b.index]);
            const dReal* w = dBodyGetAngularVel(bodies_[b.index]);
            st.velocity = Vec3(v[0], v[1], v[2]);
            st.angular_velocity = Vec3(w[0], w[1], w[2]);
            return st;
        },
        [&](int i) { return com(i); }, [&](int i) { return orientation(i); });
    s.energy.external = external_work_;
    s.energy.contact = contact_energy_;
    s.contacts = contact_count_;
    return s;
}

}  // namespace

BackendInfo ode_backend_info() {
    BackendInfo info;
    info.name = "ode";
    info.description = "Open Dynamics Engine 0.16 rigid bodies (double); contact rigid or matched (soft ERP/CFM)";
    info.capabilities = ode_capabilities();
    info.solver = "QuickStep 200 iterations, ERP 0.2, CFM 1e-10";
    // Debian's ODE keeps its collision data global (built without mt_collisions): one run at a time
    info.thread_safe = false;
    info.make = [] { return std::make_unique<OdeBackend>(); };
    return info;
}

}  // namespace cairn

#include "bullet/bullet_backend.hpp"

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <memory>
#include <sstream>

#include "applied_loads.hpp"
#include "engine_settings.hpp"
#include "error.hpp"
#include "rigid_blocks.hpp"
#include "rigid_sample.hpp"

namespace cairn {

std::vector<FeatureSupport> bullet_capabilities();

namespace {

btVector3 bt(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
Vec3 eig(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
Quat eig(const btQuaternion& q) { return Quat(q.w(), q.x(), q.y(), q.z()); }
btQuaternion bt(const Quat& q) { return {q.x(), q.y(), q.z(), q.w()}; }

// the per-pair contact parameters, set on every manifold point before the solver runs
struct PairLaw {
    double friction = 0.0;
    double restitution = 0.0;
    bool matched = false;
};

// a world that writes the scene's friction, restitution and (matched mode) spring into every
// contact point, so that no pair-combination rule of Bullet changes them
class CairnWorld : public btDiscreteDynamicsWorld {
public:
    using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
    const Scene* scene = nullptr;
    const std::vector<RigidBlock>* blocks = nullptr;
    PairLaw law;

protected:
    void solveConstraints(btContactSolverInfo& info) override {
        btDispatcher* d = getDispatcher();
        for (int m = 0; m < d->getNumManifolds(); ++m) {
            btPersistentManifold* pm = d->getManifoldByIndexInternal(m);
            const auto& a = (*blocks)[pm->getBody0()->getUserIndex()];
            const auto& b = (*blocks)[pm->getBody1()->getUserIndex()];
            // block frame → world: Bullet's body frame is the block's principal axes
            const Quat qa = eig(pm->getBody0()->getWorldTransform().getRotation()) * Quat(a.principal.transpose());
            const Quat qb = eig(pm->getBody1()->getWorldTransform().getRotation()) * Quat(b.principal.transpose());
            for (int i = 0; i < pm->getNumContacts(); ++i) {
                btManifoldPoint& p = pm->getContactPoint(i);
                PointSpring s;
                // the point's normal points from body 1 to body 0
                if (law.matched) s = matched_point_spring(*scene, a, qa, b, qb, -eig(p.m_normalWorldOnB));
                p.m_combinedFriction = law.friction;
                p.m_combinedRestitution = law.restitution;
                p.m_combinedRollingFriction = 0.0;
                p.m_combinedSpinningFriction = 0.0;
                if (law.matched) {
                    p.m_contactPointFlags |= BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING;
                    p.m_combinedContactStiffness1 = s.stiffness;
                    p.m_combinedContactDamping1 = s.damping;
                }
            }
        }
        btDiscreteDynamicsWorld::solveConstraints(info);
    }
};

// call f(manifold, point) for every manifold point in contact: not apart, or pushed by the last
// solve (split impulse leaves a point that carries the weight a hair apart, distance ~1e-9 m)
template <class F>
void for_each_touching_point(const btDynamicsWorld& world, F&& f) {
    btDispatcher* d = const_cast<btDynamicsWorld&>(world).getDispatcher();
    for (int m = 0; m < d->getNumManifolds(); ++m) {
        const btPersistentManifold* pm = d->getManifoldByIndexInternal(m);
        for (int i = 0; i < pm->getNumContacts(); ++i) {
            const btManifoldPoint& p = pm->getContactPoint(i);
            if (!(p.getDistance() > 0.0) || p.m_appliedImpulse > 0.0) f(*pm, p);
        }
    }
}

class BulletBackend : public Backend {
public:
    std::string name() const override { return "bullet"; }
    std::string engine_version() const override {
        return "Bullet " + std::to_string(btGetVersion() / 100) + "." + std::to_string(btGetVersion() % 100) +
               " (double precision, btDiscreteDynamicsWorld, sequential impulse)";
    }
    void build(const Scene& scene, const RunOptions& options) override;
    double time_step() const override { return dt_; }
    double critical_step() const override { return 0.0; }
    StepStatus step() override;
    Sample sample() const override;
    std::string failure() const override { return failure_; }
    std::vector<std::string> notes() const override { return notes_; }
    std::vector<ContactPoint> contact_points() const override;

private:
    void clear();
    /// centre of mass of block i, world, m
    Vec3 com(int i) const { return eig(bodies_[i]->getCenterOfMassPosition()); }
    /// rotation block frame → world of block i (Bullet's body frame is the principal axes)
    Quat orientation(int i) const { return eig(bodies_[i]->getOrientation()) * Quat(blocks_[i].principal.transpose()); }
    Scene scene_;
    std::vector<RigidBlock> blocks_;
    std::unique_ptr<btDefaultCollisionConfiguration> config_;
    std::unique_ptr<btCollisionDispatcher> dispatcher_;
    std::unique_ptr<btBroadphaseInterface> broadphase_;
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
    std::unique_ptr<CairnWorld> world_;
    std::vector<std::unique_ptr<btCollisionShape>> shapes_;
    std::vector<std::unique_ptr<btRigidBody>> bodies_;   // one per scene block
    bool matched_ = false;
    double dt_ = 0.0;
    double t_ = 0.0;
    double external_work_ = 0.0;
    std::string failure_;
    std::vector<std::string> notes_;
};

void BulletBackend::clear() {
    if (world_)
        for (auto& b : bodies_) world_->removeRigidBody(b.get());
    bodies_.clear();
    world_.reset();
    solver_.reset();
    broadphase_.reset();
    dispatcher_.reset();
    config_.reset();
    shapes_.clear();
}

void BulletBackend::build(const Scene& scene, const RunOptions& options) {
    clear();
    scene_ = scene;
    notes_.clear();
    failure_.clear();
    t_ = 0.0;
    external_work_ = 0.0;
    EngineSettings settings(scene_, "bullet");
    matched_ = contact_mode(settings, options) == "matched";
    const long long iterations = settings.integer("iterations", 50, 1);
    // matched springs read the depth of the shapes grown by the margin (a hull's lies outside its
    // corners): 1e-3 m there is a millimetre of spring at every touching joint (docs/backends.md)
    const double margin = settings.number("margin", matched_ ? 1e-5 : 1e-3, 0.0);
    const long long directions = settings.integer("friction_directions", 2, 1);
    const double restitution_threshold = settings.number("restitution_threshold", 0.2, 0.0);
    settings.finish();
    if (directions > 2) throw Error("bullet setting 'friction_directions' must be 1 or 2");
    dt_ = engine_time_step(scene_);
    blocks_ = rigid_blocks(scene_, "bullet");

    // a fresh world per build: no state survives from an earlier run
    config_ = std::make_unique<btDefaultCollisionConfiguration>();
    dispatcher_ = std::make_unique<btCollisionDispatcher>(config_.get());
    broadphase_ = std::make_unique<btDbvtBroadphase>();
    solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
    world_ = std::make_unique<CairnWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(), config_.get());
    world_->scene = &scene_;
    world_->blocks = &blocks_;
    world_->law = {scene_.contact.friction, scene_.contact.restitution, matched_};
    world_->setGravity(bt(scene_.gravity));
    world_->getDispatchInfo().m_enableSatConvex = true;
    btContactSolverInfo& info = world_->getSolverInfo();
    info.m_numIterations = static_cast<int>(iterations);
    info.m_restitutionVelocityThreshold = restitution_threshold;
    if (directions == 2) info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
    if (matched_) {
        // the spring must carry the momentum: no split impulse
        info.m_splitImpulse = 0;
    } else {
        // every penetration is corrected by split impulse (positions only): no Baumgarte rebound
        info.m_splitImpulse = 1;
        info.m_splitImpulsePenetrationThreshold = 0.0;
    }

    const double linear_damping = 1.0 - std::exp(-scene_.damping.alpha);
    for (const RigidBlock& b : blocks_) {
        std::unique_ptr<btCollisionShape> shape;
        if (b.is_box) {
            shape = std::make_unique<btBoxShape>(bt(b.half_extents));
        } else {
            auto hull = std::make_unique<btConvexHullShape>();
            for (const Vec3& c : b.corners) hull->addPoint(bt(b.principal.transpose() * (c - b.com)), false);
            hull->recalcLocalAabb();
            hull->initializePolyhedralFeatures();
            shape = std::move(hull);
        }
        shape->setMargin(margin);
        // body frame: centre of mass, principal axes
        btTransform start;
        start.setOrigin(bt(b.com_world));
        start.setRotation(bt(Quat(b.orientation.toRotationMatrix() * b.principal)));
        double mass = b.fixed ? 0.0 : b.mass;
        btRigidBody::btRigidBodyConstructionInfo ci(mass, nullptr, shape.get(),
                                                    b.fixed ? btVector3(0, 0, 0) : bt(b.moments));
        ci.m_startWorldTransform = start;
        ci.m_friction = scene_.contact.friction;
        ci.m_restitution = scene_.contact.restitution;
        ci.m_linearDamping = b.fixed ? 0.0 : linear_damping;
        ci.m_angularDamping = b.fixed ? 0.0 : linear_damping;
        auto body = std::make_unique<btRigidBody>(ci);
        body->setUserIndex(b.index);
        body->setActivationState(DISABLE_DEACTIVATION);
        if (!b.fixed) {
            const BlockDef& d = scene_.blocks[b.index];
            body->setLinearVelocity(bt(d.velocity));
            body->setAngularVelocity(bt(d.angular_velocity));
        }
        world_->addRigidBody(body.get());
        shapes_.push_back(std::move(shape));
        bodies_.push_back(std::move(body));
    }

    std::ostringstream n;
    auto note = [&](const std::string& line) { notes_.push_back(line); };
    n << "contact_mode: " << (matched_ ? "matched" : "rigid");
    note(n.str());
    n.str("");
    n << "time_step: " << dt_ << " s" << (scene_.run.dt ? "" : " (dt = auto: engine default 1e-4 s)");
    note(n.str());
    note("solver: sequential impulse, " + std::to_string(iterations) + " iterations, stepSimulation(dt, 1, dt)");
    n.str("");
    n << "margin: " << margin << " m (inside box half extents; hulls use their corners)";
    note(n.str());
    if (matched_)
        note("matched contact: kn*A/4 per manifold point (A = smaller area of the two faces most aligned with the contact normal), "
             "erp = h*k/(h*k+c), cfm = 1/(h*k+c), split impulse off");
    else
        note("rigid contact: split impulse on with threshold 0 (no Baumgarte rebound), restitution " +
             std::to_string(scene_.contact.restitution));
    n.str("");
    n << "restitution_threshold: " << restitution_threshold << " m/s (restitution is zero below it)";
    note(n.str());
    note("friction: mu per contact point along " + std::to_string(directions) +
         " direction(s), each clamped separately (a box, not a cone); no elastic stick before slip");
    if (scene_.damping.alpha > 0) {
        n.str("");
        n << "mass-proportional damping: body damping 1-exp(-alpha) = " << linear_damping
          << " (v *= exp(-alpha*dt) each step, linear and angular)";
        note(n.str());
    }
    note("deactivation: disabled on every body");
    for (const auto& line : rigid_engine_notes(scene_)) note(line);
}

StepStatus BulletBackend::step() {
    // lever arm (world) of a block's material point from its body's centre of mass
    auto arm = [&](int block, const Vec3& point) {
        btRigidBody* body = bodies_[block].get();
        const RigidBlock& b = blocks_[block];
        Quat q = eig(body->getOrientation()) * Quat(b.principal.transpose());
        Vec3 com = eig(body->getCenterOfMassPosition());
        return Vec3(block_point_world(b, com, q, point) - com);
    };
    // loads at their material points: the force through Bullet (cleared after every step), the
    // moment as this step's angular impulse added to the body's spin before the step. Bullet's
    // solver (btSequentialImpulseConstraintSolver::setupFrictionConstraint) adds the external FORCE
    // impulse to the velocity its contacts and friction act on but not the external TORQUE impulse,
    // which it adds after the solve: a load with a moment would then escape friction every step and
    // the block creep at 1.5 H dt/m under a sub-limit push at its base (7.4e-4 m/s at dt 1e-4 s).
    std::vector<AppliedLoad> loads;
    applied_loads(scene_, t_, loads);
    // work of the loads: force at the start of the step times the point's mean velocity
    auto power = [&]() {
        return cairn::load_power(loads, [&](int block, const Vec3& point) {
            btRigidBody* body = bodies_[block].get();
            return Vec3(eig(body->getLinearVelocity()) + eig(body->getAngularVelocity()).cross(arm(block, point)));
        });
    };
    double p0 = power();
    for (const AppliedLoad& l : loads) {
        btRigidBody* body = bodies_[l.block].get();
        body->applyCentralForce(bt(l.force));
        const btVector3 moment = bt(arm(l.block, l.point).cross(l.force));
        body->setAngularVelocity(body->getAngularVelocity() + body->getInvInertiaTensorWorld() * moment * dt_);
    }
    world_->stepSimulation(dt_, 1, dt_);
    double p1 = power();
    t_ += dt_;
    external_work_ += 0.5 * (p0 + p1) * dt_;
    failure_ = non_finite_block(blocks_, t_, [&](int i) { return com(i); });
    return failure_.empty() ? StepStatus::ok : StepStatus::unstable;
}

Sample BulletBackend::sample() const {
    Sample s = rigid_sample(
        t_, blocks_, scene_,
        [&](const RigidBlock& b) {
            const btRigidBody* body = bodies_[b.index].get();
            BlockState st;
            st.position = com(b.index);
            st.orientation = orientation(b.index).normalized();
            st.velocity = eig(body->getLinearVelocity());
            st.angular_velocity = eig(body->getAngularVelocity());
            return st;
        },
        [&](int i) { return com(i); }, [&](int i) { return orientation(i); });
    s.energy.external = external_work_;
    for_each_touching_point(*world_, [&](const btPersistentManifold&, const btManifoldPoint& p) {
        ++s.contacts;
        if (matched_ && p.getDistance() < 0.0) {   // the spring is compressed only below zero distance
            double k = p.m_combinedContactStiffness1;
            s.energy.contact += 0.5 * k * p.getDistance() * p.getDistance();
        }
    });
    return s;
}

// the manifold points in contact; forces are the last step's solver impulses over the step
std::vector<ContactPoint> BulletBackend::contact_points() const {
    std::vector<ContactPoint> out;
    for_each_touching_point(*world_, [&](const btPersistentManifold& pm, const btManifoldPoint& p) {
        ContactPoint c;
        c.position = eig(p.m_positionWorldOnB);
        c.normal = eig(p.m_normalWorldOnB);   // from body 1 towards body 0
        // the solver pushes body 0 along the normal and the friction directions
        c.normal_force = (p.m_appliedImpulse / dt_) * c.normal;
        c.shear_force = (p.m_appliedImpulseLateral1 * eig(p.m_lateralFrictionDir1) +
                         p.m_appliedImpulseLateral2 * eig(p.m_lateralFrictionDir2)) / dt_;
        c.block_a = pm.getBody0()->getUserIndex();
        c.block_b = pm.getBody1()->getUserIndex();
        out.push_back(c);
    });
    return out;
}

}  // namespace

BackendInfo bullet_backend_info() {
    BackendInfo info;
    info.name = "bullet";
    info.description = "Bullet 3 rigid bodies (double precision); contact rigid or matched (kn*A per manifold)";
    info.capabilities = bullet_capabilities();
    info.solver = "sequential impulses, 50 iterations, split impulse";
    info.make = [] { return std::make_unique<BulletBackend>(); };
    return info;
}

}  // namespace cairn

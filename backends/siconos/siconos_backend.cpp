#include "siconos/siconos_backend.hpp"

#include "siconos_relation.hpp"

#include <SolverOptions.h>

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "applied_loads.hpp"
#include "engine_settings.hpp"
#include "error.hpp"
#include "rigid_blocks.hpp"
#include "rigid_sample.hpp"
#include "siconos_contacts.hpp"

namespace cairn {

std::vector<FeatureSupport> siconos_capabilities();

namespace {

// the most free blocks a scene may have: NSGS iterations grow with a stack's height, and a
// 16-block wall already takes about 0.1 s a step (docs/backends.md)
constexpr int kMaxFreeBlocks = 64;

// the solver names of the settings table and Siconos's numerics ids
int solver_id(const std::string& name) {
    if (name == "nsn") return SICONOS_FRICTION_3D_NSN_AC;
    if (name == "admm") return SICONOS_FRICTION_3D_ADMM;
    return SICONOS_FRICTION_3D_NSGS;
}

// the solver outcome of the step being computed: Siconos reports it through a plain function
// pointer, so the backend stepping on this thread leaves its counter here
thread_local int* solver_failures = nullptr;

void count_solver_failure(int info, Simulation*) {
    if (info != 0 && solver_failures) ++*solver_failures;
}

// Siconos's matrices are 6 × 6 to a few hundred rows: a threaded OpenBLAS spends more time
// yielding between its threads than computing (a third of a rocking run). One thread, when the
// BLAS in use is OpenBLAS (found at run time: the BLAS is chosen by the system's alternatives)
void single_threaded_blas() {
    static const bool done = [] {
        using SetThreads = void (*)(int);
        if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
        return true;
    }();
    (void)done;
}

SP::SiconosVector vector3(const Vec3& v) {
    auto out = std::make_shared<SiconosVector>(3);
    for (int k = 0; k < 3; ++k) (*out)(k) = v[k];
    return out;
}

class SiconosBackend : public Backend {
public:
    ~SiconosBackend() override { release(); }
    std::string name() const override { return "siconos"; }
    std::string engine_version() const override { return "Siconos 4.4 (kernel, numerics)"; }
    void build(const Scene& scene, const RunOptions& options) override;
    double time_step() const override { return dt_; }
    double critical_step() const override { return 0.0; }
    StepStatus step() override;
    Sample sample() const override;
    std::string failure() const override { return failure_; }
    std::vector<std::string> notes() const override;
    std::vector<ContactPoint> contact_points() const override;

private:
    Vec3 com(int block) const;
    Quat orientation(int block) const;
    Vec3 point_velocity(int block, const Vec3& world_point) const;
    Corners world_corners(int block) const;
    double load_power() const;
    void set_forces();
    void update_contacts();
    void release();

    Scene scene_;
    std::vector<RigidBlock> blocks_;
    std::vector<SP::NewtonEulerDS> bodies_;   // per block, null for fixed blocks
    std::vector<SP::SiconosVector> force_, moment_;
    SP::NonSmoothDynamicalSystem nsds_;
    SP::MoreauJeanOSI osi_;
    SP::FrictionContact problem_;
    SP::TimeStepping sim_;
    SP::NonSmoothLaw law_;
    struct Linked {
        SP::Interaction inter;
        std::shared_ptr<PointContactR> relation;
        GapContact geometry;
    };
    // the contacts of each near pair (free block first); a pair keeping its number of points keeps
    // its interactions (their impulses start the solver), moved to the new points
    std::map<std::pair<int, int>, std::vector<Linked>> linked_;
    double dt_ = 0.0;
    double t_ = 0.0;
    double theta_ = 0.5;
    double margin_ = 0.0;
    std::string solver_;
    double tolerance_ = 0.0;
    long long iterations_ = 0;
    bool stop_unconverged_ = false;   // a step missing the solver tolerance stops the run
    double worst_residual_ = 0.0;     // largest residual the solver ended a step with
    long long solver_iterations_ = 0; // the solver's iterations over the run
    double initial_energy_ = 0.0;
    double external_work_ = 0.0;
    int solver_failures_ = 0;      // steps whose friction-contact solve missed its tolerance
    int newton_failures_ = 0;      // steps whose Newton loop did not converge
    double worst_gap_ = 0.0;       // deepest overlap met, m (≤ 0)
    std::string failure_;
    std::vector<std::string> notes_;
};

Vec3 SiconosBackend::com(int block) const {
    if (!bodies_[block]) return blocks_[block].com_world;
    const SiconosVector& q = *bodies_[block]->q();
    return {q(0), q(1), q(2)};
}

Quat SiconosBackend::orientation(int block) const {
    if (!bodies_[block]) return blocks_[block].orientation;
    const SiconosVector& q = *bodies_[block]->q();
    return Quat(q(3), q(4), q(5), q(6)).normalized();
}

Vec3 SiconosBackend::point_velocity(int block, const Vec3& p) const {
    if (!bodies_[block]) return Vec3::Zero();
    const SiconosVector& v = *bodies_[block]->twist();
    SiconosVector w(3);
    bodies_[block]->angularVelocity(true, w);
    return Vec3(v(0), v(1), v(2)) + Vec3(w(0), w(1), w(2)).cross(p - com(block));
}

Corners SiconosBackend::world_corners(int block) const {
    Corners w;
    const Vec3 c = com(block);
    const Quat q = orientation(block);
    for (int i = 0; i < 8; ++i) w[i] = block_point_world(blocks_[block], c, q, blocks_[block].corners[i]);
    return w;
}

// Siconos's objects hold each other through shared pointers: the integrator and the problem hold
// the simulation that holds them, the integrator holds the systems graph whose vertices hold the
// integrator, and interactions still in the topology at the end stay in a loop of their own (found
// by LeakSanitizer on a rocking run). Cut all three so that the model is freed, not leaked whole
void SiconosBackend::release() {
    if (osi_) {
        osi_->setSimulationPtr(nullptr);
        osi_->setDynamicalSystemsGraph(nullptr);
    }
    if (problem_) problem_->setSimulationPtr(nullptr);
    if (nsds_) {
        for (const auto& [pair, list] : linked_)
            for (const Linked& l : list) nsds_->removeInteraction(l.inter);
    }
    linked_.clear();
    bodies_.clear();
    sim_.reset();
    problem_.reset();
    osi_.reset();
    nsds_.reset();
}

void SiconosBackend::build(const Scene& scene, const RunOptions& options) {
    release();
    scene_ = scene;
    failure_.clear();
    linked_.clear();
    bodies_.clear();
    force_.clear();
    moment_.clear();
    t_ = external_work_ = worst_gap_ = worst_residual_ = 0.0;
    solver_iterations_ = 0;
    solver_failures_ = newton_failures_ = 0;
    single_threaded_blas();
    EngineSettings settings(scene_, "siconos");
    if (contact_mode(settings, options) != "rigid")
        throw Error("backend siconos has only rigid (non-smooth) contact: contact mode 'matched' needs a penalty "
                    "spring; use dem, bullet, ode or mujoco");
    dt_ = settings.number("time_step", engine_time_step(scene_), 1e-9);
    theta_ = settings.number("theta", 0.5, 0.0);
    if (theta_ > 1.0)
        throw Error("backends.siconos.theta = " + std::to_string(theta_) + " is not in [0, 1]");
    solver_ = settings.word("solver", "nsgs", {"nsgs", "nsn", "admm"});
    tolerance_ = settings.number("tolerance", 1e-5, 1e-16);
    iterations_ = settings.integer("iterations", 1000, 1);
    stop_unconverged_ = settings.word("on_unconverged", "warn", {"warn", "stop"}) == "stop";
    settings.finish();
    blocks_ = rigid_blocks(scene_, "siconos");
    int free_blocks = 0;
    for (const RigidBlock& b : blocks_) free_blocks += b.fixed ? 0 : 1;
    if (free_blocks > kMaxFreeBlocks)
        throw Error("backend siconos: " + std::to_string(free_blocks) + " free blocks exceed its limit of " +
                    std::to_string(kMaxFreeBlocks) + " (its solver needs about 0.1 s a step for 16 stacked blocks)");

    // contacts are made for pairs closer than a margin, so the scheme can close them before they
    // meet: twice the largest block's step of travel at 5 m/s, at least 0.1 mm
    margin_ = std::max(1e-4, 2.0 * 5.0 * dt_);

    nsds_ = std::make_shared<NonSmoothDynamicalSystem>(0.0, 1e12);
    for (const RigidBlock& b : blocks_) {
        if (b.fixed) {
            bodies_.push_back(nullptr);
            force_.push_back(nullptr);
            moment_.push_back(nullptr);
            continue;
        }
        const BlockDef& d = scene_.blocks[b.index];
        auto q = std::make_shared<SiconosVector>(7);
        for (int k = 0; k < 3; ++k) (*q)(k) = b.com_world[k];
        (*q)(3) = b.orientation.w();
        (*q)(4) = b.orientation.x();
        (*q)(5) = b.orientation.y();
        (*q)(6) = b.orientation.z();
        // twist: centre-of-mass velocity in the world, angular velocity in the body frame
        auto v = std::make_shared<SiconosVector>(6);
        const Vec3 w_body = b.orientation.conjugate() * d.angular_velocity;
        for (int k = 0; k < 3; ++k) {
            (*v)(k) = d.velocity[k];
            (*v)(3 + k) = w_body[k];
        }
        auto inertia = std::make_shared<SimpleMatrix>(3, 3);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) (*inertia)(i, j) = b.inertia(i, j);
        auto body = std::make_shared<NewtonEulerDS>(q, v, b.mass, inertia);
        force_.push_back(vector3(b.mass * scene_.gravity));
        moment_.push_back(vector3(Vec3::Zero()));
        body->setFExtPtr(force_.back());
        body->setIsMextExpressedInInertialFrame(true);
        body->setMExtPtr(moment_.back());
        nsds_->insertDynamicalSystem(body);
        bodies_.push_back(body);
    }
    law_ = std::make_shared<NewtonImpactFrictionNSL>(scene_.contact.restitution, 0.0, scene_.contact.friction, 3);
    osi_ = std::make_shared<MoreauJeanOSI>(theta_);
    problem_ = std::make_shared<FrictionContact>(3, solver_id(solver_));
    problem_->numericsSolverOptions()->dparam[SICONOS_DPARAM_TOL] = tolerance_;
    problem_->numericsSolverOptions()->iparam[SICONOS_IPARAM_MAX_ITER] = static_cast<int>(iterations_);
    auto td = std::make_shared<TimeDiscretisation>(0.0, dt_);
    sim_ = std::make_shared<TimeStepping>(nsds_, td, osi_, problem_);
    sim_->setNewtonTolerance(1e-10);
    sim_->setNewtonMaxIteration(20);
    sim_->setWarnOnNonConvergence(false);
    sim_->setCheckSolverFunction(&count_solver_failure);

    initial_energy_ = 0.0;
    for (const RigidBlock& b : blocks_) {
        if (b.fixed) continue;
        const BlockDef& d = scene_.blocks[b.index];
        initial_energy_ += kinetic_energy(b, b.orientation, d.velocity, d.angular_velocity) +
                           potential_energy(b, scene_.gravity, b.com_world);
    }

    std::ostringstream n;
    auto note = [&](std::ostringstream& s) { notes_.push_back(s.str()); s.str(""); };
    notes_.clear();
    n << "contact_mode: rigid";
    note(n);
    n << "time_step: " << dt_ << " s"
      << (scene_.run.dt ? "" : " (dt = auto: engine default 1e-4 s)");
    note(n);
    n << "integrator: Moreau–Jean, theta " << theta_ << "; Newton loop on the rotations (tolerance 1e-10, 20 "
      << "iterations)";
    note(n);
    n << "contact: Signorini at velocity level, exact Coulomb cone mu " << scene_.contact.friction
      << ", Newton impact law e_n " << scene_.contact.restitution << " (e_t 0); FrictionContact(3) by " << solver_
      << ", tolerance " << tolerance_ << ", " << iterations_ << " iterations; a step missing the tolerance "
      << (stop_unconverged_ ? "stops the run" : "is counted (last note)");
    note(n);
    n << "contact geometry: cairn's face-clipping collider, up to 4 points per pair, made when the gap is below "
      << margin_ << " m (closed by the scheme only when it would close within the step)";
    note(n);
    if (scene_.damping.alpha > 0) {
        n << "mass-proportional damping: forces -alpha m v and -alpha I omega from the start-of-step velocities";
        note(n);
    }
    if (scene_.contact.ks > 0) notes_.push_back("shear stiffness ks: ignored (rigid stick)");
    if (scene_.contact.kn > 0) notes_.push_back("normal stiffness kn: ignored (rigid unilateral contact)");
    if (scene_.damping.beta > 0) notes_.push_back("stiffness-proportional damping: beta ignored (rigid bodies)");
    notes_.push_back("energy: dissipated = initial energy - kinetic - potential + external work (impacts, friction "
                     "and damping together); contact energy 0");
}

// gravity, the loads at the middle of the step and the damping forces, world frame
void SiconosBackend::set_forces() {
    for (size_t i = 0; i < bodies_.size(); ++i) {
        if (!bodies_[i]) continue;
        const RigidBlock& b = blocks_[i];
        Vec3 f = b.mass * scene_.gravity, m = Vec3::Zero();
        if (scene_.damping.alpha > 0) {
            const SiconosVector& v = *bodies_[i]->twist();
            SiconosVector w(3);
            bodies_[i]->angularVelocity(true, w);
            const Mat3 r = orientation(static_cast<int>(i)).toRotationMatrix();
            f -= scene_.damping.alpha * b.mass * Vec3(v(0), v(1), v(2));
            m -= scene_.damping.alpha * r * b.inertia * r.transpose() * Vec3(w(0), w(1), w(2));
        }
        for (int k = 0; k < 3; ++k) {
            (*force_[i])(k) = f[k];
            (*moment_[i])(k) = m[k];
        }
    }
    for (const LoadDef& l : scene_.loads) {
        if (!bodies_[l.block]) continue;
        const double factor = 0.5 * (l.factor(t_) + l.factor(t_ + dt_));
        if (factor == 0.0) continue;
        const Vec3 f = factor * l.force;
        const Vec3 arm = block_point_world(blocks_[l.block], com(l.block), orientation(l.block), l.point) - com(l.block);
        const Vec3 m = arm.cross(f);
        for (int k = 0; k < 3; ++k) {
            (*force_[l.block])(k) += f[k];
            (*moment_[l.block])(k) += m[k];
        }
    }
}

// the point contacts of the current state replace the last step's
void SiconosBackend::update_contacts() {
    auto old = std::move(linked_);
    linked_.clear();
    std::vector<Corners> corners(blocks_.size());
    std::vector<bool> fixed(blocks_.size());
    for (size_t i = 0; i < blocks_.size(); ++i) {
        corners[i] = world_corners(static_cast<int>(i));
        fixed[i] = blocks_[i].fixed;
    }
    for (auto [i, j] : near_pairs(corners, fixed, margin_)) {
        if (fixed[i]) std::swap(i, j);   // the first body of a relation must move
        const std::vector<GapContact> found = gap_contacts(corners[i], corners[j], margin_);
        if (found.empty()) continue;
        auto kept = old.find({i, j});
        const bool reuse = kept != old.end() && kept->second.size() == found.size();
        if (kept != old.end() && !reuse) {
            for (const Linked& l : kept->second) sim_->unlink(l.inter);
            old.erase(kept);
        }
        std::vector<Linked>& list = linked_[{i, j}];
        for (size_t k = 0; k < found.size(); ++k) {
            GapContact c = found[k];
            c.a = i;
            c.b = j;
            worst_gap_ = std::min(worst_gap_, c.gap);
            // body-frame points (b's in the world when b is fixed)
            const Quat qa = orientation(i);
            const Vec3 on_a = qa.conjugate() * (c.on_a - com(i));
            Vec3 on_b = c.on_b, normal = c.normal;
            if (bodies_[j]) {
                const Quat qb = orientation(j);
                on_b = qb.conjugate() * (c.on_b - com(j));
                normal = qb.conjugate() * c.normal;
            }
            if (reuse) {
                Linked l = kept->second[k];
                l.relation->set(on_a.data(), on_b.data(), normal.data());
                l.geometry = c;
                list.push_back(l);
                continue;
            }
            auto relation = std::make_shared<PointContactR>(on_a.data(), on_b.data(), normal.data());
            auto inter = std::make_shared<Interaction>(law_, relation);
            if (bodies_[j]) sim_->link(inter, bodies_[i], bodies_[j]);
            else sim_->link(inter, bodies_[i]);
            list.push_back({inter, relation, c});
        }
        if (reuse) old.erase(kept);
    }
    for (const auto& [pair, list] : old)
        for (const Linked& l : list) sim_->unlink(l.inter);
}

double SiconosBackend::load_power() const {
    std::vector<AppliedLoad> loads;
    applied_loads(scene_, t_, loads);
    return cairn::load_power(loads, [&](int block, const Vec3& point) {
        return point_velocity(block, block_point_world(blocks_[block], com(block), orientation(block), point));
    });
}

StepStatus SiconosBackend::step() {
    if (!failure_.empty()) return StepStatus::unstable;
    const double p0 = load_power();
    update_contacts();
    set_forces();
    int failures = 0;
    solver_failures = &failures;
    try {
        sim_->computeOneStep();
        if (!sim_->isNewtonConverge()) ++newton_failures_;
        sim_->nextStep();
        sim_->clearNSDSChangeLog();   // it keeps every linked and unlinked interaction otherwise
    } catch (const std::exception& e) {
        solver_failures = nullptr;
        failure_ = std::string("Siconos: ") + e.what() + " at t = " + std::to_string(t_) + " s";
        return StepStatus::unstable;
    }
    solver_failures = nullptr;
    solver_failures_ += failures;
    if (!linked_.empty()) solver_iterations_ += problem_->numericsSolverOptions()->iparam[SICONOS_IPARAM_ITER_DONE];
    if (!linked_.empty())
        worst_residual_ = std::max(worst_residual_, problem_->numericsSolverOptions()->dparam[SICONOS_DPARAM_RESIDU]);
    if (failures > 0 && stop_unconverged_) {
        std::ostringstream m;
        m << "Siconos " << solver_ << " did not converge at t = " << t_ << " s: residual "
          << problem_->numericsSolverOptions()->dparam[SICONOS_DPARAM_RESIDU] << " after " << iterations_
          << " iterations, tolerance " << tolerance_ << " (on_unconverged = \"stop\")";
        failure_ = m.str();
        return StepStatus::unstable;
    }
    t_ += dt_;
    external_work_ += 0.5 * (p0 + load_power()) * dt_;
    failure_ = non_finite_block(blocks_, t_, [&](int i) { return com(i); });
    return failure_.empty() ? StepStatus::ok : StepStatus::unstable;
}

Sample SiconosBackend::sample() const {
    Sample s = rigid_sample(
        t_, blocks_, scene_,
        [&](const RigidBlock& b) {
            const auto& body = bodies_[b.index];
            BlockState st;
            st.position = com(b.index);
            st.orientation = orientation(b.index);
            const SiconosVector& v = *body->twist();
            SiconosVector w(3);
            body->angularVelocity(true, w);
            st.velocity = Vec3(v(0), v(1), v(2));
            st.angular_velocity = Vec3(w(0), w(1), w(2));
            return st;
        },
        [&](int i) { return com(i); }, [&](int i) { return orientation(i); });
    s.energy.external = external_work_;
    s.energy.dissipated = initial_energy_ - s.energy.kinetic - s.energy.potential + external_work_;
    // active contacts: those that carried a normal impulse over the last step
    for (const auto& [pair, list] : linked_)
        for (const Linked& l : list) s.contacts += l.inter->lambda(1) && (*l.inter->lambda(1))(0) > 0.0 ? 1 : 0;
    return s;
}

std::vector<std::string> SiconosBackend::notes() const {
    std::vector<std::string> out = notes_;
    std::ostringstream n;
    n << "solver: " << solver_iterations_ << " iterations in all; " << solver_failures_
      << " steps missed the friction-contact tolerance (worst residual "
      << worst_residual_ << "), " << newton_failures_ << " steps ended the Newton loop unconverged ("
      << (sim_ ? sim_->getNewtonCumulativeNbIterations() : 0) << " Newton iterations in all); deepest overlap "
      << -worst_gap_ << " m";
    out.push_back(n.str());
    return out;
}

// the last step's contacts with the impulse of each over the step, as a mean force
std::vector<ContactPoint> SiconosBackend::contact_points() const {
    std::vector<ContactPoint> out;
    for (const auto& [pair, list] : linked_)
        for (const Linked& l : list) {
            if (!l.inter->lambda(1) || (*l.inter->lambda(1))(0) <= 0.0) continue;
            ContactPoint c;
            c.position = 0.5 * (l.geometry.on_a + l.geometry.on_b);
            c.normal = l.geometry.normal;
            c.normal_force = (*l.inter->lambda(1))(0) / dt_ * c.normal;
            // the relation's reaction on a (world force part of its generalized force): its part
            // normal to n is the friction impulse
            const SiconosVector& r = *l.relation->contactForce();
            const Vec3 total(r(0), r(1), r(2));
            c.shear_force = (total - total.dot(c.normal) * c.normal) / dt_;
            c.block_a = l.geometry.a;
            c.block_b = l.geometry.b;
            out.push_back(c);
        }
    return out;
}

}  // namespace

BackendInfo siconos_backend_info() {
    BackendInfo info;
    info.name = "siconos";
    info.description =
        "Siconos 4.4 non-smooth contact dynamics: Moreau–Jean, Signorini and Coulomb cone, Newton impact; rigid only";
    info.capabilities = siconos_capabilities();
    info.solver = "Moreau-Jean theta 0.5, FrictionContact(3) by NSGS, tolerance 1e-5";
    // Siconos 4.4's thread safety is not established: one run at a time
    info.thread_safe = false;
    info.make = [] { return std::make_unique<SiconosBackend>(); };
    return info;
}

}  // namespace cairn

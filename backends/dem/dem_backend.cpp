#include "dem_backend.hpp"

#include <cmath>
#include <memory>
#include <sstream>

#include "error.hpp"
#include "time_step.hpp"
#include "world.hpp"

namespace cairn {

namespace {

class DemBackend : public Backend {
public:
    std::string name() const override { return "dem"; }
    std::string engine_version() const override { return std::string("cairn dem ") + CAIRN_VERSION; }

    void build(const Scene& scene, const RunOptions& options) override {
        scene_ = scene;
        for (const auto& [key, s] : scene_.backend_settings["dem"])
            throw Error(s.origin + ": backends.dem." + key + ": unknown setting of backend dem (it has none yet)");
        for (const auto& b : scene_.blocks)
            if (b.model == BlockModel::deformable && !b.fixed)
                throw Error("backend dem: block '" + b.name +
                            "' asks for the deformable model, which this build does not have yet; "
                            "run with --model rigid");
        std::vector<dem::Block> blocks;
        double min_edge = 1e300;
        for (const auto& def : scene_.blocks) {
            blocks.push_back(dem::make_rigid_block(def, scene_.materials[def.material], scene_.contact.grid_spacing));
            min_edge = std::min(min_edge, blocks.back().min_edge);
        }
        critical_ = dem::critical_step(blocks, scene_.contact);
        if (scene_.run.dt) {
            dt_ = *scene_.run.dt;
        } else {
            if (!(critical_ > 0.0))
                throw Error(scene_.source + ": run.dt = \"auto\": no contact stiffness to derive a step from; give run.dt");
            dt_ = scene_.run.dt_safety * critical_;
        }
        margin_ = scene_.run.contact_margin ? *scene_.run.contact_margin : 0.05 * min_edge;
        world_ = std::make_unique<dem::World>(scene_, dt_, margin_);
    }

    double time_step() const override { return dt_; }
    double critical_step() const override { return critical_; }

    StepStatus step() override {
        if (world_->step()) return StepStatus::ok;
        std::ostringstream m;
        m << "the state is no longer finite (NaN or infinity)";
        failure_ = m.str();
        return StepStatus::unstable;
    }

    Sample sample() const override {
        Sample s;
        s.t = world_->time();
        const auto& blocks = world_->blocks();
        for (const auto& p : scene_.probes) s.probes.push_back(blocks[p.block].world_point(p.point));
        for (const auto& b : blocks) {
            if (b.fixed) continue;
            BlockState st;
            st.position = b.body.x;
            st.orientation = b.body.q;
            st.velocity = b.body.v;
            st.angular_velocity = b.body.omega();
            s.blocks.push_back(st);
        }
        s.energy.kinetic = world_->kinetic();
        s.energy.potential = world_->potential();
        s.energy.contact = world_->energy().contact;
        s.energy.dissipated = world_->energy().dissipated;
        s.energy.external = world_->energy().external;
        s.contacts = world_->active_contacts();
        return s;
    }

    std::string failure() const override { return failure_; }

    std::vector<std::string> notes() const override {
        std::vector<std::string> n;
        auto num = [](double v) {
            std::ostringstream o;
            o.precision(6);
            o << v;
            return o.str();
        };
        n.push_back("model: rigid blocks, central differences (kick-drift-kick), implicit-midpoint rotation");
        n.push_back("critical step of the contact springs (s): " + num(critical_));
        n.push_back("time step (s): " + num(dt_) + (scene_.run.dt ? " (given)" : " (auto)"));
        if (critical_ > 0.0 && dt_ > critical_)
            n.push_back("warning: the time step exceeds the critical step estimate; the run may blow up");
        n.push_back("broad-phase margin (m): " + num(margin_));
        n.push_back("contact refresh interval (steps): " + std::to_string(scene_.run.contact_interval));
        if (world_ && world_->early_refreshes() > 0)
            n.push_back("warning: contact pairs were refreshed early " + std::to_string(world_->early_refreshes()) +
                        " times because a block moved more than half the margin within the interval; "
                        "raise run.contact_margin or lower run.contact_interval");
        n.push_back(std::string("contact damping: ") + to_string(scene_.contact.damping_rule) + " " +
                    num(scene_.contact.damping));
        return n;
    }

private:
    Scene scene_;
    std::unique_ptr<dem::World> world_;
    double dt_ = 0.0, critical_ = 0.0, margin_ = 0.0;
    std::string failure_;
};

}  // namespace

BackendInfo dem_backend_info() {
    BackendInfo info;
    info.name = "dem";
    info.description = "in-house discrete element engine (the paper's contact law), rigid blocks";
    info.capabilities = {
        {"penalty stiffness kn·A", Support::exact, "kn·a per hitting point (corners + virtual grid)"},
        {"normal contact damping", Support::exact, "dashpot per hitting point (ratio ζ or time γ)"},
        {"elastic stick before slip", Support::exact, "shear spring ks·a from a stored stick anchor"},
        {"friction shape", Support::exact, "Coulomb disc per hitting point"},
        {"mass-proportional damping", Support::exact, "α·M, implicit in the kick"},
        {"stiffness-proportional damping", Support::none, "rigid blocks have no element stiffness"},
        {"deformable blocks", Support::none, "not built yet: refused"},
        {"general convex hexahedra", Support::exact, "planar-faced convex hexahedra"},
    };
    info.make = [] { return std::make_unique<DemBackend>(); };
    return info;
}

}  // namespace cairn

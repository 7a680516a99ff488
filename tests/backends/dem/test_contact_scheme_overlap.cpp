// The overlap scheme in use: crossing edges, collinear pairs, independence of block order, of the
// sub-division and of the mesh, a block that holds under a load below the Coulomb limit, and on
// deformable blocks a normal force that is the gradient of the energy booked for it.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "dem/block_builder.hpp"
#include "dem/contact.hpp"
#include "dem/world.hpp"
#include "dem_test_util.hpp"
#include "scene/arch_builder.hpp"
#include "scene/scene_io.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

namespace {

Scene overlap_scene(double friction = 0.6) {
    Scene s = test::stone_scene(friction);
    s.contact.scheme = ContactScheme::overlap;
    return s;
}

// resultant contact force on block 0 of two blocks whose edges cross: A's bottom edge runs along
// x (A turned 45° about x), B's top edge along y (B turned 45° about y); A's edge sits `depth`
// below B's and is shifted 0.05 m along itself, between the paper grid's points
Vec3 crossing_force(ContactScheme scheme, double depth) {
    Scene s = overlap_scene();
    s.contact.scheme = scheme;
    const double h = std::sqrt(0.5);
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0.05, 0, h - depth), false, Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX())));
    add_box(s, "B", Vec3(1, 1, 1), Vec3(0, 0, -h), true, Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY())));
    return test::contact_resultant(s, 0);
}

// time of the first zero crossing of the tilt about y, s (linear interpolation); -1 if none
double first_impact(Backend& b, double duration) {
    double t_prev = 0, th_prev = 0, hit = -1;
    test::run_dem(b, duration, [&](const Sample& s) {
        Eigen::AngleAxisd aa(s.blocks[0].orientation);
        const double th = aa.angle() * aa.axis().y();
        if (hit < 0 && s.t > 0 && th_prev > 0 && th <= 0) hit = t_prev + th_prev / (th_prev - th) * (s.t - t_prev);
        t_prev = s.t;
        th_prev = th;
    });
    return hit;
}

Scene rocking(int subdivision) {
    return load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/paper/rocking.toml",
                      {{"contact.scheme", "\"overlap\""}, {"contact.subdivision", std::to_string(subdivision)}});
}

}  // namespace

TEST_CASE("crossing edges are found: a penalty on the penetration that grows as its cube", "[dem][contact]") {
    const double d = 2e-3;
    const Vec3 f1 = crossing_force(ContactScheme::overlap, d), f2 = crossing_force(ContactScheme::overlap, 2 * d);
    INFO("force at " << d << " m: " << f1.transpose() << ", at twice: " << f2.transpose());
    // the overlap of two crossing wedges is a cone with its apex at the crossing: self-similar in
    // the depth, so ∫kn·d dA scales as depth³ exactly (rounding only)
    CHECK(f1.z() > 0.0);
    CHECK(f2.z() / f1.z() == Approx(8.0).epsilon(1e-9));
    // symmetric crossing: the push is straight up
    CHECK(f1.head<2>().norm() < 1e-9 * f1.z());
    // the paper's node-to-face rule sees no hitting point inside B and misses it
    CHECK(crossing_force(ContactScheme::paper, d).norm() == 0.0);
}

namespace {

// two voussoirs of a 25-voussoir arch (faces meeting at 3.6° along the intrados edge), the upper
// one pushed `depth` into the lower (held) one across their joint: its resultant contact force
Vec3 joint_force(double depth, Vec3& normal, double& area) {
    Scene s = overlap_scene();
    const ArchSpec arch{25, 2.0, 0.2355, 0.5};
    const double a = M_PI * 5 / arch.voussoirs;   // the joint between V5 and V6
    normal = Vec3(std::sin(a), 0.0, std::cos(a));  // from V5 into V6
    area = arch.thickness * arch.depth;
    for (int i : {4, 5}) {
        BlockDef b;
        b.name = "V" + std::to_string(i + 1);
        b.shape = Shape::hexahedron;
        b.corners = arch_voussoir(arch, i);
        if (i == 5)
            for (auto& c : b.corners) c -= depth * normal;
        b.fixed = i == 4;
        s.blocks.push_back(b);
    }
    return test::contact_resultant(s, 1);
}

}  // namespace

TEST_CASE("a joint between voussoirs pushes along its normal only", "[dem][contact][arch]") {
    // the joint face of each voussoir overhangs the other's intrados by 3.6° at the shared edge;
    // measuring a point's depth behind the intrados instead of the joint it entered through
    // pushed the upper voussoir along the intrados normal (54 % of the joint force at 1 mm)
    for (double depth : {1e-4, 1e-3}) {
        Vec3 n;
        double area = 0.0;
        const Vec3 f = joint_force(depth, n, area);
        const double kn = 3e7, expected = kn * depth * area;
        INFO("depth " << depth << " m: force " << f.transpose() << " N, kn·d·A = " << expected << " N");
        // uniform penetration over the joint: kn·d·A, less at most strips of width d along its
        // edges that lie nearer another side (relative area d·perimeter/A = 2d(1/t + 1/D): 1.25 %
        // at 1 mm); measured 0.41 %: the strip along the intrados edge only, whose side the
        // joint faces (the others run across it and keep the quarter-edge tolerance)
        CHECK(f.dot(n) == Approx(expected).epsilon(2.0 * depth * (1.0 / 0.2355 + 1.0 / 0.5) + 1e-6));
        // the sliver along the intrados edge pushes along the intrados normal: kn·D·d²/2, that is
        // d/(2t) of the joint force (0.2 % at 1 mm)
        CHECK((f - f.dot(n) * n).norm() <= expected * depth / 0.2355);
    }
}

TEST_CASE("contact forces act as collinear pairs: a free pair keeps its angular momentum", "[dem][contact]") {
    Scene s = overlap_scene(0.5);
    s.gravity = Vec3::Zero();
    add_box(s, "A", Vec3(0.5, 0.4, 0.3), Vec3(0, 0, 0), false);
    add_box(s, "B", Vec3(0.4, 0.5, 0.3), Vec3(0.62, 0.1, 0.05), false, Quat(Eigen::AngleAxisd(0.3, Vec3(0.2, 0.5, 1).normalized())));
    s.blocks[1].velocity = Vec3(-0.5, 0.05, 0);
    s.blocks[1].angular_velocity = Vec3(0.3, -0.2, 1.0);
    dem::World w(s, 0.05);
    w.start(2e-5);
    auto momentum = [&] {
        Vec3 l = Vec3::Zero();
        for (const auto& b : w.blocks()) l += b.body.mass * b.body.x.cross(b.body.v) + b.body.L;
        return l;
    };
    const Vec3 l0 = momentum();
    int touched = 0;
    for (int i = 0; i < 10000; ++i) {
        const bool ok = w.step();
        INFO("step " << i << ": " << w.failure());
        REQUIRE(ok);
        touched = std::max(touched, w.active_contacts());
    }
    REQUIRE(touched > 0);
    // every force pair is equal and opposite at one point: only rounding changes L
    CHECK((momentum() - l0).norm() < 1e-12 * (l0.norm() + 1.0));
}

TEST_CASE("renaming and reordering equal blocks gives the same trajectory", "[dem][contact]") {
    // two equal bricks stacked and a third beside the lower one, touching: equal sides of equal
    // blocks, so the target is chosen by geometry (the lower one, the one on the -x side)
    // started as placed, and settled under gravity first (no spring slips while settling, and the
    // settling takes a fixed count of steps: the settled state does not depend on the order)
    auto stack = [](ContactScheme scheme, bool reversed, bool settle) {
        Scene s = overlap_scene(0.6);
        s.contact.scheme = scheme;
        s.run.settle = settle;
        s.run.duration = 0.3;
        const double d = 0.2 * 9.81 * 2600 / 3e7;   // static penetration of a 0.2 m block
        struct Item { std::string name; Vec3 at; };
        std::vector<Item> items = {{"lower", Vec3(0, 0, 0.1 - d)}, {"beside", Vec3(0.4, 0, 0.1 - d)},
                                   {"upper", Vec3(0.05, 0.02, 0.3 - 2 * d)}};
        if (reversed) std::swap(items[0], items[2]), items[0].name = "z1", items[1].name = "m2", items[2].name = "a3";
        for (const auto& it : items) add_box(s, it.name, Vec3(0.4, 0.4, 0.2), it.at, false);
        const size_t upper = reversed ? 0 : 2;
        s.blocks[upper].velocity = Vec3(0.05, 0, 0);
        add_box(s, "base", Vec3(2, 2, 0.5), Vec3(0, 0, -0.25), true);
        auto b = test::build_dem(s);
        std::vector<Vec3> path;
        test::run_dem(*b, 0.3, [&](const Sample& x) { path.push_back(x.blocks[upper].position); });
        return path;
    };
    for (bool settle : {false, true})
        for (auto scheme : {ContactScheme::overlap, ContactScheme::paper}) {
            const auto a = stack(scheme, false, settle), b = stack(scheme, true, settle);
            REQUIRE(a.size() == b.size());
            double worst = 0.0;
            for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, (a[i] - b[i]).norm());
            INFO((scheme == ContactScheme::paper ? "paper" : "overlap") << (settle ? ", settled" : ", as placed")
                                                                       << ": largest difference " << worst << " m");
            // the same physics; only the order of sums differs: round-off
            CHECK(worst < 1e-10);
        }
}

TEST_CASE("rocking at the paper's kn: the first impact does not depend on the sub-division or the mesh", "[dem][contact][rocking]") {
    double t[3];
    int i = 0;
    for (int n : {2, 4, 8}) {
        auto b = test::build_dem(rocking(n));
        t[i++] = first_impact(*b, 1.2);
    }
    INFO("first impact n = 2, 4, 8: " << t[0] << ", " << t[1] << ", " << t[2] << " s");
    // the normal force is exact for any n; the shear converges as n grows: 0.2 % (measured 0.12 %)
    CHECK(t[1] == Approx(t[0]).epsilon(2e-3));
    CHECK(t[2] == Approx(t[0]).epsilon(2e-3));
    Scene s = rocking(2);
    s.blocks[0].model = BlockModel::deformable;   // 2 x 2 x 2 mesh in the scene
    s.blocks[0].mesh.mass = MassScheme::corrected;
    auto d = test::build_dem(s);
    const double td = first_impact(*d, 1.2);
    INFO("deformable 2 x 2 x 2, corrected mass: " << td << " s");
    // the mesh changes neither the contact integral nor (E = 30 GPa) the motion: 0.2 % as above
    CHECK(td == Approx(t[0]).epsilon(2e-3));
}

TEST_CASE("a block loaded below the Coulomb limit with part of its base lifted holds", "[dem][contact][friction]") {
    // paper case (c), sticking: H = 0.5 W at the centre of a 0.5 m cube, μ = 0.6. The moment puts
    // the resultant 0.125 m off centre, beyond the kern (B/6 = 0.083 m): a triangular pressure
    // over 3·(0.25 − 0.125) = 0.375 m of the base, so the contact area is 0.1875 m² and the
    // elastic shear H/(ks·A) = 1594.125/(3e7·0.1875) = 2.83e-4 m
    const double elastic = 1594.125 / (3e7 * 0.1875);
    for (double zeta : {0.0, 0.1}) {
        Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/paper/friction_stick.toml",
                             {{"contact.scheme", "\"overlap\""}, {"run.duration", "5.0"}, {"loads.H.ramp", "0.2"}});
        // the load ramped in 0.2 s (the shipped scene ramps it over 8 s for its quasi-static
        // reference); the scene's own damping replaced by the one under test
        s.contact.damping_rule = zeta > 0 ? ContactDampingRule::ratio : ContactDampingRule::none;
        s.contact.damping = zeta;
        auto b = test::build_dem(s);
        const double x0 = b->sample().probes[0].x();   // probe "base": the centre of the bottom face
        double worst = 0.0, early = 0.0, late = 0.0;
        int n_early = 0, n_late = 0;
        test::run_dem(*b, 5.0, [&](const Sample& x) {
            const double u = x.probes[0].x() - x0;
            worst = std::max(worst, std::abs(u));
            if (x.t >= 1.0 && x.t < 2.0) early += u, ++n_early;
            if (x.t >= 4.0) late += u, ++n_late;
        });
        early /= n_early;
        late /= n_late;
        INFO("zeta " << zeta << ": largest shear " << worst << " m, mean 1-2 s " << early << ", 4-5 s " << late);
        // elastic only: within twice the static estimate (the ramp's overshoot and the block's
        // tilt add to it), and no creep: the mean offset moves less than 5 % of the elastic shear
        // in 3 s (the issue saw 18 mm/s of sliding)
        CHECK(worst < 2.0 * elastic);
        CHECK(std::abs(late - early) < 0.05 * elastic);
    }
}

TEST_CASE("the overlap scheme's reported contact points carry a resting cube's weight", "[dem][contact]") {
    // a 1 m cube pressed into a fixed slab: every sub-contact is reported on the cube's bottom
    // face with the slab's normal, and their forces add up to the one evaluation's resultant
    for (int n : {1, 3}) {
        Scene s = overlap_scene();
        s.contact.subdivision = n;
        s.contact.kn = s.contact.ks = 1e9;
        s.contact.damping_rule = ContactDampingRule::none;   // the spring alone
        test::add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5 - 1e-5), false);
        test::add_box(s, "B", Vec3(2, 2, 0.5), Vec3(0, 0, -0.25), true);
        auto b = dem_backend_info().make();
        RunOptions options;
        options.record_contacts = true;
        b->build(s, options);
        REQUIRE(b->step() == StepStatus::ok);
        const auto points = b->contact_points();
        CAPTURE(n, points.size());
        CHECK(points.size() == size_t(n * n));
        double up = 0.0;
        for (const auto& c : points) {
            CHECK(c.normal.isApprox(Vec3::UnitZ(), 1e-12));
            CHECK(std::abs(c.position.z()) <= 2e-5);   // where both blocks take it: between the two faces
            CHECK(std::abs(c.position.x()) <= 0.5 + 1e-12);
            CHECK(std::abs(c.position.y()) <= 0.5 + 1e-12);
            up += c.normal_force.z();
        }
        // kn·A·d over the whole face (A = 1 m², d the cube's depth after the step), to rounding
        const double depth = 0.5 - b->sample().blocks[0].position.z();
        CHECK(up == Approx(1e9 * depth).epsilon(1e-9));
    }
}

namespace {

// two deformable voussoirs of a 25-voussoir arch (one hex8 each), V6 pushed 0.1 mm into V5 across
// their joint, every node then moved by up to 30 µm (a fixed pattern) so that both joint faces
// warp; frictionless, undamped, kn = 1e11 N/m³, sub-division n
struct WarpedJoint {
    Scene s;
    std::vector<dem::Block> blocks;
    explicit WarpedJoint(int n) {
        s = overlap_scene();
        s.contact.kn = 1e11;
        s.contact.ks = 0.0;
        s.contact.subdivision = n;
        const ArchSpec arch{25, 2.0, 0.2355, 0.5};
        const double a = M_PI * 5 / arch.voussoirs;
        const Vec3 normal(std::sin(a), 0.0, std::cos(a));
        for (int i : {4, 5}) {
            BlockDef b;
            b.name = "V" + std::to_string(i + 1);
            b.shape = Shape::hexahedron;
            b.corners = arch_voussoir(arch, i);
            if (i == 5)
                for (auto& c : b.corners) c -= 1e-4 * normal;
            b.model = BlockModel::deformable;
            s.blocks.push_back(b);
        }
        for (const auto& d : s.blocks) blocks.push_back(dem::make_block(d, s));
        for (size_t b = 0; b < 2; ++b)
            for (size_t k = 0; k < blocks[b].x.size(); ++k) {
                const double t = 1.3 * double(k) + 0.7 * double(b);
                blocks[b].x[k] += 3e-5 * Vec3(std::sin(t), std::cos(1.7 * t), std::sin(2.3 * t + 1.0));
            }
    }
    // one fresh contact evaluation at rest: the stored energy (J) and the node forces (N)
    double evaluate(std::vector<std::vector<Vec3>>* forces = nullptr) {
        for (auto& b : blocks)
            for (auto& f : b.f) f.setZero();
        dem::ContactSet cs;
        cs.configure(s.contact, 0.05);
        cs.refresh(blocks);
        const double e = cs.apply(blocks, 1e-6).stored;
        if (forces) *forces = {blocks[0].f, blocks[1].f};
        return e;
    }
};

}  // namespace

TEST_CASE("on deformable blocks the overlap's normal force is the gradient of its energy", "[dem][contact][energy]") {
    // The energy booked for a joint is ½kn∫d² dA over the overlap, and the step does the work of
    // the forces actually applied: they must be its gradient with respect to the nodes, or a
    // closed path of the nodes makes energy. On a warped element face the force of one
    // sub-contact applied at its pressure centre by the hex8 shape functions is not: the
    // structures/arch_thick arch (one sub-contact per face) gained 48 % of its motion energy on
    // deformable blocks. Measured on this joint (0.84 MN): before the fix, up to about 6e4 N
    // off on a node of the hitting face at n = 1 and 2e3 N at n = 2; after, at most 88 N.
    for (int n : {1, 2}) {
        WarpedJoint j(n);
        std::vector<std::vector<Vec3>> f;
        const double e = j.evaluate(&f);
        double total = 0.0;   // the joint's normal force, N
        for (const auto& fn : f[0]) total += fn.norm();
        REQUIRE(e > 0.0);
        REQUIRE(total > 1e5);
        // Left out of the force: the change of the integration area as a corner moves along the
        // face (and of the target face's edges), ½kn·d²·(length) against kn·d·(area): at most
        // d/t of the joint force for a depth d over a face of width t = 0.2355 m, here d ≤ 0.16 mm:
        // 6.8e-4 of it, 573 N
        const double bound = 1.6e-4 / 0.2355 * total;
        const double h = 1e-9;   // m: E is piecewise quadratic in the nodes; rounding ~1e-5 N
        for (size_t b = 0; b < 2; ++b)
            for (size_t k = 0; k < j.blocks[b].x.size(); ++k) {
                Vec3 grad;
                for (int c = 0; c < 3; ++c) {
                    const double x0 = j.blocks[b].x[k][c];
                    j.blocks[b].x[k][c] = x0 + h;
                    const double ep = j.evaluate();
                    j.blocks[b].x[k][c] = x0 - h;
                    const double em = j.evaluate();
                    j.blocks[b].x[k][c] = x0;
                    grad[c] = (ep - em) / (2.0 * h);
                }
                INFO("n = " << n << ", block " << b << ", node " << k << ": force " << f[b][k].transpose()
                            << " N, −∇E " << -grad.transpose() << " N, joint force " << total << " N");
                CHECK((f[b][k] + grad).norm() <= bound);
            }
    }
}

TEST_CASE("a brick hanging over the edge of its base is pushed by its bottom only, not by its side measured from the "
          "base's side", "[dem][contact]") {
    // A 0.4 × 0.2 × 0.2 m brick whose width lies 0.109 m over a base's side (y = −0.5) and 0.091 m
    // beyond it, its bottom sunk d = 1.7 mm into the base's top: its inner side (normal +y) faces
    // the base's −y side 0.109 m behind it, and the sliver of it that is under the top lies behind
    // that side. The sliver entered through the top, 1.7 mm away: measured from the side it made a
    // horizontal force as large as the weight it carried (kn·0.4·d·0.109) and, on a deformable
    // brick falling off a wall under El Centro, 8 kJ from nowhere. The bottom alone carries
    // kn·d over its 0.4 × 0.109 m² over the base, and the edge force ½kn·d²·0.4 along −y where
    // that region ends on the base's edge (docs/dem.md), rigid or deformable alike.
    const double kn = 1e9, d = 1.7e-3, inside = 0.109, length = 0.4;
    for (const BlockModel model : {BlockModel::rigid, BlockModel::deformable}) {
        Scene s = overlap_scene();
        s.contact.kn = s.contact.ks = kn;
        add_box(s, "brick", Vec3(length, 0.2, 0.2), Vec3(0, -0.5 + inside - 0.1, 0.1 - d), false);
        add_box(s, "base", Vec3(3.0, 1.0, 0.5), Vec3(0, 0, -0.25), true);
        s.blocks[0].model = model;
        s.blocks[0].mesh.divisions = {2, 1, 1};
        const Vec3 f = test::contact_resultant(s, 0);
        INFO((model == BlockModel::rigid ? "rigid" : "deformable") << ": force " << f.transpose());
        // 74 kN: the region over the base runs to its edge plus the flush tolerance 1e-4 × its
        // shortest edge (0.5 m), as a whole side's face does
        const double carried = kn * d * length * (inside + 1e-4 * 0.5);
        CHECK(f.z() == Approx(carried).epsilon(1e-6));
        const double edge = -0.5 * kn * d * d * length;   // −578 N
        CHECK(f.y() == Approx(edge).margin(1e-6 * carried));
        CHECK(std::abs(f.x()) < 1e-6 * carried);
    }
}

// Small dry brick walls on the paper scheme under the El Centro record, out of plane: they run
// without a block caught behind a neighbour's side, and close their energy balance.
#include <catch2/catch.hpp>

#include <cmath>

#include "dem_test_util.hpp"
#include "support/scene_builder.hpp"
#include "scene/scene_io.hpp"
#include "scene/scene_toml.hpp"
#include "scene/wall_builder.hpp"

using namespace cairn;

namespace {

// `cairn make wall --courses 4 --bricks 4 --bond BOND --scheme paper` (kn = ks = 1e9 N/m³,
// μ 0.7, ζ 0.1, 2600 kg/m³) with the shipped El Centro record along y
Scene wall_under_elcentro(WallBond bond, double duration) {
    Scene s;
    s.materials.push_back(test::stone());
    WallSpec w;
    w.courses = 4;
    w.bricks = 4;
    w.bond = bond;
    add_wall(s, w);
    s.contact.scheme = ContactScheme::paper;   // written to the file, so no overlap key comes along
    const std::string text = scene_toml(s, "paper-scheme wall test") + "\n[ground_motion.y]\nfile = \"" CAIRN_SOURCE_DIR
                             "/scenarios/data/elcentro_1940_ns.csv\"\n";
    std::vector<Override> set;
    for (const std::string kv : {"contact.kn=1e9", "contact.ks=1e9", "contact.friction=0.7", "contact.damping_ratio=0.1",
                                 "run.output_interval=0.005"})
        set.push_back(parse_override(kv));
    set.push_back(parse_override("run.duration=" + std::to_string(duration)));
    return parse_scene(text, "<paper wall test>", set);
}

// the deepest a corner of one block lies inside another box, m (over every ordered pair)
double deepest_corner(const Scene& s, const Sample& x) {
    std::vector<Vec3> size, centre;
    std::vector<Quat> turn;
    size_t free = 0;
    for (const auto& b : s.blocks) {
        size.push_back(b.size);
        if (b.fixed) {
            centre.push_back(b.position), turn.push_back(b.orientation);
        } else {
            centre.push_back(x.blocks[free].position), turn.push_back(x.blocks[free].orientation);
            ++free;
        }
    }
    double worst = 0.0;
    for (size_t a = 0; a < size.size(); ++a)
        for (size_t b = 0; b < size.size(); ++b) {
            if (a == b) continue;
            for (int c = 0; c < 8; ++c) {
                const Vec3 local(((c & 1) ? 0.5 : -0.5) * size[a].x(), ((c & 2) ? 0.5 : -0.5) * size[a].y(),
                                 ((c & 4) ? 0.5 : -0.5) * size[a].z());
                const Vec3 p = turn[b].conjugate() * (centre[a] + turn[a] * local - centre[b]);
                const Vec3 in = 0.5 * size[b] - p.cwiseAbs();   // > 0 on every axis: inside b
                worst = std::max(worst, in.minCoeff());
            }
        }
    return worst;
}

void check_wall(WallBond bond, double duration, bool standing) {
    const Scene s = wall_under_elcentro(bond, duration);
    auto b = test::build_dem(s);
    double worst_error = 0.0, worst_depth = 0.0, kinetic = 0.0, contact = 0.0, work = 0.0, exchanged = 0.0;
    double potential0 = 0.0, total0 = 0.0;
    long n = 0;
    const bool ok = test::run_dem(*b, duration, [&](const Sample& x) {
        const Energies& e = x.energy;
        if (n == 0) potential0 = e.potential, total0 = e.total();
        worst_error = std::max(worst_error, std::abs(e.total() - total0));
        kinetic = std::max(kinetic, e.kinetic);
        contact = std::max(contact, e.contact);
        work = std::max(work, std::abs(e.external));
        exchanged = std::max(exchanged, std::abs(e.potential - potential0));
        if (n++ % 100 == 0) worst_depth = std::max(worst_depth, deepest_corner(s, x));
    });
    REQUIRE(ok);
    // the energy of the motion: what moved through the ledger (kinetic, stored, the record's work,
    // the potential energy exchanged); 1 % of it, the drift the runner flags
    const double motion = kinetic + contact + work + exchanged;
    INFO("balance error " << worst_error << " J of a motion energy " << motion << " J; deepest corner "
                          << worst_depth << " m");
    CHECK(worst_error < 0.01 * motion);
    // a brick 0.4 x 0.2 x 0.2 m weighs 163 N; the wall of 4 courses carries at most its whole
    // weight W (about 2.8 kN with the closers) on one joint's pivot row. On a corner hitting point
    // (tributary 0.05 x 0.05 m at the 0.1 m grid) the whole W sinks W/(kn·a) = 1.1 mm: 5 mm, five
    // times that, is the most a rocking impact can drive a corner in; a point caught behind a
    // neighbour's side went centimetres in (the run stopped at a quarter edge, 5 cm)
    if (standing) CHECK(worst_depth < 5e-3);
}

}  // namespace

TEST_CASE("paper scheme: a running-bond wall under El Centro keeps its energy and its joints", "[dem][physics][paper]") {
    // 2.5 s: the record's peak (0.32 g at 2.12 s) rocks the wall (t/H = 0.25) over; before the
    // side rule the run made 520 J at 2.23 s (measured balance now 0.5 J of 242 J). Its bricks
    // topple from 2.2 s: a tumbling brick's corner that pokes into a side its face does not hit is
    // not seen by the node-to-face rule (measured 12.7 mm deep), so the depth bound is for standing
    // walls only; later (2.7 s) a brick turning past 45° switches the face that hits and still makes
    // energy (docs/dem.md, Known limits)
    check_wall(WallBond::running, 2.5, false);
}

TEST_CASE("paper scheme: an English-bond wall under El Centro keeps its energy and its joints", "[dem][physics][paper]") {
    // measured: the wall rocks and stands, balance error 0.004 J (0.37 J before the side rule)
    check_wall(WallBond::english, 3.5, true);
}

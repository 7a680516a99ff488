#include "scene/tower_builder.hpp"

#include <cmath>
#include <cstdio>

#include "error.hpp"
#include "scene/scene_builder.hpp"

namespace cairn {

namespace {

struct Segment {
    double a = 0.0, b = 0.0;   // along the wall, m
};

// `segs` without the interval [a, b]
std::vector<Segment> subtract(const std::vector<Segment>& segs, double a, double b, double tiny) {
    std::vector<Segment> out;
    for (const Segment& s : segs) {
        if (s.b <= a + tiny || s.a >= b - tiny) {
            out.push_back(s);
            continue;
        }
        if (a - s.a > tiny) out.push_back({s.a, a});
        if (s.b - b > tiny) out.push_back({b, s.b});
    }
    return out;
}

void check_opening(const TowerSpec& t, const Opening& o, double wall_length, double l, int k) {
    const std::string what = "opening " + std::to_string(k) + ": ";
    if (o.wall < 0 || o.wall > 3) throw Error(what + "wall " + std::to_string(o.wall) + " is not 0-3");
    if (!(o.from >= l - 1e-9 && o.to <= wall_length - l + 1e-9 && o.to > o.from))
        throw Error(what + "from " + std::to_string(o.from) + " m to " + std::to_string(o.to) +
                    " m must lie at least one brick length (" + std::to_string(l) +
                    " m) inside the wall of " + std::to_string(wall_length) + " m");
    if (o.course_from < 0 || o.course_to <= o.course_from || o.course_to > t.courses)
        throw Error(what + "courses " + std::to_string(o.course_from) + " to " + std::to_string(o.course_to) +
                    " do not lie within the tower's " + std::to_string(t.courses) + " courses");
}

}  // namespace

long long tower_brick_count(const TowerSpec& tower) {
    return (long long)tower.courses * (2LL * tower.length + 2LL * tower.width - 2);
}

int add_tower(Scene& scene, const TowerSpec& t) {
    if (t.length < 3 || t.width < 3) throw Error("tower plan " + std::to_string(t.length) + " x " +
                                                 std::to_string(t.width) + " bricks: each side needs at least 3");
    if (t.courses < 1) throw Error("tower courses " + std::to_string(t.courses) + ": need at least 1");
    const double l = t.brick_length, w = 0.5 * l, h = t.brick_height, tiny = 1e-6 * l;
    const double lx = t.length * l, ly = t.width * l;
    const double side[4] = {lx, ly, lx, ly};
    std::vector<Opening> openings = t.openings;
    for (size_t k = 0; k < openings.size(); ++k) {
        Opening& o = openings[k];
        check_opening(t, o, o.wall < 0 || o.wall > 3 ? 0.0 : side[o.wall], l, int(k));
        o.from = w * std::round(o.from / w);   // joints fall on whole brick thicknesses
        o.to = w * std::round(o.to / w);
        for (size_t j = 0; j < k; ++j) {
            // two holes of a wall with their lintels' bearings (w each side) must not meet
            const Opening& p = openings[j];
            if (p.wall == o.wall && o.from - w < p.to + w - tiny && p.from - w < o.to + w - tiny &&
                o.course_from <= p.course_to && p.course_from <= o.course_to)
                throw Error("opening " + std::to_string(k) + " meets opening " + std::to_string(j) +
                            " or its lintel in wall " + std::to_string(o.wall));
        }
    }
    add_box(scene, "base", Vec3(lx + 1.0, ly + 1.0, 0.5), Vec3(0, 0, -0.25), true);
    const int first = int(scene.blocks.size());
    char name[48];
    for (int c = 0; c < t.courses; ++c) {
        const double zc = (c + 0.5) * h;
        for (int wall = 0; wall < 4; ++wall) {
            // walls 0 and 2 run along x through the corners on even courses, 1 and 3 on odd ones
            const bool through = (wall % 2 == 0) == (c % 2 == 0);
            const double len = side[wall];
            std::vector<Segment> segs;
            for (double a = through ? 0.0 : w; a + l <= (through ? len : len - w) + tiny; a += l)
                segs.push_back({a, a + l});
            std::vector<Segment> lintels;
            for (const Opening& o : openings) {
                if (o.wall != wall) continue;
                if (c >= o.course_from && c < o.course_to) segs = subtract(segs, o.from, o.to, tiny);
                if (c == o.course_to) {
                    segs = subtract(segs, o.from - w, o.to + w, tiny);
                    lintels.push_back({o.from - w, o.to + w});
                }
            }
            segs.insert(segs.end(), lintels.begin(), lintels.end());
            for (size_t i = 0; i < segs.size(); ++i) {
                const double s = 0.5 * (segs[i].a + segs[i].b), n = segs[i].b - segs[i].a;
                std::snprintf(name, sizeof name, "c%03d_w%d_%03zu", c, wall, i);
                if (wall % 2 == 0) {
                    const double y = (wall == 0 ? -1.0 : 1.0) * 0.5 * (ly - w);
                    add_box(scene, name, Vec3(n, w, h), Vec3(-0.5 * lx + s, y, zc), false);
                } else {
                    const double x = (wall == 1 ? 1.0 : -1.0) * 0.5 * (lx - w);
                    add_box(scene, name, Vec3(w, n, h), Vec3(x, -0.5 * ly + s, zc), false);
                }
            }
        }
    }
    return first;
}

}  // namespace cairn

#include "scene/wall_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "error.hpp"
#include "scene/scene_builder.hpp"

namespace cairn {

namespace {

// a piece of a course: from a to b along the wall in quarter bricks from its left end (every
// joint and cut lies on that grid, so positions are exact multiples of it), in the front leaf
// (−1), the back leaf (+1) or through the whole thickness (0)
struct Piece {
    int a = 0, b = 0;
    int leaf = 0;
};

std::string text(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}

// the bricks of course c before any opening is cut; a brick is 4 quarters long, 2 thick (English)
std::vector<Piece> course_pieces(const WallSpec& wall, int c) {
    const int n = wall.bricks, length = 4 * n;
    std::vector<Piece> out;
    if (wall.bond == WallBond::english) {
        if (c % 2 == 0) {
            // stretcher course: two leaves of whole bricks
            for (int leaf : {-1, 1})
                for (int i = 0; i < n; ++i) out.push_back({4 * i, 4 * i + 4, leaf});
        } else {
            // header course: end header, queen closer, 2·bricks − 3 headers, queen closer, end header
            out.push_back({0, 2, 0});
            out.push_back({2, 3, 0});
            for (int i = 0; i < 2 * n - 3; ++i) out.push_back({3 + 2 * i, 5 + 2 * i, 0});
            out.push_back({length - 3, length - 2, 0});
            out.push_back({length - 2, length, 0});
        }
        return out;
    }
    int x = c % 2 == 1 && !wall.half_bricks ? 2 : 0;
    const bool halves = c % 2 == 1 && wall.half_bricks;
    for (int i = 0; i < n + (halves ? 1 : 0); ++i) {
        const int len = halves && (i == 0 || i == n) ? 2 : 4;
        out.push_back({x, x + len, 0});
        x += len;
    }
    return out;
}

// `pieces` without the interval [a, b]
std::vector<Piece> cut(const std::vector<Piece>& pieces, int a, int b) {
    std::vector<Piece> out;
    for (const Piece& p : pieces) {
        if (p.b <= a || p.a >= b) {
            out.push_back(p);
            continue;
        }
        if (p.a < a) out.push_back({p.a, a, p.leaf});
        if (p.b > b) out.push_back({b, p.b, p.leaf});
    }
    return out;
}

}  // namespace

std::vector<double> wall_course(const WallSpec& wall, int c) {
    const double l = wall.brick.x();
    std::vector<double> out;
    if (c % 2 == 1 && wall.half_bricks) {
        out.push_back(0.5 * l);
        for (int i = 1; i < wall.bricks; ++i) out.push_back(l);
        out.push_back(0.5 * l);
    } else {
        out.assign(size_t(wall.bricks), l);
    }
    return out;
}

double wall_thickness(const WallSpec& wall) {
    return wall.bond == WallBond::english ? wall.brick.x() : wall.brick.y();
}

std::vector<WallHole> wall_holes(const WallSpec& wall) {
    const double l = wall.brick.x(), h = wall.brick.z(), q = 0.25 * l, tiny = 1e-6 * l;
    const double length = l * wall.bricks;
    std::vector<WallHole> out;
    for (size_t k = 0; k < wall.openings.size(); ++k) {
        const WallOpening& o = wall.openings[k];
        const std::string what = "opening " + std::to_string(k) + " (x0 " + text(o.x0) + " m, z0 " + text(o.z0) +
                                 " m, width " + text(o.width) + " m, height " + text(o.height) + " m): ";
        if (!(std::isfinite(o.x0) && std::isfinite(o.z0) && o.width > 0.0 && o.height > 0.0 &&
              std::isfinite(o.width) && std::isfinite(o.height)))
            throw Error(what + "needs finite x0, z0 and a positive width and height");
        WallHole hole{q * std::round(o.x0 / q), q * std::round((o.x0 + o.width) / q), int(std::lround(o.z0 / h)),
                      int(std::lround((o.z0 + o.height) / h))};
        if (hole.x1 - hole.x0 < tiny || hole.course_to <= hole.course_from)
            throw Error(what + "is less than a quarter brick (" + text(q) + " m) wide or half a course (" +
                        text(0.5 * h) + " m) high");
        if (hole.x0 < 0.5 * l - tiny || hole.x1 > length - 0.5 * l + tiny)
            throw Error(what + "must lie at least half a brick (" + text(0.5 * l) +
                        " m) inside the ends of the wall of " + text(length) + " m");
        if (hole.course_from < 0 || hole.course_to > wall.courses)
            throw Error(what + "must lie within the wall's height of " + text(wall.courses * h) + " m");
        for (size_t j = 0; j < out.size(); ++j) {
            const WallHole& p = out[j];
            // with their lintels' bearings, two holes must leave a pier of a brick between them
            const bool apart_x = hole.x0 - 0.5 * l >= p.x1 + 0.5 * l - tiny || p.x0 - 0.5 * l >= hole.x1 + 0.5 * l - tiny;
            const bool apart_z = hole.course_from > p.course_to || p.course_from > hole.course_to;
            if (!apart_x && !apart_z)
                throw Error(what + "comes within a brick (" + text(l) + " m) of opening " + std::to_string(j) +
                            " or its lintel");
        }
        out.push_back(hole);
    }
    return out;
}

int add_wall(Scene& scene, const WallSpec& wall) {
    const double l = wall.brick.x(), w = wall.brick.y(), h = wall.brick.z(), tiny = 1e-6 * l;
    const double length = l * wall.bricks, thick = wall_thickness(wall);
    if (wall.bond == WallBond::english) {
        if (std::abs(l - 2.0 * w) > tiny)
            throw Error("English bond needs the brick length (" + text(l) + " m) twice its thickness (" + text(w) +
                        " m): the wall is a brick length thick");
        if (wall.bricks < 2)
            throw Error("English bond needs at least 2 bricks per course (the header courses end in closers)");
    }
    const std::vector<WallHole> holes = wall_holes(wall);
    if (wall.base) add_box(scene, "base", Vec3(length + 1.0, thick + 0.8, 0.5), Vec3(0, 0, -0.25), true);
    const int first = int(scene.blocks.size());
    const double q = 0.25 * l;   // a quarter brick, m
    auto quarters = [&](double x) { return int(std::lround(x / q)); };
    double z = 0.0;
    char name[48];
    for (int c = 0; c < wall.courses; ++c) {
        // the joint under course c carries the courses above it: pressure (courses − c)·ρ g h
        if (wall.placed_kn > 0.0) z -= (wall.courses - c) * wall.density * wall.gravity * h / wall.placed_kn;
        std::vector<Piece> pieces = course_pieces(wall, c);
        std::vector<std::pair<int, Piece>> lintels;
        for (size_t k = 0; k < holes.size(); ++k) {
            const WallHole& o = holes[k];
            const int a = quarters(o.x0), b = quarters(o.x1);
            if (c >= o.course_from && c < o.course_to) pieces = cut(pieces, a, b);
            if (c == o.course_to) {
                // half a brick of bearing on each side
                pieces = cut(pieces, a - 2, b + 2);
                lintels.push_back({int(k), {a - 2, b + 2, 0}});
            }
        }
        // front leaf, then through-pieces, then the back leaf, each left to right
        std::stable_sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) {
            return a.leaf != b.leaf ? a.leaf < b.leaf : a.a < b.a;
        });
        auto place = [&](const std::string& n, const Piece& p) {
            const double t = p.leaf == 0 ? thick : 0.5 * thick;
            const double x = 0.5 * q * (p.a + p.b - 4 * wall.bricks);
            add_box(scene, n, Vec3(q * (p.b - p.a), t, h), Vec3(x, 0.25 * thick * p.leaf, z + 0.5 * h),
                    !wall.base && c == 0);
        };
        for (size_t i = 0; i < pieces.size(); ++i) {
            std::snprintf(name, sizeof name, "b%03d_%03zu", c, i);
            place(name, pieces[i]);
        }
        for (const auto& [k, p] : lintels) place("lintel" + std::to_string(k), p);
        z += h;
    }
    return first;
}

}  // namespace cairn

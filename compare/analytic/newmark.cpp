// Newmark's rigid sliding block: holds while the drive is inside the friction disk, slides against
// its relative velocity otherwise
#include "analytic/newmark.hpp"

#include <algorithm>
#include <cmath>

namespace cairn::oracle {

Vec2 SlidingHistory::at(double at) const {
    if (t.empty()) return Vec2::Zero();
    if (at <= t.front()) return x.front();
    if (at >= t.back()) return x.back();
    const size_t i = size_t(std::upper_bound(t.begin(), t.end(), at) - t.begin());
    const double w = (at - t[i - 1]) / (t[i] - t[i - 1]);
    return (1.0 - w) * x[i - 1] + w * x[i];
}

SlidingHistory newmark_slide(const std::function<Vec3(double)>& drive, double g, double mu, double duration,
                              const Vec2& v0) {
    constexpr long kMaxSteps = 2000000;
    const double h = std::max(1e-5, duration / double(kMaxSteps));
    const long steps = std::max(1L, long(std::ceil(duration / h)));
    SlidingHistory out;
    out.t.reserve(size_t(steps) + 1);
    out.x.reserve(size_t(steps) + 1);
    Vec2 x = Vec2::Zero(), v = Vec2::Zero();
    out.t.push_back(0.0);
    out.x.push_back(x);
    // the horizontal drive and the friction disk's radius μ·n at time t
    auto load = [&](double t, Vec2* f, double* cap) {
        const Vec3 d = drive(t);
        *f = Vec2(d.x(), d.y());
        const double n = g - d.z();
        *cap = mu * std::max(0.0, n);
        if (n > 0.0) out.peak_ratio = std::max(out.peak_ratio, f->norm() / n);
        else if (f->norm() > 0.0) out.peak_ratio = INFINITY;
    };
    // acceleration while sliding with velocity direction `dir` (unit)
    auto sliding = [&](double t, const Vec2& dir) {
        Vec2 f;
        double cap;
        load(t, &f, &cap);
        return Vec2(f - cap * dir);
    };
    bool held = true;
    if (v0.norm() > 0.0) {   // launched: sliding from the start
        held = false;
        v = v0;
        ++out.onsets;
    }
    for (long i = 0; i < steps; ++i) {
        const double t0 = double(i) * h, t1 = std::min(duration, t0 + h), dt = t1 - t0;
        if (held) {
            Vec2 f;
            double cap;
            load(0.5 * (t0 + t1), &f, &cap);
            if (f.norm() <= cap) {
                out.t.push_back(t1);
                out.x.push_back(x);
                continue;
            }
            // friction gives way: slide off along the drive's excess over the disk
            held = false;
            ++out.onsets;
            const Vec2 a = f - cap * f.normalized();
            const Vec2 v1 = a * dt;
            x += 0.5 * v1 * dt;
            v = v1;
            out.slide_time += dt;
            out.t.push_back(t1);
            out.x.push_back(x);
            continue;
        }
        const double speed = v.norm();
        const Vec2 dir = v / speed;
        const Vec2 a0 = sliding(t0, dir);
        const Vec2 vh = v + 0.5 * dt * a0;
        // the midpoint's velocity sets the friction's direction over the step; one that has turned
        // back stops within the step's first half, at the start's deceleration
        const Vec2 v1 = vh.dot(dir) > 0.0 ? Vec2(v + dt * sliding(t0 + 0.5 * dt, vh.normalized())) : Vec2(v + dt * a0);
        if (v1.dot(dir) <= 0.0) {
            // the velocity along its direction vanishes within the step: stop there (linear in the
            // step), then hold if friction can, else slide off again from rest at the step's end
            const double s = speed / (speed - v1.dot(dir));
            x += 0.5 * v * s * dt;
            out.slide_time += s * dt;
            v = Vec2::Zero();
            held = true;
            Vec2 f;
            double cap;
            load(t1, &f, &cap);
            if (f.norm() > cap && s < 1.0) {   // (at s = 1 the next step's check starts it)
                held = false;
                ++out.onsets;
                v = (f - cap * f.normalized()) * (1.0 - s) * dt;
                out.slide_time += (1.0 - s) * dt;
            }
        } else {
            x += 0.5 * (v + v1) * dt;
            v = v1;
            out.slide_time += dt;
        }
        out.t.push_back(t1);
        out.x.push_back(x);
    }
    return out;
}

}  // namespace cairn::oracle

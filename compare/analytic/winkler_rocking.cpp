#include "analytic/winkler_rocking.hpp"

#include <array>
#include <cmath>
#include <string>

#include "error.hpp"

namespace cairn::oracle {

namespace {

constexpr int kMaxCells = WinklerRocking::max_cells;   // contact cells of the three lower faces together

// the state: centre (m), rotation (rad), their rates, each face's shear state Q = u·√A (m²) and
// the energy dissipated by the dashpots and the work of the drive (J)
struct State {
    double x = 0, z = 0, th = 0, vx = 0, vz = 0, w = 0;
    std::array<double, kMaxCells> q{};
    double lost = 0, work = 0;
};

State axpy(const State& s, double h, const State& d) {
    State o;
    o.x = s.x + h * d.x, o.z = s.z + h * d.z, o.th = s.th + h * d.th;
    o.vx = s.vx + h * d.vx, o.vz = s.vz + h * d.vz, o.w = s.w + h * d.w;
    for (int k = 0; k < kMaxCells; ++k) o.q[size_t(k)] = s.q[size_t(k)] + h * d.q[size_t(k)];
    o.lost = s.lost + h * d.lost;
    o.work = s.work + h * d.work;
    return o;
}

// what the base does to one face
struct FaceLoad {
    double area = 0, d1 = 0, d2 = 0;   // contact area (m²), ∫d dA (m³), ∫d² dA (m⁴)
    double fn = 0, fs = 0;             // vertical and horizontal force on the block, N
    double rx = 0, rz = 0;             // the pressure centre from the block's centre, m
    double vt = 0;                     // horizontal velocity of the block there, m/s
    double power = 0;                  // rate of dissipation of the dashpots, W
};

// one contact cell: a piece of a lower face, its ends in the block's frame and the face's outward
// normal, with its own shear spring; its dashpots scale with the whole face's area
struct Cell {
    double a[2], b[2], n[2];
    double side_area;   // m²
};

}  // namespace

WinklerTrace WinklerRocking::rock(double theta0, double duration, double sample_dt, double sink) const {
    const double alpha = std::atan(width / height);
    auto bad = [](const std::string& what, double v) {
        throw Error("Winkler rocking: " + what + " = " + std::to_string(v) + " is out of range");
    };
    if (!(width > 0)) bad("width", width);
    if (!(height > 0)) bad("height", height);
    if (!(depth > 0)) bad("depth", depth);
    if (!(mass > 0)) bad("mass", mass);
    if (!(g >= 0)) bad("g", g);
    if (!(kn > 0)) bad("kn", kn);
    if (!(ks >= 0)) bad("ks", ks);
    if (!(mu >= 0)) bad("mu", mu);
    if (!(zeta >= 0)) bad("zeta", zeta);
    if (!(theta0 >= 0 && theta0 < alpha)) bad("theta0", theta0);
    if (!(duration > 0)) bad("duration", duration);
    if (!(sample_dt > 0)) bad("sample_dt", sample_dt);
    if (!(steps_per_period >= 10)) bad("steps_per_period", steps_per_period);
    if (cells_across < 1 || cells_up < 1 || cells_across + 2 * cells_up > kMaxCells)
        bad("cells_across + 2 cells_up", cells_across + 2 * cells_up);

    const double b = 0.5 * width, hh = 0.5 * height, inertia_c = inertia();
    const double corner[4][2] = {{-b, -hh}, {b, -hh}, {b, hh}, {-b, hh}};
    // the lower faces (bottom, +x side, −x side), each cut into equal cells
    std::vector<Cell> cells;
    auto add_face = [&](const double* p0, const double* p1, double nx, double nz, double area, int count) {
        for (int i = 0; i < count; ++i) {
            const double f0 = double(i) / count, f1 = double(i + 1) / count;
            cells.push_back(Cell{{p0[0] + f0 * (p1[0] - p0[0]), p0[1] + f0 * (p1[1] - p0[1])},
                                 {p0[0] + f1 * (p1[0] - p0[0]), p0[1] + f1 * (p1[1] - p0[1])},
                                 {nx, nz}, area});
        }
    };
    add_face(corner[0], corner[1], 0, -1, width * depth, cells_across);
    add_face(corner[1], corner[2], 1, 0, height * depth, cells_up);
    add_face(corner[3], corner[0], -1, 0, height * depth, cells_up);
    const int n_cells = int(cells.size());
    std::vector<double> cn, ct;
    for (const Cell& c : cells) {
        cn.push_back(2.0 * zeta * std::sqrt(kn * mass / c.side_area));
        ct.push_back(2.0 * zeta * std::sqrt(ks * mass / c.side_area));
    }
    // the stiffest mode is bounded by every lower face pressed on the corner's lever
    const double lever2 = b * b + hh * hh;
    const double area_all = depth * (width + 2.0 * height);
    const double omega_max = std::sqrt(std::max(kn, ks) * area_all * (1.0 / mass + lever2 / inertia_c));
    const double h = 2.0 * M_PI / omega_max / steps_per_period;
    const double wanted = std::ceil(duration / h);
    if (!(wanted <= 1e8))
        throw Error("Winkler rocking: kn = " + std::to_string(kn) + " N/m³ over " + std::to_string(duration) +
                    " s needs " + std::to_string(wanted) + " steps of " + std::to_string(h) + " s, more than 1e8");

    // world position of a body point relative to the centre: R_y(θ)·(bx, bz)
    auto arm = [](double th, double bx, double bz, double& rx, double& rz) {
        const double c = std::cos(th), s = std::sin(th);
        rx = bx * c + bz * s;
        rz = -bx * s + bz * c;
    };
    // the base's action on face k: the part of the face below z = 0 projected on the base's top,
    // d affine along it; the face hits only while its outward normal points down past 1e-3, as dem's
    auto face_load = [&](const State& s, int k) {
        FaceLoad f;
        const Cell& cell = cells[size_t(k)];
        const double nz = -cell.n[0] * std::sin(s.th) + cell.n[1] * std::cos(s.th);
        if (!(nz < -1e-3)) return f;
        double px[2], pd[2];
        for (int e = 0; e < 2; ++e) {
            double rx, rz;
            const double* end = e == 0 ? cell.a : cell.b;
            arm(s.th, end[0], end[1], rx, rz);
            px[e] = s.x + rx;
            pd[e] = -(s.z + rz);
        }
        if (pd[0] <= 0 && pd[1] <= 0) return f;
        double xa = px[0], da = pd[0], xb = px[1], db = pd[1];
        // clip at d = 0
        if (da < 0) {
            xa = xa + (xb - xa) * da / (da - db);
            da = 0;
        } else if (db < 0) {
            xb = xb + (xa - xb) * db / (db - da);
            db = 0;
        }
        const double span = std::abs(xb - xa);
        if (!(span > 0)) return f;
        f.area = depth * span;
        f.d1 = f.area * 0.5 * (da + db);
        f.d2 = f.area * (da * da + da * db + db * db) / 3.0;
        const double moment = f.area * (da * (2 * xa + xb) + db * (xa + 2 * xb)) / 6.0;
        const double xc = moment / f.d1;
        f.rx = xc - s.x;
        f.rz = -s.z;
        // velocity of the block's material at the pressure centre: v + ω ŷ × r
        f.vt = s.vx + s.w * f.rz;
        const double closing = -(s.vz - s.w * f.rx);
        const double fn_el = kn * f.d1;
        f.fn = std::max(0.0, fn_el + cn[size_t(k)] * f.area * closing);
        f.power = (f.fn - fn_el) * closing;
        if (ks > 0 && f.fn > 0) {
            const double f_el = -ks * std::sqrt(f.area) * s.q[size_t(k)], cap = mu * f.fn;
            if (std::abs(f_el) > cap) {
                f.fs = std::copysign(cap, f_el);
            } else {
                f.fs = f_el - ct[size_t(k)] * f.area * f.vt;
                if (std::abs(f.fs) > cap) f.fs = std::copysign(cap, f.fs);
                f.power -= (f.fs - f_el) * f.vt;
            }
        }
        return f;
    };
    auto rate = [&](const State& s, double t) {
        State d;
        d.x = s.vx, d.z = s.vz, d.th = s.w;
        double fx = 0, fz = -mass * g, tq = 0;
        if (drive) {
            const auto a = drive(t);
            fx += mass * a[0], fz += mass * a[1];
            d.work = mass * (a[0] * s.vx + a[1] * s.vz);
        }
        for (int k = 0; k < n_cells; ++k) {
            const FaceLoad f = face_load(s, k);
            fx += f.fs;
            fz += f.fn;
            tq += f.rz * f.fs - f.rx * f.fn;
            d.q[size_t(k)] = f.fn > 0 ? std::sqrt(f.area) * f.vt : 0.0;
            d.lost += f.power;
        }
        d.vx = fx / mass, d.vz = fz / mass, d.w = tq / inertia_c;
        return d;
    };
    auto energy = [&](const State& s) {
        double e = 0.5 * mass * (s.vx * s.vx + s.vz * s.vz) + 0.5 * inertia_c * s.w * s.w + mass * g * s.z + s.lost - s.work;
        for (int k = 0; k < n_cells; ++k) {
            const FaceLoad f = face_load(s, k);
            e += 0.5 * kn * f.d2 + 0.5 * ks * s.q[size_t(k)] * s.q[size_t(k)];
        }
        return e;
    };
    // after a step: a face out of contact gives up its shear spring, one past the cap slips back to
    // it; both book the spring energy they release
    WinklerTrace tr;
    auto settle_shear = [&](State& s) {
        if (!(ks > 0)) return;
        for (int k = 0; k < n_cells; ++k) {
            double& q = s.q[size_t(k)];
            const FaceLoad f = face_load(s, k);
            double q_new = q;
            if (!(f.fn > 0)) {
                q_new = 0;
            } else if (ks * std::sqrt(f.area) * std::abs(q) > mu * f.fn) {
                q_new = std::copysign(mu * f.fn / (ks * std::sqrt(f.area)), q);
                ++tr.slip_steps;
            }
            s.lost += 0.5 * ks * (q * q - q_new * q_new);
            q = q_new;
        }
    };
    // bottom corners' heights above the base (−x, +x) and their rates
    auto corner_z = [&](const State& s, int c, double& zc, double& vzc) {
        double rx, rz;
        arm(s.th, corner[c][0], corner[c][1], rx, rz);
        zc = s.z + rz;
        vzc = s.vz - s.w * rx;
    };
    // the root in [0, h] of the cubic Hermite through (y0, dy0) and (y1, dy1), by bisection
    auto hermite_root = [h](double y0, double dy0, double y1, double dy1) {
        auto at = [&](double u) {
            const double u2 = u * u, u3 = u2 * u;
            return (2 * u3 - 3 * u2 + 1) * y0 + (u3 - 2 * u2 + u) * h * dy0 + (-2 * u3 + 3 * u2) * y1 + (u3 - u2) * h * dy1;
        };
        double lo = 0, hi = 1;
        const bool rising = y0 < y1;
        for (int i = 0; i < 60; ++i) {
            const double mid = 0.5 * (lo + hi);
            ((at(mid) < 0) == rising ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi) * h;
    };

    State s;
    s.th = theta0;
    {
        double rx, rz;
        arm(theta0, b, -hh, rx, rz);   // the +x bottom edge at the origin
        s.x = -rx;
        s.z = -rz - sink;
    }
    const double e0 = energy(s);
    tr.step = h;
    tr.t.push_back(0);
    tr.theta.push_back(s.th);
    tr.x.push_back(s.x);
    tr.z.push_back(s.z);
    double next_sample = sample_dt, swing_max = 0;
    int lifted = 0;   // the −x bottom edge (corner 0) starts lifted, the +x one (1) on the base
    const long steps = long(wanted);
    for (long n = 1; n <= steps; ++n) {
        const double t0 = (n - 1) * h;
        const State p = s;
        const State k1 = rate(p, t0), k2 = rate(axpy(p, 0.5 * h, k1), t0 + 0.5 * h),
                    k3 = rate(axpy(p, 0.5 * h, k2), t0 + 0.5 * h), k4 = rate(axpy(p, h, k3), t0 + h);
        s = axpy(axpy(axpy(axpy(p, h / 6, k1), h / 3, k2), h / 3, k3), h / 6, k4);
        settle_shear(s);
        if (!std::isfinite(s.th) || !std::isfinite(s.z))
            throw Error("Winkler rocking: the integration went unstable at t = " + std::to_string(t0 + h) + " s");
        tr.energy_error = std::max(tr.energy_error, std::abs(energy(s) - e0));
        if ((p.th > 0 && s.th <= 0) || (p.th < 0 && s.th >= 0)) {
            tr.crossings.push_back(t0 + hermite_root(p.th, p.w, s.th, s.w));
            if (tr.crossings.size() > 1) tr.amplitudes.push_back(swing_max);
            swing_max = 0;
        }
        if (!tr.crossings.empty()) swing_max = std::max(swing_max, std::abs(s.th));
        {
            // the lifted bottom edge reaching the base; then the other one is the one to watch
            double z0, v0, z1, v1;
            corner_z(p, lifted, z0, v0);
            corner_z(s, lifted, z1, v1);
            if (z0 > 0 && z1 <= 0) {
                tr.touches.push_back(t0 + hermite_root(z0, v0, z1, v1));
                lifted = 1 - lifted;
            }
        }
        if (n * h >= next_sample - 1e-12) {
            tr.t.push_back(n * h);
            tr.theta.push_back(s.th);
            tr.x.push_back(s.x);
            tr.z.push_back(s.z);
            next_sample += sample_dt;
        }
    }
    // the last swing counts if it has turned back
    if (!tr.crossings.empty() && swing_max > 0 && std::abs(s.th) < 0.5 * swing_max) tr.amplitudes.push_back(swing_max);
    tr.dissipated = s.lost;
    return tr;
}

}  // namespace cairn::oracle

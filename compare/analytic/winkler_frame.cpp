#include "analytic/winkler_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "error.hpp"

namespace cairn::oracle {

namespace {

// the state, flat: per body its centre (x, z, m), rotation θ (rad) and their rates, then each
// cell's shear state Q = u·√A (m²), then the energy the dashpots took and the drive's work (J)
constexpr int kBodyVars = 6;

using State = std::vector<double>;

State axpy(const State& s, double h, const State& d) {
    State o(s.size());
    for (size_t i = 0; i < s.size(); ++i) o[i] = s[i] + h * d[i];
    return o;
}

// a rectangle's point (bx, bz) in its own frame, from its centre in the world: R_y(θ)·(bx, bz)
void arm(double th, double bx, double bz, double& rx, double& rz) {
    const double c = std::cos(th), s = std::sin(th);
    rx = bx * c + bz * s;
    rz = -bx * s + bz * c;
}

// a contact cell: a piece of a hitting face (its ends and outward normal in the hitting body's
// frame) against a target plane: the ground's top (target −1) or a body's face (its centre, outward
// normal and half-length in that body's frame); its dashpots scale with the hitting face's area
struct Cell {
    int hit = 0, target = -1;
    double a[2], b[2], n[2];
    double t_centre[2] = {0, 0}, t_normal[2] = {0, 1}, t_half = std::numeric_limits<double>::infinity();
    double depth;     // along the axis, m: the joint's
    double cn, ct;    // dashpots per unit area, N·s/m³
};

// what a cell's joint does at a state
struct CellLoad {
    double area = 0, d2 = 0;    // m², ∫d² dA (m⁴)
    double fn = 0, fs = 0;      // along the target's outward normal and its tangent, on the hitting body, N
    double px = 0, pz = 0;      // the pressure centre on the target plane, world, m
    double nx = 0, nz = 1;      // the target's outward normal, world
    double vt = 0;              // tangential velocity of the hitting body relative to the target there, m/s
    double power = 0;           // rate of dissipation of the dashpots, W
};

// the assembly as the integrator takes it: its bodies at rest and its contact cells
struct Model {
    std::vector<double> m, inertia, x0, z0;   // kg, kg·m², the centres at rest (m)
    std::vector<Cell> cells;
    double omega2 = 0.0;                       // bound on the stiffest contact mode's ω², 1/s²
    int traced = 0;                            // the body whose θ and centre the trace records
};

// the joints' law and the run's settings
struct Law {
    const char* who;
    double g, kn, ks, mu, zeta, steps_per_period;
    const std::function<std::array<double, 2>(double)>* drive;
};

// the target face of a cell on a body (its centre, outward normal and half-length in that body's
// frame); none: the ground's top
struct TargetFace {
    double centre[2], normal[2], half;
};

// a face of body `hit` from p0 to p1 (its frame; outward normal (nx, nz)) cut into `count` equal
// cells against body `target`'s face `tf` (−1: the ground's top); `face_area` the whole hitting
// face's (m², for the dashpots, as dem's), `joint_depth` the joint's extent along the axis (m)
void add_face(Model& md, const Law& law, int hit, int target, const TargetFace* tf, const double* p0, const double* p1,
              double nx, double nz, double face_area, int count, double joint_depth) {
    // dem's dashpots: the pair's reduced mass (the ground's is infinite) over the hitting side's area
    const double mh = md.m[size_t(hit)];
    const double mr = target < 0 ? mh : mh * md.m[size_t(target)] / (mh + md.m[size_t(target)]);
    for (int i = 0; i < count; ++i) {
        const double f0 = double(i) / count, f1 = double(i + 1) / count;
        Cell c;
        c.hit = hit;
        c.target = target;
        c.a[0] = p0[0] + f0 * (p1[0] - p0[0]), c.a[1] = p0[1] + f0 * (p1[1] - p0[1]);
        c.b[0] = p0[0] + f1 * (p1[0] - p0[0]), c.b[1] = p0[1] + f1 * (p1[1] - p0[1]);
        c.n[0] = nx, c.n[1] = nz;
        c.depth = joint_depth;
        c.cn = 2.0 * law.zeta * std::sqrt(law.kn * mr / face_area);
        c.ct = 2.0 * law.zeta * std::sqrt(law.ks * mr / face_area);
        if (tf) {
            c.t_centre[0] = tf->centre[0], c.t_centre[1] = tf->centre[1];
            c.t_normal[0] = tf->normal[0], c.t_normal[1] = tf->normal[1];
            c.t_half = tf->half;
        }
        md.cells.push_back(c);
    }
}

// the common checks of both assemblies' law and run
void check_law(const Law& law, double duration, double sample_dt) {
    auto bad = [&](const std::string& what, double v) {
        throw Error(std::string(law.who) + ": " + what + " = " + std::to_string(v) + " is out of range");
    };
    if (!(law.g >= 0)) bad("g", law.g);
    if (!(law.kn > 0)) bad("kn", law.kn);
    if (!(law.ks >= 0)) bad("ks", law.ks);
    if (!(law.mu >= 0)) bad("mu", law.mu);
    if (!(law.zeta >= 0)) bad("zeta", law.zeta);
    if (!(duration > 0)) bad("duration", duration);
    if (!(sample_dt > 0)) bad("sample_dt", sample_dt);
    if (!(law.steps_per_period >= 10)) bad("steps_per_period", law.steps_per_period);
}

// every body and cell together by RK4, from the model's state at rest
WinklerTrace integrate(const Model& md, const Law& law, double duration, double sample_dt) {
    const auto& cells = md.cells;
    const auto& m = md.m;
    const auto& inertia = md.inertia;
    const double g = law.g, kn = law.kn, ks = law.ks, mu = law.mu, steps_per_period = law.steps_per_period;
    const double omega2 = md.omega2;
    const auto& drive = *law.drive;
    const int bodies = int(m.size()), n_cells = int(cells.size());
    const int lost_at = bodies * kBodyVars + n_cells, work_at = lost_at + 1;
    const size_t x_at = size_t(md.traced * kBodyVars), z_at = x_at + 1, th_at = x_at + 2;
    const double h = 2.0 * M_PI / std::sqrt(omega2) / steps_per_period;
    const double wanted = std::ceil(duration / h);
    if (!(wanted <= 1e8))
        throw Error(std::string(law.who) + ": kn = " + std::to_string(kn) + " N/m³ over " + std::to_string(duration) +
                    " s needs " + std::to_string(wanted) + " steps of " + std::to_string(h) + " s, more than 1e8");

    auto body = [](const State& s, int i) { return &s[size_t(i * kBodyVars)]; };   // x, z, θ, vx, vz, ω
    // world point and velocity of body i's frame point (bx, bz)
    auto point = [&](const State& s, int i, double bx, double bz, double& px, double& pz, double& vx, double& vz) {
        const double* q = body(s, i);
        double rx, rz;
        arm(q[2], bx, bz, rx, rz);
        px = q[0] + rx, pz = q[1] + rz;
        vx = q[3] + q[5] * rz, vz = q[4] - q[5] * rx;   // v + ω ŷ × r
    };
    // the target's action on cell k: the part of the hitting face behind the target plane and over
    // the target face, projected on the plane, d affine along it; the face hits only while its
    // outward normal opposes the target's past 1e-3, as dem's
    auto cell_load = [&](const State& s, int k) {
        CellLoad f;
        const Cell& c = cells[size_t(k)];
        const double th_h = body(s, c.hit)[2];
        // the target plane in the world: a point o, outward normal n, tangent t = (n_z, −n_x)·(−1)
        double ox = 0, oz = 0, nx = 0, nz = 1, ovx = 0, ovz = 0;
        if (c.target >= 0) {
            point(s, c.target, c.t_centre[0], c.t_centre[1], ox, oz, ovx, ovz);
            arm(body(s, c.target)[2], c.t_normal[0], c.t_normal[1], nx, nz);
        }
        const double tx = nz, tz = -nx;   // the tangent: +x for the ground's top
        double hnx, hnz;
        arm(th_h, c.n[0], c.n[1], hnx, hnz);
        if (!(hnx * nx + hnz * nz < -1e-3)) return f;
        double u[2], d[2];
        for (int e = 0; e < 2; ++e) {
            const double* end = e == 0 ? c.a : c.b;
            double px, pz, vx, vz;
            point(s, c.hit, end[0], end[1], px, pz, vx, vz);
            u[e] = (px - ox) * tx + (pz - oz) * tz;
            d[e] = -((px - ox) * nx + (pz - oz) * nz);
        }
        // clip at d = 0 and to the target face's extent along its tangent (d affine along u)
        auto cut = [&](double keep0, double keep1) {   // keep where keep ≥ 0 (affine along the piece)
            if (keep0 >= 0 && keep1 >= 0) return true;
            if (keep0 < 0 && keep1 < 0) return false;
            const double r = keep0 / (keep0 - keep1);
            const double uc = u[0] + r * (u[1] - u[0]), dc = d[0] + r * (d[1] - d[0]);
            if (keep0 < 0) u[0] = uc, d[0] = dc;
            else u[1] = uc, d[1] = dc;
            return true;
        };
        if (!cut(d[0], d[1])) return f;
        if (!cut(c.t_half - u[0], c.t_half - u[1])) return f;
        if (!cut(u[0] + c.t_half, u[1] + c.t_half)) return f;
        d[0] = std::max(0.0, d[0]), d[1] = std::max(0.0, d[1]);
        const double span = std::abs(u[1] - u[0]);
        if (!(span > 0)) return f;
        f.area = c.depth * span;
        const double d1 = f.area * 0.5 * (d[0] + d[1]);
        if (!(d1 > 0)) return f;
        f.d2 = f.area * (d[0] * d[0] + d[0] * d[1] + d[1] * d[1]) / 3.0;
        const double moment = f.area * (d[0] * (2 * u[0] + u[1]) + d[1] * (u[0] + 2 * u[1])) / 6.0;
        const double uc = moment / d1;
        f.px = ox + uc * tx, f.pz = oz + uc * tz;
        f.nx = nx, f.nz = nz;
        // the hitting body's velocity relative to the target's at the pressure centre
        double vhx, vhz, vtx = 0, vtz = 0;
        {
            const double* q = body(s, c.hit);
            const double rx = f.px - q[0], rz = f.pz - q[1];
            vhx = q[3] + q[5] * rz, vhz = q[4] - q[5] * rx;
        }
        if (c.target >= 0) {
            const double* q = body(s, c.target);
            const double rx = f.px - q[0], rz = f.pz - q[1];
            vtx = q[3] + q[5] * rz, vtz = q[4] - q[5] * rx;
        }
        const double rvx = vhx - vtx, rvz = vhz - vtz;
        f.vt = rvx * tx + rvz * tz;
        const double closing = -(rvx * nx + rvz * nz);
        const double fn_el = kn * d1;
        f.fn = std::max(0.0, fn_el + c.cn * f.area * closing);
        f.power = (f.fn - fn_el) * closing;
        if (ks > 0 && f.fn > 0) {
            const double f_el = -ks * std::sqrt(f.area) * s[size_t(bodies * kBodyVars + k)], cap = mu * f.fn;
            if (std::abs(f_el) > cap) {
                f.fs = std::copysign(cap, f_el);
            } else {
                f.fs = f_el - c.ct * f.area * f.vt;
                if (std::abs(f.fs) > cap) f.fs = std::copysign(cap, f.fs);
                f.power -= (f.fs - f_el) * f.vt;
            }
        }
        return f;
    };
    auto rate = [&](const State& s, double t) {
        State d(s.size(), 0.0);
        const size_t nb = static_cast<size_t>(bodies);
        std::vector<double> fx(nb), fz(nb), tq(nb, 0.0);
        std::array<double, 2> a{0.0, 0.0};
        if (drive) a = drive(t);
        for (int i = 0; i < bodies; ++i) {
            const double* q = body(s, i);
            fx[size_t(i)] = m[size_t(i)] * a[0];
            fz[size_t(i)] = m[size_t(i)] * (a[1] - g);
            d[size_t(work_at)] += m[size_t(i)] * (a[0] * q[3] + a[1] * q[4]);
        }
        for (int k = 0; k < n_cells; ++k) {
            const CellLoad f = cell_load(s, k);
            if (!(f.area > 0)) continue;
            const Cell& c = cells[size_t(k)];
            const double tx = f.nz, tz = -f.nx;
            const double gx = f.fn * f.nx + f.fs * tx, gz = f.fn * f.nz + f.fs * tz;   // on the hitting body
            for (int side = 0; side < 2; ++side) {
                const int i = side == 0 ? c.hit : c.target;
                if (i < 0) continue;
                const double sign = side == 0 ? 1.0 : -1.0;
                const double* q = body(s, i);
                const double rx = f.px - q[0], rz = f.pz - q[1];
                fx[size_t(i)] += sign * gx;
                fz[size_t(i)] += sign * gz;
                tq[size_t(i)] += sign * (rz * gx - rx * gz);
            }
            d[size_t(bodies * kBodyVars + k)] = f.fn > 0 ? std::sqrt(f.area) * f.vt : 0.0;
            d[size_t(lost_at)] += f.power;
        }
        for (int i = 0; i < bodies; ++i) {
            const double* q = body(s, i);
            double* r = &d[size_t(i * kBodyVars)];
            r[0] = q[3], r[1] = q[4], r[2] = q[5];
            r[3] = fx[size_t(i)] / m[size_t(i)];
            r[4] = fz[size_t(i)] / m[size_t(i)];
            r[5] = tq[size_t(i)] / inertia[size_t(i)];
        }
        return d;
    };
    auto energy = [&](const State& s) {
        double e = s[size_t(lost_at)] - s[size_t(work_at)];
        for (int i = 0; i < bodies; ++i) {
            const double* q = body(s, i);
            const double mi = m[size_t(i)];
            e += 0.5 * mi * (q[3] * q[3] + q[4] * q[4]) + 0.5 * inertia[size_t(i)] * q[5] * q[5] + mi * g * q[1];
        }
        for (int k = 0; k < n_cells; ++k) {
            const double q = s[size_t(bodies * kBodyVars + k)];
            e += 0.5 * kn * cell_load(s, k).d2 + 0.5 * ks * q * q;
        }
        return e;
    };
    // after a step: a cell out of contact gives up its shear spring, one past the cap slips back to
    // it; both book the spring energy they release
    WinklerTrace tr;
    auto settle_shear = [&](State& s) {
        if (!(ks > 0)) return;
        for (int k = 0; k < n_cells; ++k) {
            double& q = s[size_t(bodies * kBodyVars + k)];
            const CellLoad f = cell_load(s, k);
            double q_new = q;
            if (!(f.fn > 0)) {
                q_new = 0;
            } else if (ks * std::sqrt(f.area) * std::abs(q) > mu * f.fn) {
                q_new = std::copysign(mu * f.fn / (ks * std::sqrt(f.area)), q);
                ++tr.slip_steps;
            }
            s[size_t(lost_at)] += 0.5 * ks * (q * q - q_new * q_new);
            q = q_new;
        }
    };

    State s(size_t(work_at + 1), 0.0);
    for (int i = 0; i < bodies; ++i) {
        s[size_t(i * kBodyVars)] = md.x0[size_t(i)];
        s[size_t(i * kBodyVars + 1)] = md.z0[size_t(i)];
    }
    const double e0 = energy(s);
    tr.step = h;
    tr.t.push_back(0);
    tr.theta.push_back(s[th_at]);
    tr.x.push_back(s[x_at]);
    tr.z.push_back(s[z_at]);
    double next_sample = sample_dt, swing_max = 0;
    const long steps = long(wanted);
    for (long n = 1; n <= steps; ++n) {
        const double t0 = (n - 1) * h;
        const State p = s;
        const State k1 = rate(p, t0), k2 = rate(axpy(p, 0.5 * h, k1), t0 + 0.5 * h),
                    k3 = rate(axpy(p, 0.5 * h, k2), t0 + 0.5 * h), k4 = rate(axpy(p, h, k3), t0 + h);
        s = axpy(axpy(axpy(axpy(p, h / 6, k1), h / 3, k2), h / 3, k3), h / 6, k4);
        settle_shear(s);
        if (!std::isfinite(s[th_at]) || !std::isfinite(s[z_at]))
            throw Error(std::string(law.who) + ": the integration went unstable at t = " + std::to_string(t0 + h) + " s");
        tr.energy_error = std::max(tr.energy_error, std::abs(energy(s) - e0));
        if ((p[th_at] > 0 && s[th_at] <= 0) || (p[th_at] < 0 && s[th_at] >= 0)) {
            tr.crossings.push_back(t0 + h * p[th_at] / (p[th_at] - s[th_at]));
            if (tr.crossings.size() > 1) tr.amplitudes.push_back(swing_max);
            swing_max = 0;
        }
        if (!tr.crossings.empty()) swing_max = std::max(swing_max, std::abs(s[th_at]));
        if (n * h >= next_sample - 1e-12) {
            tr.t.push_back(n * h);
            tr.theta.push_back(s[th_at]);
            tr.x.push_back(s[x_at]);
            tr.z.push_back(s[z_at]);
            next_sample += sample_dt;
        }
    }
    if (!tr.crossings.empty() && swing_max > 0 && std::abs(s[th_at]) < 0.5 * swing_max)
        tr.amplitudes.push_back(swing_max);
    tr.dissipated = s[size_t(lost_at)];
    return tr;
}

}  // namespace

WinklerTrace WinklerFrame::rest(double duration, double sample_dt) const {
    const Law law{"Winkler frame", g, kn, ks, mu, zeta, steps_per_period, &drive};
    check_law(law, duration, sample_dt);
    auto bad = [](const std::string& what, double v) {
        throw Error("Winkler frame: " + what + " = " + std::to_string(v) + " is out of range");
    };
    for (auto [name, v] : {std::pair<const char*, double>{"width", width}, {"height", height}, {"depth", depth},
                           {"mass", mass}, {"beam_length", beam_length}, {"beam_height", beam_height},
                           {"beam_depth", beam_depth}, {"beam_mass", beam_mass}})
        if (!(v > 0)) bad(name, v);
    if (column_x.size() < 2 || column_x.size() > 8) bad("columns", double(column_x.size()));
    const int columns = int(column_x.size());
    if (cells_across < 1 || cells_up < 1 || columns * (2 * cells_across + 2 * cells_up) > max_cells)
        bad("cells", double(columns * (2 * cells_across + 2 * cells_up)));

    const int beam = columns;
    const double b = 0.5 * width, hh = 0.5 * height;
    Model md;
    md.m.assign(size_t(columns), mass);
    md.inertia.assign(size_t(columns), mass * (width * width + height * height) / 12.0);
    md.m.push_back(beam_mass);
    md.inertia.push_back(beam_mass * (beam_length * beam_length + beam_height * beam_height) / 12.0);
    // each column's lower faces (bottom, +x side, −x side) on the ground, and its top under the
    // beam's bottom face (the larger: dem's target), each cut into equal cells
    const double corner[4][2] = {{-b, -hh}, {b, -hh}, {b, hh}, {-b, hh}};
    const double joint_depth = std::min(depth, beam_depth);
    const TargetFace beam_bottom{{0.0, -0.5 * beam_height}, {0.0, -1.0}, 0.5 * beam_length};
    for (int i = 0; i < columns; ++i) {
        add_face(md, law, i, -1, nullptr, corner[0], corner[1], 0, -1, width * depth, cells_across, depth);
        add_face(md, law, i, -1, nullptr, corner[1], corner[2], 1, 0, height * depth, cells_up, depth);
        add_face(md, law, i, -1, nullptr, corner[3], corner[0], -1, 0, height * depth, cells_up, depth);
        add_face(md, law, i, beam, &beam_bottom, corner[3], corner[2], 0, 1, width * depth, cells_across, joint_depth);
    }
    // the stiffest mode is bounded, per body, by every face it can press on its farthest lever
    {
        const double lever2 = b * b + hh * hh, area = depth * (2.0 * width + 2.0 * height);
        md.omega2 = std::max(kn, ks) * area * (1.0 / mass + lever2 / md.inertia[0]);
        const double beam_lever2 = 0.25 * (beam_length * beam_length + beam_height * beam_height);
        const double beam_area = columns * width * joint_depth;
        const double beam_omega2 = std::max(kn, ks) * beam_area * (1.0 / beam_mass + beam_lever2 / md.inertia.back());
        md.omega2 = std::max(md.omega2, beam_omega2);
    }
    // at rest: each column sunk by the weight it carries, W_column + W_beam/N over its base, the beam
    // on their tops sunk by its share over a top
    const double settle_base = (mass + beam_mass / columns) * g / (kn * width * depth);
    const double settle_top = beam_mass / columns * g / (kn * width * joint_depth);
    for (int i = 0; i < columns; ++i) md.x0.push_back(column_x[size_t(i)]), md.z0.push_back(hh - settle_base);
    md.x0.push_back(beam_x);
    md.z0.push_back(height - settle_base - settle_top + 0.5 * beam_height);
    return integrate(md, law, duration, sample_dt);
}

WinklerTrace WinklerStack::rest(double duration, double sample_dt) const {
    const Law law{"Winkler stack", g, kn, ks, mu, zeta, steps_per_period, &drive};
    check_law(law, duration, sample_dt);
    auto bad = [](const std::string& what, double v) {
        throw Error("Winkler stack: " + what + " = " + std::to_string(v) + " is out of range");
    };
    if (layers.size() < 2 || layers.size() > 16) bad("layers", double(layers.size()));
    if (traced < 0 || traced >= int(layers.size())) bad("traced", traced);
    int n_cells = 0;
    for (const auto& l : layers) {
        for (double v : {l.width, l.height, l.depth, l.mass})
            if (!(v > 0)) bad("a layer's size or mass", v);
        if (l.cells_across < 1 || l.cells_up < 1) bad("a layer's cells", std::min(l.cells_across, l.cells_up));
        n_cells += 2 * l.cells_across + 2 * l.cells_up;
    }
    if (n_cells > max_cells) bad("cells", n_cells);
    Model md;
    md.traced = traced;
    for (const auto& l : layers) {
        md.m.push_back(l.mass);
        md.inertia.push_back(l.mass * (l.width * l.width + l.height * l.height) / 12.0);
        // every face it can press, on its farthest lever
        const double lever2 = 0.25 * (l.width * l.width + l.height * l.height);
        const double area = l.depth * 2.0 * (l.width + l.height);
        md.omega2 = std::max(md.omega2, std::max(kn, ks) * area * (1.0 / l.mass + lever2 / md.inertia.back()));
    }
    // each bed joint: the smaller of the two faces hits the larger (dem's target; equal: the lower
    // one is the target), the hitting block's sides with its bottom; the first layer on the ground
    double z = 0.0, carried = 0.0;
    for (const auto& l : layers) carried += l.mass;
    for (int k = 0; k < int(layers.size()); ++k) {
        const WinklerLayer& l = layers[size_t(k)];
        const double b = 0.5 * l.width, hh = 0.5 * l.height;
        const double corner[4][2] = {{-b, -hh}, {b, -hh}, {b, hh}, {-b, hh}};
        double area;
        if (k == 0) {
            area = l.width * l.depth;
            add_face(md, law, k, -1, nullptr, corner[0], corner[1], 0, -1, l.width * l.depth, l.cells_across, l.depth);
            add_face(md, law, k, -1, nullptr, corner[1], corner[2], 1, 0, l.height * l.depth, l.cells_up, l.depth);
            add_face(md, law, k, -1, nullptr, corner[3], corner[0], -1, 0, l.height * l.depth, l.cells_up, l.depth);
        } else {
            const WinklerLayer& u = layers[size_t(k - 1)];
            const double depth = std::min(l.depth, u.depth);
            area = std::min(l.width, u.width) * depth;
            if (l.width * l.depth <= u.width * u.depth) {   // this layer's bottom hits the top below
                const TargetFace top{{0.0, 0.5 * u.height}, {0.0, 1.0}, 0.5 * u.width};
                add_face(md, law, k, k - 1, &top, corner[0], corner[1], 0, -1, l.width * l.depth, l.cells_across, depth);
                add_face(md, law, k, k - 1, &top, corner[1], corner[2], 1, 0, l.height * l.depth, l.cells_up, depth);
                add_face(md, law, k, k - 1, &top, corner[3], corner[0], -1, 0, l.height * l.depth, l.cells_up, depth);
            } else {   // the top below hits this layer's bottom
                const double ub = 0.5 * u.width, uh = 0.5 * u.height;
                const double top_l[2] = {-ub, uh}, top_r[2] = {ub, uh};
                const TargetFace bottom{{0.0, -hh}, {0.0, -1.0}, b};
                add_face(md, law, k - 1, k, &bottom, top_l, top_r, 0, 1, u.width * u.depth, u.cells_across, depth);
            }
        }
        // at rest: sunk by the weight it carries over the joint's area
        z -= carried * g / (kn * area);
        md.x0.push_back(0.0);
        md.z0.push_back(z + hh);
        z += l.height;
        carried -= l.mass;
    }
    return integrate(md, law, duration, sample_dt);
}

}  // namespace cairn::oracle

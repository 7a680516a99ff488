#include "analytic/spring_block.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "error.hpp"

namespace cairn::oracle {

std::vector<SpringRow> spring_rows(double width, double depth, int divisions, double spacing) {
    divisions = std::max(1, divisions);
    const double face = width / divisions;
    const int n = std::max(2, int(std::ceil(face / spacing - 1e-9)) + 1);
    const double du = face / (n - 1);
    std::map<long, SpringRow> rows;   // keyed by the position in units of du/2: shared points merge
    for (int f = 0; f < divisions; ++f)
        for (int i = 0; i < n; ++i) {
            const double x = -0.5 * width + f * face + i * du;
            const double w = (i == 0 || i == n - 1) ? 0.5 : 1.0;
            auto& r = rows[std::lround(x / (0.5 * du))];
            r.x = x;
            r.area += w * du * depth;
        }
    std::vector<SpringRow> out;
    for (const auto& [k, r] : rows) out.push_back(r);
    return out;
}

namespace {

struct State {
    double x = 0, z = 0, phi = 0;     // centre of mass (m) and rotation about +y (rad)
    double vx = 0, vz = 0, w = 0;     // m/s, rad/s
};

struct Anchor {
    bool on = false;
    double x0 = 0.0;   // stick point on the base, m
};

struct Load {
    double fx = 0, fz = 0, torque = 0;   // N, N, N·m about +y through the centre of mass
    double stored = 0, dissipated = 0;   // J (dissipated: this step)
};

}  // namespace

RockingTrace SpringBlock::rock(double theta0, double duration, double sample_dt) const {
    const double inertia = mass * (width * width + height * height) / 12.0;
    double area = 0.0;
    for (const auto& r : rows) area += r.area;
    const double lever2 = 0.25 * (width * width + height * height);
    const double omega_max = std::sqrt(std::max(kn, ks) * area * (1.0 / mass + lever2 / inertia));
    const double h = 2.0 * M_PI / omega_max / steps_per_period;
    // dashpots per unit area, as the contact-spring ratio ζ on the whole base
    const double cn = 2.0 * zeta * std::sqrt(kn * mass / area), ct = 2.0 * zeta * std::sqrt(ks * mass / area);
    std::vector<Anchor> anchors(rows.size());

    // the body point (bx, bz) in the world: R_y(φ)·(bx, bz) + centre
    auto world = [](const State& s, double bx, double bz, double& px, double& pz, double& rx, double& rz) {
        const double c = std::cos(s.phi), sn = std::sin(s.phi);
        rx = bx * c + bz * sn;
        rz = -bx * sn + bz * c;
        px = s.x + rx;
        pz = s.z + rz;
    };
    auto contact = [&](const State& s, double step) {
        Load l;
        for (size_t i = 0; i < rows.size(); ++i) {
            double px, pz, rx, rz;
            world(s, rows[i].x, -0.5 * height, px, pz, rx, rz);
            Anchor& an = anchors[i];
            const double depth = -pz;
            if (!(depth > 0.0)) { an.on = false; continue; }
            const double a = rows[i].area;
            // velocity of the point: v + ω ŷ × r = (vx + ω rz, vz − ω rx)
            const double vpx = s.vx + s.w * rz, vpz = s.vz - s.w * rx;
            const double closing = -vpz;
            const double fn_el = kn * a * depth;
            const double fn = std::max(0.0, fn_el + cn * a * closing);
            l.dissipated += (fn - fn_el) * closing * step;
            l.stored += 0.5 * fn_el * depth;
            double fs = 0.0;
            if (ks > 0.0 && fn > 0.0) {
                if (!an.on) an = Anchor{true, px};
                const double ks_a = ks * a, u = px - an.x0, f_el = -ks_a * u, cap = mu * fn;
                if (std::abs(f_el) > cap) {
                    // slip: the force sits at the cap and the anchor follows
                    fs = std::copysign(cap, f_el);
                    const double moved = px + fs / ks_a;
                    l.dissipated += cap * std::abs(moved - an.x0);
                    an.x0 = moved;
                    l.stored += 0.5 * fs * fs / ks_a;
                } else {
                    fs = f_el - ct * a * vpx;
                    if (std::abs(fs) > cap) fs = std::copysign(cap, fs);
                    l.stored += 0.5 * ks_a * u * u;
                    l.dissipated -= (fs - f_el) * vpx * step;
                }
            } else {
                an.on = false;
            }
            l.fx += fs;
            l.fz += fn;
            l.torque += rz * fs - rx * fn;
        }
        return l;
    };

    State s;
    s.phi = theta0;
    {
        // the +x bottom edge at the origin, on the base's top
        double px, pz, rx, rz;
        world(s, 0.5 * width, -0.5 * height, px, pz, rx, rz);
        s.x = -rx;
        s.z = -rz;
    }
    auto energy = [&](const State& st, double stored) {
        return 0.5 * mass * (st.vx * st.vx + st.vz * st.vz) + 0.5 * inertia * st.w * st.w + mass * g * st.z + stored;
    };
    Load l = contact(s, h);
    const double e0 = energy(s, l.stored);
    double dissipated = 0.0;
    RockingTrace tr;
    tr.step = h;
    tr.t.push_back(0.0);
    tr.theta.push_back(s.phi);
    double next_sample = sample_dt, swing_max = 0.0;
    // a bound on the work: 1e8 steps (a few seconds) covers kn up to ~1e13 N/m³ over 3 s
    const double wanted = std::ceil(duration / h);
    if (!(wanted <= 1e8))
        throw Error("spring block: kn = " + std::to_string(kn) + " N/m³ over " + std::to_string(duration) +
                    " s needs " + std::to_string(wanted) + " steps of " + std::to_string(h) + " s, more than 1e8");
    const long steps = long(wanted);
    for (long k = 1; k <= steps; ++k) {
        const double t = k * h;
        const double ax = l.fx / mass, az = l.fz / mass - g, al = l.torque / inertia;
        const State prev = s;
        s.x += h * s.vx + 0.5 * h * h * ax;
        s.z += h * s.vz + 0.5 * h * h * az;
        s.phi += h * s.w + 0.5 * h * h * al;
        // forces at the new positions with the predicted velocities (for the dashpots)
        State pred = s;
        pred.vx = prev.vx + h * ax;
        pred.vz = prev.vz + h * az;
        pred.w = prev.w + h * al;
        l = contact(pred, h);
        s.vx = prev.vx + 0.5 * h * (ax + l.fx / mass);
        s.vz = prev.vz + 0.5 * h * (az + l.fz / mass - g);
        s.w = prev.w + 0.5 * h * (al + l.torque / inertia);
        dissipated += l.dissipated;
        tr.energy_error = std::max(tr.energy_error, std::abs(energy(s, l.stored) + dissipated - e0));
        if ((prev.phi > 0.0 && s.phi <= 0.0) || (prev.phi < 0.0 && s.phi >= 0.0)) {
            tr.impacts.push_back(t - h + h * prev.phi / (prev.phi - s.phi));
            if (tr.impacts.size() > 1) tr.amplitudes.push_back(swing_max);
            swing_max = 0.0;
        }
        if (!tr.impacts.empty()) swing_max = std::max(swing_max, std::abs(s.phi));
        if (t >= next_sample - 1e-12) {
            tr.t.push_back(t);
            tr.theta.push_back(s.phi);
            next_sample += sample_dt;
        }
    }
    // the last swing counts if it has turned back
    if (!tr.impacts.empty() && swing_max > 0.0 && std::abs(s.phi) < 0.5 * swing_max) tr.amplitudes.push_back(swing_max);
    return tr;
}

std::vector<double> SpringBlock::angles(double theta0, const std::vector<double>& times) const {
    if (times.empty()) return {};
    // sample finely enough that linear interpolation is far below any tolerance
    return angles_at(rock(theta0, times.back() + 1e-9, 1e-4), times);
}

std::vector<double> angles_at(const RockingTrace& tr, const std::vector<double>& times) {
    std::vector<double> out;
    if (tr.t.empty()) return out;
    size_t j = 0;
    for (double t : times) {
        while (j + 1 < tr.t.size() && tr.t[j + 1] < t) ++j;
        if (j + 1 >= tr.t.size()) { out.push_back(tr.theta.back()); continue; }
        const double f = (t - tr.t[j]) / (tr.t[j + 1] - tr.t[j]);
        out.push_back(tr.theta[j] + std::clamp(f, 0.0, 1.0) * (tr.theta[j + 1] - tr.theta[j]));
    }
    return out;
}

}  // namespace cairn::oracle

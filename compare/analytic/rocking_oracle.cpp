// the rocking oracle: Dormand–Prince 5(4) with dense output, events located on the interpolant
#include "analytic/rocking_oracle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "error.hpp"

namespace cairn::oracle {

namespace {

using Y = std::array<double, 2>;   // θ, θ̇

// one Dormand–Prince step from (t, y) of size h: the 5th-order result, the error estimate and the
// coefficients of Hairer's 4th-order continuous extension
struct Step {
    Y y1{}, err{};
    std::array<Y, 5> dense{};
    double t0 = 0.0, h = 0.0;
    // the state at t0 + f·h, 0 <= f <= 1
    Y at(double f) const {
        const double g = 1.0 - f;
        Y out;
        for (int i = 0; i < 2; ++i)
            out[size_t(i)] = dense[0][size_t(i)] +
                             f * (dense[1][size_t(i)] +
                                  g * (dense[2][size_t(i)] + f * (dense[3][size_t(i)] + g * dense[4][size_t(i)])));
        return out;
    }
};

template <class F>
Step dp_step(const F& f, double t, const Y& y, double h) {
    auto axpy = [&](std::initializer_list<std::pair<double, const Y*>> terms) {
        Y out = y;
        for (const auto& [c, k] : terms)
            for (int i = 0; i < 2; ++i) out[size_t(i)] += h * c * (*k)[size_t(i)];
        return out;
    };
    const Y k1 = f(t, y);
    const Y k2 = f(t + h / 5.0, axpy({{1.0 / 5.0, &k1}}));
    const Y k3 = f(t + 3.0 * h / 10.0, axpy({{3.0 / 40.0, &k1}, {9.0 / 40.0, &k2}}));
    const Y k4 = f(t + 4.0 * h / 5.0, axpy({{44.0 / 45.0, &k1}, {-56.0 / 15.0, &k2}, {32.0 / 9.0, &k3}}));
    const Y k5 = f(t + 8.0 * h / 9.0, axpy({{19372.0 / 6561.0, &k1}, {-25360.0 / 2187.0, &k2},
                                            {64448.0 / 6561.0, &k3}, {-212.0 / 729.0, &k4}}));
    const Y k6 = f(t + h, axpy({{9017.0 / 3168.0, &k1}, {-355.0 / 33.0, &k2}, {46732.0 / 5247.0, &k3},
                                {49.0 / 176.0, &k4}, {-5103.0 / 18656.0, &k5}}));
    Step s;
    s.t0 = t;
    s.h = h;
    s.y1 = axpy({{35.0 / 384.0, &k1}, {500.0 / 1113.0, &k3}, {125.0 / 192.0, &k4}, {-2187.0 / 6784.0, &k5},
                 {11.0 / 84.0, &k6}});
    const Y k7 = f(t + h, s.y1);
    for (size_t i = 0; i < 2; ++i) {
        s.err[i] = h * (71.0 / 57600.0 * k1[i] - 71.0 / 16695.0 * k3[i] + 71.0 / 1920.0 * k4[i] -
                        17253.0 / 339200.0 * k5[i] + 22.0 / 525.0 * k6[i] - 1.0 / 40.0 * k7[i]);
        const double dy = s.y1[i] - y[i], bspl = h * k1[i] - dy;
        s.dense[0][i] = y[i];
        s.dense[1][i] = dy;
        s.dense[2][i] = bspl;
        s.dense[3][i] = dy - h * k7[i] - bspl;
        s.dense[4][i] = h * (-12715105075.0 / 11282082432.0 * k1[i] + 87487479700.0 / 32700410799.0 * k3[i] -
                             10690763975.0 / 1880347072.0 * k4[i] + 701980252875.0 / 199316789632.0 * k5[i] -
                             1453857185.0 / 822651844.0 * k6[i] + 69997945.0 / 29380423.0 * k7[i]);
    }
    return s;
}

// the root of g on [a, b] with g(a) and g(b) of opposite signs (g(a) on the "before" side), to
// machine precision in t; returns the first point on the "after" side
template <class G>
double bisect(const G& g, double a, double b) {
    const bool before = g(a) > 0.0;
    for (int i = 0; i < 200 && b - a > 4.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(b)); ++i) {
        const double m = 0.5 * (a + b);
        ((g(m) > 0.0) == before ? a : b) = m;
    }
    return b;
}

constexpr int kSubsamples = 8;          // interpolant samples per step searched for events
constexpr long long kMaxSteps = 50000000LL;   // bound on the work of one run
constexpr int kMaxImpacts = 1000000;

}  // namespace

RockingOracle::RockingOracle(double b, double h, double g) : block_{b, h, g} {
    if (!(b > 0.0) || !(h > 0.0) || !(g > 0.0) || !std::isfinite(b) || !std::isfinite(h) || !std::isfinite(g))
        throw Error("rocking oracle: half-width, half-height and gravity must be positive and finite (got b = " +
                    std::to_string(b) + ", h = " + std::to_string(h) + ", g = " + std::to_string(g) + ")");
}

double RockingOracle::acceleration(int s, double theta, double a_g, double a_v, bool linear) const {
    const double a = alpha(), p2 = p() * p(), g = block_.g, x = a * s - theta;
    if (linear) return -p2 * ((1.0 + a_v / g) * x + a_g / g);
    return -p2 * ((1.0 + a_v / g) * std::sin(x) + (a_g / g) * std::cos(x));
}

double RockingOracle::energy(double theta, double omega, bool linear) const {
    const double a = alpha(), p2 = p() * p(), t = std::abs(theta);
    if (linear) return 0.5 * omega * omega + p2 * (a * t - 0.5 * t * t);
    return 0.5 * omega * omega + p2 * (std::cos(a - t) - std::cos(a));
}

double RockingOracle::uplift_threshold(double a_v, bool linear) const {
    return (block_.g + a_v) * (linear ? alpha() : std::tan(alpha()));
}

RockingResult RockingOracle::run(const BaseMotion& motion, const RockingOptions& o) const {
    const double a = alpha(), r = o.restitution < 0.0 ? housner_restitution() : o.restitution;
    if (!(o.duration > 0.0) || !std::isfinite(o.duration) || !(o.max_step > 0.0) || !(o.rtol > 0.0) || !(o.atol > 0.0))
        throw Error("rocking oracle: duration, max_step and tolerances must be positive and finite");
    if (std::abs(o.theta0) >= a || (o.theta0 == 0.0 && o.omega0 != 0.0))
        throw Error("rocking oracle: the initial rotation must satisfy |theta0| < alpha, and a block at theta0 = 0 "
                    "starts at rest");
    if (r > 1.0) throw Error("rocking oracle: the restitution must not exceed 1 (got " + std::to_string(r) + ")");
    auto ag = [&](double t) { return motion.horizontal && t >= 0.0 && t < motion.end ? motion.horizontal(t) : 0.0; };
    auto av = [&](double t) { return motion.vertical && t >= 0.0 && t < motion.end ? motion.vertical(t) : 0.0; };
    auto lifted = [&](double t) { return block_.g + av(t) <= 0.0; };

    std::vector<double> breaks = motion.breaks;
    breaks.push_back(motion.end);
    breaks.push_back(o.duration);
    std::sort(breaks.begin(), breaks.end());
    auto next_break = [&](double t) {
        auto it = std::upper_bound(breaks.begin(), breaks.end(), t * (1.0 + 1e-15) + 1e-300);
        return it == breaks.end() ? o.duration : std::min(*it, o.duration);
    };

    RockingResult res;
    const auto& outs = o.output_times;
    res.theta.assign(outs.size(), NAN);
    res.omega.assign(outs.size(), NAN);
    size_t k = 0;   // next output
    auto emit_until = [&](double t_end, const auto& state_at) {
        for (; k < outs.size() && outs[k] <= t_end; ++k) {
            const Y y = state_at(outs[k]);
            res.theta[k] = y[0];
            res.omega[k] = y[1];
        }
    };
    const double hill = energy(a, 0.0, o.linear);
    const double omega_rest = 1e-9 * p() * a;   // below this an impact leaves the block at rest

    double t = 0.0;
    Y y{o.theta0, o.omega0};
    int s = o.theta0 > 0.0 ? 1 : o.theta0 < 0.0 ? -1 : 0;
    double h = std::min(o.max_step, 1e-3 / p());
    bool first_step = true;   // of a rocking phase: bounded so that the block leaves θ = 0
    for (long long n = 0;; ++n) {
        if (n > kMaxSteps || res.impacts > kMaxImpacts)
            throw Error("rocking oracle: no end after " + std::to_string(kMaxSteps) + " steps or " +
                        std::to_string(kMaxImpacts) + " impacts (t = " + std::to_string(t) + " s)");
        if (t >= o.duration) {
            res.stop = "duration";
            break;
        }
        if (s == 0) {
            // resting: scan the uplift condition |a_g| > (g + a_v) tan α and bisect its crossing
            auto u = [&](double tt) {
                if (lifted(tt))
                    throw Error("rocking oracle: the vertical ground acceleration exceeds g at t = " +
                                std::to_string(tt) + " s: the block leaves the base");
                return std::abs(ag(tt)) - uplift_threshold(av(tt), o.linear);
            };
            if (t >= motion.end) {   // no motion left: at rest for good
                emit_until(o.duration, [](double) { return Y{0.0, 0.0}; });
                res.stop = "settled";
                break;
            }
            double tu = -1.0;
            if (u(t) > 0.0) {
                tu = t;
            } else {
                double ta = t;
                while (ta < std::min(motion.end, o.duration)) {
                    const double tb = std::min({ta + o.max_step, next_break(ta), motion.end, o.duration});
                    if (u(tb) > 0.0) {
                        tu = bisect(u, ta, tb);
                        break;
                    }
                    ta = tb;
                    ++n;
                }
            }
            if (tu < 0.0) {   // rests to the end of the motion
                t = std::min(motion.end, o.duration);
                emit_until(t, [](double) { return Y{0.0, 0.0}; });
                continue;
            }
            emit_until(tu, [](double) { return Y{0.0, 0.0}; });
            t = tu;
            y = {0.0, 0.0};
            s = ag(t) > 0.0 ? -1 : 1;   // pushed towards −x the block tips about its −x edge
            res.uplift_times.push_back(t);
            first_step = true;
            continue;
        }
        // rocking on edge s
        auto f = [&](double tt, const Y& yy) -> Y {
            if (lifted(tt))
                throw Error("rocking oracle: the vertical ground acceleration exceeds g at t = " + std::to_string(tt) +
                            " s: the block leaves the base");
            return {yy[1], acceleration(s, yy[0], ag(tt), av(tt), o.linear)};
        };
        double hmax = std::min(o.max_step, next_break(t) - t);
        if (first_step) {
            // a block leaving θ = 0 with θ̇ against its acceleration returns after 2|θ̇|/|θ̈|:
            // the first step is at most half that, so that the block is off θ = 0 at its end
            const double acc = f(t, y)[1];
            if (s * acc < 0.0 && y[1] != 0.0) hmax = std::min(hmax, 0.5 * std::abs(y[1] / acc));
        }
        h = std::min(h, hmax);
        Step st = dp_step(f, t, y, h);
        double err = 0.0;
        for (size_t i = 0; i < 2; ++i)
            err = std::max(err, std::abs(st.err[i]) / (o.atol + o.rtol * std::max(std::abs(y[i]), std::abs(st.y1[i]))));
        if (err > 1.0) {
            h *= std::max(0.1, 0.9 * std::pow(err, -0.2));
            if (h < 1e-15 * std::max(1.0, t))
                throw Error("rocking oracle: step size underflow at t = " + std::to_string(t) + " s");
            continue;
        }
        ++res.steps;
        first_step = false;
        // events on the interpolant: the first subsample at or past 0 (impact) or π/2 (overturning)
        auto side = [&](double tt) { return s * st.at((tt - st.t0) / st.h)[0]; };
        double t_event = -1.0;
        bool impact = false;
        double prev = st.t0;
        for (int i = 1; i <= kSubsamples; ++i) {
            const double ti = st.t0 + st.h * i / kSubsamples;
            const double v = side(ti);
            res.max_abs_theta = std::max(res.max_abs_theta, std::abs(v));
            if (res.exceed_time < 0.0 && v > a)
                res.exceed_time = bisect([&](double tt) { return a - side(tt); }, prev, ti);
            if (v <= 0.0) {
                t_event = bisect(side, prev, ti);
                impact = true;
                break;
            }
            if (v >= 0.5 * M_PI) {
                t_event = bisect([&](double tt) { return 0.5 * M_PI - side(tt); }, prev, ti);
                break;
            }
            prev = ti;
        }
        if (t_event < 0.0) {
            emit_until(st.t0 + st.h, [&](double tt) { return st.at((tt - st.t0) / st.h); });
            t = st.t0 + st.h;
            y = st.y1;
            h *= std::min(5.0, 0.9 * std::pow(std::max(err, 1e-10), -0.2));
            if (o.settle && t >= motion.end && k >= outs.size() && energy(y[0], y[1], o.linear) < hill * (1.0 - 1e-9)) {
                res.stop = "settled";   // free and below the hill: it can never overturn
                break;
            }
            continue;
        }
        // the state at the event by a full step from the step's start (5th order, not the interpolant)
        emit_until(t_event, [&](double tt) { return st.at((tt - st.t0) / st.h); });
        const double he = t_event - st.t0;
        if (he > 0.0) y = dp_step(f, st.t0, y, he).y1;
        t = t_event;
        if (!impact) {
            res.overturned = true;
            res.overturn_time = t;
            res.max_abs_theta = std::max(res.max_abs_theta, 0.5 * M_PI);
            for (; k < outs.size(); ++k) {
                res.theta[k] = s * 0.5 * M_PI;
                res.omega[k] = 0.0;
            }
            res.stop = "overturned";
            break;
        }
        ++res.impacts;
        res.impact_times.push_back(t);
        res.impact_omega.push_back(y[1]);
        y = {0.0, r * y[1]};
        if (std::abs(y[1]) < omega_rest) {
            s = 0;
            y = {0.0, 0.0};
        } else {
            s = -s;
            first_step = true;
        }
    }
    res.end_time = t;
    return res;
}

}  // namespace cairn::oracle

// pulses and records as base motions; the linearised one-sine closed form
#include "analytic/rocking_oracle_pulse.hpp"

#include <array>
#include <cmath>
#include <memory>

#include "error.hpp"

namespace cairn::oracle {

PulseShape parse_pulse_shape(const std::string& name) {
    if (name == "sine") return PulseShape::sine;
    if (name == "cosine") return PulseShape::cosine;
    if (name == "ricker") return PulseShape::ricker;
    throw Error("--pulse: unknown pulse shape '" + name + "' (sine, cosine, ricker)");
}

const char* to_string(PulseShape shape) {
    switch (shape) {
        case PulseShape::sine: return "sine";
        case PulseShape::cosine: return "cosine";
        case PulseShape::ricker: return "ricker";
    }
    return "?";
}

double Pulse::duration() const { return shape == PulseShape::ricker ? 16.0 / omega : 2.0 * M_PI / omega; }

double Pulse::at(double t) const {
    if (t < 0.0 || t > duration()) return 0.0;
    switch (shape) {
        case PulseShape::sine: return amplitude * std::sin(omega * t);
        case PulseShape::cosine: return amplitude * std::cos(omega * t);
        case PulseShape::ricker: {
            const double x = omega * (t - 8.0 / omega);
            return amplitude * (1.0 - 0.5 * x * x) * std::exp(-0.25 * x * x);
        }
    }
    return 0.0;
}

BaseMotion Pulse::motion() const {
    BaseMotion m;
    const Pulse copy = *this;
    m.horizontal = [copy](double t) { return copy.at(t); };
    m.end = duration();
    return m;
}

TimeSeries Pulse::sampled(double dt) const {
    if (!(dt > 0.0)) throw Error("pulse sampling step must be positive");
    const long n = std::max(1L, long(std::ceil(duration() / dt - 1e-9)));
    if (n > 10000000L) throw Error("pulse sampling: more than 1e7 samples");
    TimeSeries ts;
    for (long i = 0; i <= n; ++i) {   // n equal intervals, at most dt, ending exactly at the pulse's end
        const double t = duration() * double(i) / double(n);
        ts.time.push_back(t);
        ts.value.push_back(at(t));
    }
    return ts;
}

BaseMotion record_motion(const TimeSeries& record, double scale) {
    BaseMotion m;
    auto rec = std::make_shared<const TimeSeries>(record);
    m.horizontal = [rec, scale](double t) { return scale * rec->at(t); };
    m.end = record.time.empty() ? 0.0 : record.time.back();
    m.breaks = record.time;
    return m;
}

double LinearSinePulse::uplift_time() const {
    if (!(amplitude > g * alpha)) throw Error("linearised one-sine pulse: a_p must exceed g·alpha to uplift");
    return std::asin(g * alpha / amplitude) / omega;
}

std::array<double, 2> LinearSinePulse::state(double t) const {
    const double tu = uplift_time(), T = 2.0 * M_PI / omega, p2 = p * p;
    const double C = amplitude / g * p2 / (p2 + omega * omega);
    const double A = alpha - C * std::sin(omega * tu), B = -C * omega / p * std::cos(omega * tu);
    auto forced = [&](double x) -> std::array<double, 2> {
        const double c = std::cosh(p * (x - tu)), s = std::sinh(p * (x - tu));
        return {-alpha + C * std::sin(omega * x) + A * c + B * s, C * omega * std::cos(omega * x) + p * (A * s + B * c)};
    };
    if (t <= T) return forced(t);
    const auto e = forced(T);   // free from the end of the pulse on
    const double A2 = e[0] + alpha, B2 = e[1] / p, c = std::cosh(p * (t - T)), s = std::sinh(p * (t - T));
    return {-alpha + A2 * c + B2 * s, p * (A2 * s + B2 * c)};
}

}  // namespace cairn::oracle

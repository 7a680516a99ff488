#include "metrics/signal.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

#include <Eigen/Dense>

namespace cairn::metrics {

std::vector<double> crossings(const Series& s, double level, Crossing dir, double t_from) {
    assert(s.t.size() == s.y.size());
    std::vector<double> out;
    for (size_t i = 1; i < s.t.size(); ++i) {
        if (s.t[i] < t_from) continue;
        double a = s.y[i - 1] - level, b = s.y[i] - level;
        bool up = a < 0.0 && b >= 0.0, down = a > 0.0 && b <= 0.0;
        if ((dir == Crossing::up && !up) || (dir == Crossing::down && !down) || (!up && !down))
            continue;
        double f = a / (a - b);
        double t = s.t[i - 1] + f * (s.t[i] - s.t[i - 1]);
        if (t >= t_from) out.push_back(t);
    }
    return out;
}

namespace {
/// the extremum at sample i (0 < i < n − 1; `sign` −1 for a minimum), at the vertex of the
/// parabola through it and its neighbours where that falls between them
Extremum refined_extremum(const Series& s, size_t i, double sign) {
    const double y0 = sign * s.y[i - 1], y1 = sign * s.y[i], y2 = sign * s.y[i + 1];
    const double t0 = s.t[i - 1], t1 = s.t[i], t2 = s.t[i + 1];
    const double d1 = (y1 - y0) / (t1 - t0), d2 = (y2 - y1) / (t2 - t1);
    const double c2 = (d2 - d1) / (t2 - t0);
    Extremum e{t1, sign * y1};
    if (c2 < 0.0) {
        const double c1 = d1 - c2 * (t0 + t1);
        const double tv = -c1 / (2.0 * c2);
        if (tv > t0 && tv < t2) {
            e.t = tv;
            e.y = sign * (y1 + d1 * (tv - t1) + c2 * (tv - t0) * (tv - t1));
        }
    }
    return e;
}
}  // namespace

std::vector<Extremum> extrema(const Series& s, bool maxima, double prominence) {
    std::vector<Extremum> out;
    const double sign = maxima ? 1.0 : -1.0;
    const size_t n = s.y.size();
    double valley = n ? sign * s.y[0] : 0.0;   // lowest (signed) value since the last extremum
    for (size_t i = 1; i + 1 < n; ++i) {
        double y0 = sign * s.y[i - 1], y1 = sign * s.y[i], y2 = sign * s.y[i + 1];
        valley = std::min(valley, y1);
        if (!(y1 > y0 && y1 >= y2)) continue;
        if (y1 - valley < prominence) continue;
        out.push_back(refined_extremum(s, i, sign));
        valley = y1;
    }
    return out;
}

Swings swings(const Series& s, double prominence) {
    Swings out;
    const size_t n = s.y.size();
    // a zigzag: once the signal has swung by the prominence it is rising or falling from the
    // candidate turning point `c`, which a further rise (fall) moves on and a return by the
    // prominence confirms
    int dir = 0;
    size_t hi = 0, lo = 0, c = 0;
    double fall_to_lo = 0.0, rise_to_hi = 0.0;   // before the first swing: the swing into each
    for (size_t i = 1; i < n; ++i) {
        const double y = s.y[i];
        if (dir == 0) {
            if (y > s.y[hi]) hi = i, rise_to_hi = y - s.y[lo];
            if (y < s.y[lo]) lo = i, fall_to_lo = s.y[hi] - y;
            if (s.y[hi] - s.y[lo] >= prominence) {
                // the first swing starts from a turn where the signal came into it by the
                // prominence too, else from where the signal began
                if (hi > lo && lo > 0 && fall_to_lo >= prominence) out.minima.push_back(refined_extremum(s, lo, -1.0));
                if (lo > hi && hi > 0 && rise_to_hi >= prominence) out.maxima.push_back(refined_extremum(s, hi, 1.0));
                dir = hi > lo ? 1 : -1, c = hi > lo ? hi : lo;
            }
        } else if (dir > 0) {
            if (y > s.y[c]) c = i;
            else if (s.y[c] - y >= prominence) out.maxima.push_back(refined_extremum(s, c, 1.0)), dir = -1, c = i;
        } else {
            if (y < s.y[c]) c = i;
            else if (y - s.y[c] >= prominence) out.minima.push_back(refined_extremum(s, c, -1.0)), dir = 1, c = i;
        }
    }
    return out;
}

std::vector<double> polyfit(const Series& s, int degree, double t0, double t1) {
    std::vector<size_t> rows;
    for (size_t i = 0; i < s.t.size(); ++i)
        if (s.t[i] >= t0 && s.t[i] <= t1) rows.push_back(i);
    const int m = degree + 1;
    if (int(rows.size()) < m) return std::vector<double>(m, 0.0);
    // centre and scale the times for a well-conditioned fit
    double tc = 0.5 * (s.t[rows.front()] + s.t[rows.back()]);
    double ts = std::max(1e-300, 0.5 * (s.t[rows.back()] - s.t[rows.front()]));
    Eigen::MatrixXd a(rows.size(), m);
    Eigen::VectorXd b(rows.size());
    for (size_t r = 0; r < rows.size(); ++r) {
        double u = (s.t[rows[r]] - tc) / ts, p = 1.0;
        for (int k = 0; k < m; ++k, p *= u) a(r, k) = p;
        b(r) = s.y[rows[r]];
    }
    Eigen::VectorXd cu = a.colPivHouseholderQr().solve(b);
    // back to powers of t: Σ cu_k ((t − tc)/ts)^k
    std::vector<double> c(m, 0.0);
    for (int k = 0; k < m; ++k) {
        // expand ((t − tc)/ts)^k with the binomial theorem
        double binom = 1.0;
        for (int j = 0; j <= k; ++j) {
            c[j] += cu(k) * binom * std::pow(-tc, k - j) / std::pow(ts, k);
            binom = binom * (k - j) / (j + 1);
        }
    }
    return c;
}

HeldDrift held_drift(const Series& s, double t0, double t1, double noise) {
    Series w;
    for (size_t i = 0; i < s.t.size(); ++i)
        if (s.t[i] >= t0 && s.t[i] <= t1) w.t.push_back(s.t[i]), w.y.push_back(s.y[i]);
    HeldDrift r;
    if (w.t.size() < 2) return r;
    const double span = w.t.back() - w.t.front();
    const auto line = polyfit(w, 1);
    for (size_t i = 0; i < w.t.size(); ++i) r.ringing = std::max(r.ringing, std::abs(w.y[i] - line[0] - line[1] * w.t[i]));
    r.drift = line[1] * span;
    if (r.ringing <= noise) return r;
    // a ringing signal: a straight line through it tilts with the phase at which the window cuts
    // the swings; the lines through its maxima and through its minima do not. A turning point
    // stands a tenth of the swing about the line (or the noise, if more) above the valleys on
    // either side: a fast small ringing riding on a slow swing (undamped springs under a cyclic
    // drive) has turning points all along the swing, whose lines would tilt as the straight one does
    auto turns = swings(w, std::max(noise, 0.1 * r.ringing));
    if (turns.maxima.size() < 2 || turns.minima.size() < 2)
        // a window of about two swings: the turns at its edges are needed too, the local
        // extrema that rise (fall) by the noise from the lowest (highest) value before them
        turns = {extrema(w, true, noise), extrema(w, false, noise)};
    const auto &hi = turns.maxima, &lo = turns.minima;
    if (hi.size() < 2 || lo.size() < 2) {
        r.resolved = false;
        return r;
    }
    // each kind's line: its value at the turns' mean time (a ringing that decays within the window
    // has its turns early, and its lines, extrapolated to the window's middle, may cross there),
    // its slope, and the rms scatter of its points about it
    double turns_mid = 0.0;
    for (const auto& e : hi) turns_mid += e.t;
    for (const auto& e : lo) turns_mid += e.t;
    turns_mid /= double(hi.size() + lo.size());
    struct Line {
        double at_turns, slope, scatter;
    };
    auto fit = [&](const std::vector<Extremum>& e) {
        Series p;
        for (const auto& x : e) p.t.push_back(x.t), p.y.push_back(x.y);
        const auto c = polyfit(p, 1);
        double sq = 0.0;
        for (const auto& x : e) sq += std::pow(x.y - c[0] - c[1] * x.t, 2);
        return Line{c[0] + c[1] * turns_mid, c[1], std::sqrt(sq / double(e.size()))};
    };
    const Line top = fit(hi), bottom = fit(lo);
    const double about_line = r.ringing;   // the largest swing about the straight line
    r.drift = 0.5 * (top.slope + bottom.slope) * span;
    r.ringing = 0.5 * (top.at_turns - bottom.at_turns);
    // a ringing about a steady mean, growing, decaying or steady, has the midpoints of its
    // neighbouring turns (a maximum and the minimum next to it) along one line, and its maxima
    // above its minima; a response forced by a record, whose swings carry it to either side and
    // back with the record, does not, and lines through its turns slope with the record's
    // envelope, not with a slip (a block held within 0.4 µm under El Centro read a drift of
    // 13 µm): its drift cannot be told from its ringing
    std::vector<std::pair<Extremum, bool>> turns_in_time;   // each turn, and whether it is a maximum
    for (const auto& e : hi) turns_in_time.push_back({e, true});
    for (const auto& e : lo) turns_in_time.push_back({e, false});
    std::sort(turns_in_time.begin(), turns_in_time.end(), [](const auto& a, const auto& b) { return a.first.t < b.first.t; });
    std::vector<Extremum> mids;   // of a maximum and a minimum next to each other in time
    for (size_t i = 0; i + 1 < turns_in_time.size(); ++i) {
        const auto &a = turns_in_time[i], &b = turns_in_time[i + 1];
        if (a.second != b.second) mids.push_back({0.5 * (a.first.t + b.first.t), 0.5 * (a.first.y + b.first.y)});
    }
    const double mid_scatter = mids.size() >= 2 ? fit(mids).scatter : 0.0;
    if (!(r.ringing > 0.0) || mid_scatter > 0.25 * r.ringing) {
        r.resolved = false;
        r.unsteady = true;
        r.ringing = about_line;
    }
    return r;
}

double interpolate(const Series& s, double t) {
    assert(s.t.size() == s.y.size() && std::is_sorted(s.t.begin(), s.t.end()));
    if (s.t.empty()) return 0.0;
    if (t <= s.t.front()) return s.y.front();
    if (t >= s.t.back()) return s.y.back();
    size_t i = std::upper_bound(s.t.begin(), s.t.end(), t) - s.t.begin();
    double f = (t - s.t[i - 1]) / (s.t[i] - s.t[i - 1]);
    return s.y[i - 1] + f * (s.y[i] - s.y[i - 1]);
}

double period_from_crossings(const Series& s, double level) {
    auto c = crossings(s, level, Crossing::up);
    if (c.size() < 2) return 0.0;
    return (c.back() - c.front()) / double(c.size() - 1);
}

double max_value(const Series& s, double t0, double t1) {
    double m = -1e300;
    for (size_t i = 0; i < s.t.size(); ++i)
        if (s.t[i] >= t0 && s.t[i] <= t1) m = std::max(m, s.y[i]);
    return m;
}

double min_value(const Series& s, double t0, double t1) {
    double m = 1e300;
    for (size_t i = 0; i < s.t.size(); ++i)
        if (s.t[i] >= t0 && s.t[i] <= t1) m = std::min(m, s.y[i]);
    return m;
}

double mean_value(const Series& s, double t0, double t1) {
    double area = 0.0, span = 0.0;
    for (size_t i = 1; i < s.t.size(); ++i) {
        double a = std::max(t0, s.t[i - 1]), b = std::min(t1, s.t[i]);
        if (b <= a) continue;
        area += 0.5 * (interpolate(s, a) + interpolate(s, b)) * (b - a);
        span += b - a;
    }
    return span > 0.0 ? area / span : 0.0;
}

double rms_difference(const Series& a, const Series& b, double shift) {
    if (a.t.empty() || b.t.empty()) return 0.0;
    double sum = 0.0;
    long n = 0;
    for (size_t i = 0; i < b.t.size(); ++i) {
        double ta = b.t[i] + shift;
        if (ta < a.t.front() || ta > a.t.back()) continue;
        double d = interpolate(a, ta) - b.y[i];
        sum += d * d;
        ++n;
    }
    return n ? std::sqrt(sum / n) : 0.0;
}

}  // namespace cairn::metrics

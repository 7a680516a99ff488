#pragma once
/// Tools on sampled signals y(t): level crossings, extrema, least-squares fits, interpolation and
/// differences. Times ascend; every function is exact for the shapes it names (a line between
/// samples, a parabola through three samples).

#include <vector>

namespace cairn::metrics {

/// a sampled signal
struct Series {
    std::vector<double> t;   ///< s, ascending
    std::vector<double> y;   ///< the value at each time, any unit
};

/// direction of a level crossing
enum class Crossing { up, down, any };

/// times where y crosses `level` (linear interpolation between samples), from time t_from on
std::vector<double> crossings(const Series& s, double level, Crossing dir = Crossing::any,
                              double t_from = -1e300);

/// one extremum: time and value refined by the parabola through the sample and its neighbours
struct Extremum {
    double t = 0.0;   ///< s
    double y = 0.0;
};

/// local maxima (or minima when `maxima` is false) that stand out by more than `prominence` from
/// the lowest (highest) value since the previous one
std::vector<Extremum> extrema(const Series& s, bool maxima, double prominence);

/// the turning points of a signal's swings, maxima and minima in turn
struct Swings {
    std::vector<Extremum> maxima, minima;
};
/// turning points that stand at least `prominence` above (below) the signal on both sides before
/// the next turning point of the other kind: small wiggles along a larger swing are not turns
/// (nor is a maximum or minimum the signal begins or ends on, before it has swung into or out
/// of it by the prominence)
Swings swings(const Series& s, double prominence);

/// least-squares polynomial y ≈ c0 + c1 t + c2 t² (+ ...) of the given degree over t in [t0, t1];
/// returns the coefficients, lowest power first
std::vector<double> polyfit(const Series& s, int degree, double t0 = -1e300, double t1 = 1e300);

/// the progressive drift of a signal held about a constant value, with its ringing taken out
struct HeldDrift {
    double drift = 0.0;     ///< change over the window, signal units: the mean slope of the lines
                            ///< through its upper and lower turning points where it rings by more
                            ///< than the noise, else the slope of a straight-line fit; times the window
    double ringing = 0.0;   ///< half its peak-to-peak swing about that drift, signal units
    bool resolved = true;   ///< false: it rings by more than the noise with fewer than two turning
                            ///< points of each kind in the window, or unsteadily (the midpoints of
                            ///< its neighbouring maxima and minima scatter about their line by more
                            ///< than a quarter of the ringing, or the maxima's line is not above the
                            ///< minima's: a swing forced by a record), so drift and ringing cannot
                            ///< be told apart
    bool unsteady = false;  ///< not resolved for the second reason (ringing: then its largest swing
                            ///< about a straight line)
};

/// the drift of s over t in [t0, t1]; `noise` (signal units, > 0) is the swing below which a
/// straight-line fit is taken as it is; turning points (`swings`) must stand out by the noise, and
/// by a tenth of the largest swing about that line
HeldDrift held_drift(const Series& s, double t0, double t1, double noise);

/// y at time t, linear between samples, clamped to the ends
double interpolate(const Series& s, double t);

/// mean of the period estimates 2·(gap between successive crossings of `level`), s; 0 if fewer
/// than two crossings
double period_from_crossings(const Series& s, double level);

/// largest and smallest value, over t in [t0, t1]
double max_value(const Series& s, double t0 = -1e300, double t1 = 1e300);
double min_value(const Series& s, double t0 = -1e300, double t1 = 1e300);

/// mean of y over t in [t0, t1] (trapezoid rule)
double mean_value(const Series& s, double t0, double t1);

/// root mean square of a(t + shift) − b(t) over the times of b where both are defined
double rms_difference(const Series& a, const Series& b, double shift = 0.0);

}  // namespace cairn::metrics

// the rigid block on a Winkler base: the closed form of the partial-contact base shear against the
// shear balance integrated point by point, and the paper's stick case
#include <catch2/catch.hpp>

#include <cmath>

#include "analytic/winkler_block.hpp"

using namespace cairn::oracle;

namespace {
// the paper's stick case: 0.5 m cube, 325 kg, kn = ks = 3e7 N/m³, μ = 0.6, H = 0.5 W
const double kW = 325.0 * 9.81, kH = 0.5 * kW;
WinklerBlock paper_block() { return {0.5, 0.5, 3e7, 3e7, 0.6, kW}; }
}  // namespace

TEST_CASE("Winkler block: the paper's stick case lifts its heel, its numbers", "[oracle][winkler]") {
    const auto wb = paper_block();
    const double e = wb.eccentricity(kH, 0.25);
    CHECK(e == Approx(0.125).epsilon(1e-12));
    CHECK(e > wb.width / 6.0);   // outside the kern for any kn
    CHECK(wb.contact_length(e) == Approx(0.375).epsilon(1e-12));
    CHECK(wb.peak_penetration(e) == Approx(1.13360e-3).epsilon(1e-5));
    // (μ kn/ks) d_max [1 − √(1 − H/(μW))] = 0.6 · 1.1336e-3 · (1 − √(1/6)), worked by hand
    CHECK(wb.shear_displacement(kH, 0.25) == Approx(4.0249e-4).epsilon(1e-4));
    CHECK(wb.shear_displacement(kH, 0.25) / (kH / (3e7 * 0.25)) == Approx(1.894).epsilon(1e-3));
    // H at the base: no moment, uniform pressure, every point sticks: exactly H/(ks·A)
    CHECK(wb.shear_displacement(kH, 0.0) == Approx(kH / (3e7 * 0.25)).epsilon(1e-14));
    // at H ≥ μW it slides: no static answer
    CHECK(std::isnan(wb.shear_displacement(0.6 * kW, 0.0)));
}

TEST_CASE("Winkler block: the pressure carries W with its resultant at B/2 − e from the centre", "[oracle][winkler]") {
    const auto wb = paper_block();
    for (double e : {0.0, 0.05, wb.width / 6.0, 0.125, 0.2}) {
        INFO("e = " << e);
        // midpoint rule over the contact: W and the moment about the toe, independently of the closed forms
        const double c = wb.contact_length(e);
        const int n = 100000;
        double f = 0.0, m = 0.0;
        for (int i = 0; i < n; ++i) {
            const double s = (i + 0.5) * c / n, p = wb.kn * wb.penetration_at(e, s) * wb.depth * c / n;
            f += p;
            m += p * s;
        }
        // 1e-6: the midpoint rule's error on a piecewise-linear integrand over 1e5 cells
        CHECK(f == Approx(kW).epsilon(1e-6));
        CHECK(m / f == Approx(0.5 * wb.width - e).epsilon(1e-6));
    }
}

TEST_CASE("Winkler block: the closed form balances the base shear integrated point by point", "[oracle][winkler]") {
    const auto wb = paper_block();
    // partial contact (B/6 < e < B/2) at several loads and heights: D·∫ min(ks u, μ kn d) ds = H
    for (double frac : {0.3, 0.5, 0.8, 0.95})
        for (double h : {0.25, 0.4}) {
            const double load = frac * wb.mu * kW, e = wb.eccentricity(load, h);
            if (e <= wb.width / 6.0 || e >= 0.5 * wb.width) continue;
            INFO("H = " << frac << " μW, h = " << h);
            const double u = wb.shear_displacement(load, h);
            // 1e-6: the 20000-cell midpoint rule around the slip zone's kink
            CHECK(wb.base_shear(e, u) == Approx(load).epsilon(1e-6));
            // and u is the only root: 1 % more or less displacement does not balance
            CHECK(wb.base_shear(e, 1.01 * u) > load);
            CHECK(wb.base_shear(e, 0.99 * u) < load);
        }
    // full contact with a slipping heel (e < B/6 but μ·p_heel < ks·u): the bisection balances too,
    // and at e → B/6 it meets the partial-contact closed form
    const double load = 0.55 * kW;
    const double h_kern = wb.width / 6.0 * kW / load;
    const double u_in = wb.shear_displacement(load, h_kern * (1 - 1e-9)), u_out = wb.shear_displacement(load, h_kern * (1 + 1e-9));
    CHECK(u_in == Approx(u_out).epsilon(1e-5));
    const double u_mid = wb.shear_displacement(load, 0.5 * h_kern);
    CHECK(u_mid > load / (wb.ks * wb.width * wb.depth));
    CHECK(wb.base_shear(wb.eccentricity(load, 0.5 * h_kern), u_mid) == Approx(load).epsilon(1e-6));
}

TEST_CASE("Winkler block: the weight follows the tilt (P-Δ) and can tip a block its load alone would not", "[oracle][winkler]") {
    auto wb = paper_block();
    wb.com_height = 0.25;
    for (double frac : {0.2, 0.5, 0.8})
        for (double h : {0.1, 0.25, 0.35}) {
            const double load = frac * wb.mu * kW, e0 = load * h / kW, e = wb.eccentricity(load, h);
            INFO("H = " << frac << " μW, h = " << h);
            REQUIRE(std::isfinite(e));
            // the fixed point e = H·h/W + h_c·θ(e), to the bisection's 1e-15·B
            CHECK(e - e0 - wb.com_height * wb.tilt(e) == Approx(0.0).margin(1e-12));
            CHECK(e > e0);
            // the moment of the pressure about the base centre balances H·h plus the weight's shift,
            // by the midpoint rule (1e-6, as above); the shift is h_c·θ with θ the slope of the pressure
            const double c = wb.contact_length(e);
            const int n = 100000;
            double m = 0.0;
            for (int i = 0; i < n; ++i) {
                const double s = (i + 0.5) * c / n;
                m += wb.kn * wb.penetration_at(e, s) * wb.depth * c / n * (0.5 * wb.width - s);
            }
            const double slope = (wb.penetration_at(e, 0.0) - wb.penetration_at(e, 0.999 * c)) / (0.999 * c);
            CHECK(slope == Approx(wb.tilt(e)).epsilon(1e-9));
            CHECK(m == Approx(load * h + kW * wb.com_height * slope).epsilon(1e-6));
        }
    // without the shift the paper's case is as before; with it, 0.6 % more base shear (c 0.6 % shorter)
    CHECK(paper_block().shear_displacement(kH, 0.25) == Approx(4.0249e-4).epsilon(1e-4));
    CHECK(wb.shear_displacement(kH, 0.25) / paper_block().shear_displacement(kH, 0.25) == Approx(1.0062).epsilon(1e-3));
    // a soft base: W·h_c against the springs' rocking stiffness W·c/(6θ); at kn = 3e5 the weight's
    // shift tips the block under a load whose own eccentricity stays inside the base
    auto soft = wb;
    soft.kn = soft.ks = 3e5;
    const double load = 0.5 * wb.mu * kW, h = 0.7;   // e0 = 0.21 m < B/2
    CHECK(load * h / kW < 0.5 * wb.width);
    CHECK(std::isnan(soft.eccentricity(load, h)));
    CHECK(std::isnan(soft.shear_displacement(load, h)));
}

TEST_CASE("Winkler block: the small-rocking period on the springs", "[oracle][winkler]") {
    auto wb = paper_block();
    const double inertia = 325.0 * (0.25 + 0.25) / 3.0;   // a 0.5 m cube about a base edge
    // full contact: K = kn·D·B³/12 (e = 0)
    CHECK(wb.rocking_period(0.0, inertia) == Approx(2 * M_PI * std::sqrt(inertia / (3e7 * 0.5 * 0.125 / 12))).epsilon(1e-12));
    // partial contact: the moment M(θ) = W·(B/2 − c(θ)/3) with c = √(2W/(kn·D·θ)), differentiated
    // numerically at e = 0.125 m (the paper's case)
    const double e = 0.125, th = wb.tilt(e), dth = 1e-6 * th;
    auto moment = [&](double t) { return kW * (0.25 - std::sqrt(2 * kW / (3e7 * 0.5 * t)) / 3.0); };
    const double k = (moment(th + dth) - moment(th - dth)) / (2 * dth);
    CHECK(wb.rocking_period(e, inertia) == Approx(2 * M_PI * std::sqrt(inertia / k)).epsilon(1e-6));
    // the weight's shift softens it; past W·h_c = K it does not come back
    wb.com_height = 0.25;
    CHECK(wb.rocking_period(e, inertia) == Approx(2 * M_PI * std::sqrt(inertia / (k - kW * 0.25))).epsilon(1e-6));
    wb.com_height = 2.0 * k / kW;
    CHECK(std::isinf(wb.rocking_period(e, inertia)));
}

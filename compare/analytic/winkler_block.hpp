#pragma once
/// A rigid block on a Winkler base (normal and shear springs per unit area, elastic-then-Coulomb
/// shear at every point) under its weight W and a slow, monotonic horizontal load H applied at a
/// height h above the base: the base pressure, the contact length and the base shear displacement
/// (derivation in docs/validation.md, "friction_stick"). With `com_height` set, the weight follows
/// the block's tilt on its springs (its centre of mass moves over by h_c·θ). SI units.

namespace cairn::oracle {

/// the block's base (B along the load, D across it) and the base's springs
struct WinklerBlock {
    double width;    ///< B, base length along the load, m
    double depth;    ///< D, base length across the load, m
    double kn;       ///< normal stiffness per unit area, N/m³
    double ks;       ///< shear stiffness per unit area, N/m³
    double mu;       ///< Coulomb coefficient
    double weight;   ///< W, N
    double com_height = 0.0;   ///< h_c, centre of mass above the base, m (0: the tilt's shift of the weight left out)

    /// eccentricity of the base reaction for a load H at height h, m: e = H·h/W + h_c·θ(e), the
    /// smallest root above H·h/W (the state reached as the load grows); NaN where none is below
    /// B/2 (the load, helped by the weight's shift, tips the block)
    double eccentricity(double load, double height) const;
    /// the base's tilt under eccentricity e, rad: 12·W·e/(kn·D·B³) in full contact, d_max/c beyond
    double tilt(double e) const;
    /// period of the block's small rocking on its springs about the state of eccentricity e, s:
    /// 2π·√(I/K) with the springs' tangent stiffness dM/dθ = kn·D·B³/12 in full contact and
    /// W·c/(6θ) beyond, less W·h_c; `inertia` is the block's moment of inertia about the toe's
    /// edge, kg·m² (∞ when K ≤ 0)
    double rocking_period(double e, double inertia) const;
    /// length of base in contact: B for e ≤ B/6, 3(B/2 − e) beyond (0 at e ≥ B/2: it tips), m
    double contact_length(double e) const;
    /// largest penetration (at the toe): W/(kn·B·D)·(1 + 6e/B) in full contact, 2W/(kn·D·c) beyond, m
    double peak_penetration(double e) const;
    /// penetration at a distance s (m) from the toe, m (0 where the base has lifted)
    double penetration_at(double e, double s) const;
    /// horizontal displacement of the base under H at height h (quasi-static, monotonic); NaN if H ≥ μW
    /// (it slides) or the load tips the block, m. Full contact without slip: H/(ks·B·D); partial
    /// contact (B/6 < e < B/2): (μ·kn/ks)·d_max·[1 − √(1 − H/(μW))]; full contact with slip at the
    /// heel: solved from the shear balance by bisection
    double shear_displacement(double load, double height) const;
    /// the base shear D·∫ min(ks·u, μ·kn·d(s)) ds at a base displacement u (m) under eccentricity e, N
    double base_shear(double e, double u) const;
};

}  // namespace cairn::oracle

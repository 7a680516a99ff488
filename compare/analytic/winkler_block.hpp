#pragma once
/// A rigid block on a Winkler base (normal and shear springs per unit area, elastic-then-Coulomb
/// shear at every point) under its weight W and a slow, monotonic horizontal load H applied at a
/// height h above the base: the base pressure, the contact length and the base shear displacement
/// (derivation in docs/validation.md, "friction_stick"). SI units.

namespace cairn::oracle {

/// the block's base (B along the load, D across it) and the base's springs
struct WinklerBlock {
    double width;    ///< B, base length along the load, m
    double depth;    ///< D, base length across the load, m
    double kn;       ///< normal stiffness per unit area, N/m³
    double ks;       ///< shear stiffness per unit area, N/m³
    double mu;       ///< Coulomb coefficient
    double weight;   ///< W, N

    /// eccentricity of the base reaction e = H·h/W for a load H at height h, m
    double eccentricity(double load, double height) const;
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

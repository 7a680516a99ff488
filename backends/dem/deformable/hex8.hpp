#pragma once
/// The 8-node hexahedron: shape functions, 2x2x2 Gauss integration, and the St. Venant–Kirchhoff
/// total-Lagrangian internal force, strain energy and strain-rate (Kelvin–Voigt) damping force.

#include <array>

#include "geometry/hexahedron.hpp"

namespace cairn::dem {

using Mat83 = Eigen::Matrix<double, 8, 3>;
using Mat24 = Eigen::Matrix<double, 24, 24>;

/// shape function values of the 8 nodes at natural coordinates r
std::array<double, 8> hex8_shape(const Vec3& r);

/// shape function derivatives ∂N/∂(ξ,η,ζ) at r (8 x 3)
Mat83 hex8_dshape(const Vec3& r);

/// the 8 Gauss points (±1/√3)³, each of weight 1
const std::array<Vec3, 8>& hex8_gauss_points();

/// reference data of one element at its Gauss points
struct Hex8Reference {
    std::array<Mat83, 8> dndx;      ///< ∂N/∂X at each Gauss point, 1/m
    std::array<double, 8> weight;   ///< Gauss weight × det J at each point, m³
};

/// precompute ∂N/∂X and weights from the reference node positions (m)
Hex8Reference hex8_reference(const Corners& x_ref);

/// Lamé constants, Pa
struct Lame {
    double lambda = 0.0;
    double mu = 0.0;
};
Lame lame(double young, double poisson);

/// add the internal forces of an element (N) for current node positions x (m) to f (8 x 3);
/// returns its strain energy (J). With beta > 0 (s), also adds the strain-rate damping force
/// β·(∂f/∂x)_material·v for node velocities v and accumulates its power into *damping_power (W)
double hex8_internal_force(const Hex8Reference& ref, const Lame& lame, const Mat83& x, Mat83& f,
                           double beta = 0.0, const Mat83* v = nullptr, double* damping_power = nullptr);

/// consistent mass matrix of an element per direction (8 x 8), kg
Eigen::Matrix<double, 8, 8> hex8_consistent_mass(const Hex8Reference& ref, double density);

/// tangent stiffness at the reference state (24 x 24, node-major xyz), N/m
Mat24 hex8_stiffness(const Hex8Reference& ref, const Lame& lame);

}  // namespace cairn::dem

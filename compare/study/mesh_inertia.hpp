#pragma once
/// Rotational inertia of a meshed block's assembled mass under each mass scheme (docs/dem.md),
/// computed here independently of the engine, and the closed forms of docs/physics.md.

#include <array>

#include "geometry/hexahedron.hpp"
#include "scene/scene.hpp"

namespace cairn::study {

/// mass, centre and rotational inertia of one block's assembled mass, block frame
struct MeshInertia {
    double mass = 0.0;             ///< kg
    Vec3 centre = Vec3::Zero();    ///< centre of mass, block frame, m
    Mat3 inertia = Mat3::Zero();   ///< about the centre, block axes, kg·m²
    Mat3 exact = Mat3::Zero();     ///< the homogeneous hexahedron's, about the same centre, kg·m²
};

/// the inertia of `corners` (density kg/m³) meshed with `divisions` hex8 elements under `scheme`:
/// lumped = row sums of the consistent mass at the nodes; consistent = Σ M_ab (r_a·r_b I − r_a⊗r_b)
/// of the 3×3×3-Gauss consistent mass; barycentre = element masses at element centres plus 1e-3 of
/// the exact inertia (as the engine adds); corrected = exact
MeshInertia mesh_inertia(const Corners& corners, double density, const std::array<int, 3>& divisions,
                         MassScheme scheme);

/// moment of inertia (kg·m²) about the line through `point` along the unit `axis` (block frame),
/// by the parallel-axis theorem: axisᵀ I axis + m d², d the centre's distance from the line
double inertia_about_line(const MeshInertia& mi, const Vec3& axis, const Vec3& point);

/// a point of the bottom edge a block rocks on about `axis` (unit, block frame): the bottom edge
/// farthest along axis × z (for the shipped scenes, the pivot edge at +x), m
Vec3 rocking_edge_point(const Corners& corners, const Vec3& axis);

/// docs/physics.md's closed form of I_O / I_O,exact about a base edge of a box meshed n × n in the rocking
/// plane: 1 − 1/(4n²) barycentre (+ 1e-3 · I_c/I_O of the exact, the engine's addition when
/// `with_floor`), 1 + 1/(2n²) lumped, 1 consistent and corrected; I_c/I_O of a box is 1/4
double closed_form_edge_ratio(MassScheme scheme, int n, bool with_floor = true);

/// the same for the inertia about the centre, I_c / I_c,exact: 1 − 1/n² (+1e-3), 1 + 2/n², 1, 1
double closed_form_centre_ratio(MassScheme scheme, int n, bool with_floor = true);

}  // namespace cairn::study

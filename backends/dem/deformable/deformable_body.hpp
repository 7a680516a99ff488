#pragma once
/// A deformable block: hex8 elements (St. Venant–Kirchhoff, total Lagrangian, 2x2x2 Gauss),
/// a mass scheme, strain-rate damping β, and nodal accelerations for the explicit step.

#include <Eigen/SparseCholesky>
#include <vector>

#include "dem/deformable/hex8.hpp"
#include "dem/deformable/hex8_batch.hpp"
#include "dem/mesh.hpp"
#include "scene/scene.hpp"

namespace cairn::dem {

/// Mass scheme data and the elements of one deformable block.
class DeformableBody {
public:
    /// build from the block's mesh, material, mass scheme, β (s) and fixed nodes
    DeformableBody(const Mesh& mesh, const Material& material, MassScheme scheme, double beta,
                   const std::vector<char>& fixed_node);

    /// subtract internal (and β-damping) forces from f for positions x and velocities v;
    /// returns the strain energy (J) and sets damping_power() (W)
    double add_internal_forces(const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& f);
    /// nodal accelerations (m/s²) under the nodal forces f (N) at positions x (m) and velocities
    /// v (m/s): a = M⁻¹ f, plus for `barycentre`/`corrected` the gyroscopic term of their
    /// configuration-dependent mass (fixed nodes get zero)
    void accelerations(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const std::vector<Vec3>& f,
                       std::vector<Vec3>& a);
    /// kinetic energy ½ vᵀ M v, J
    double kinetic_energy(const std::vector<Vec3>& x, const std::vector<Vec3>& v) const;
    /// uᵀ M w with this scheme's mass at positions x (m); u, w nodal vectors (velocities: J·s²/m²·…)
    double mass_product(const std::vector<Vec3>& x, const std::vector<Vec3>& u, const std::vector<Vec3>& w) const;
    /// best-fit rigid pose: centre of mass (m) and rotation block frame → world (polar decomposition)
    void pose(const std::vector<Vec3>& x, Vec3& centre, Mat3& rotation) const;
    /// centre-of-mass velocity (m/s) and angular velocity (rad/s) of the nodes
    void motion(const std::vector<Vec3>& x, const std::vector<Vec3>& v, Vec3& velocity, Vec3& omega) const;
    /// rotational inertia of the assembled mass about the centre of mass, block axes, kg·m²
    Mat3 inertia() const;

    double mass() const { return mass_; }
    const std::vector<double>& lumped_mass() const { return lumped_; }
    double damping_power() const { return damping_power_; }
    /// largest element frequency ω_max (rad/s) of the stiffness against this mass scheme
    double max_element_omega() const { return omega_max_; }
    /// the strain-rate damping coefficient β, s
    double beta() const { return beta_; }
    /// node velocities held at zero
    const std::vector<char>& fixed_nodes() const { return fixed_; }
    /// elements processed per call of add_internal_forces
    size_t element_count() const { return elements_.size(); }
    /// after add_internal_forces: the first element with det F <= 0 at a Gauss point (turned
    /// inside out), or -1
    int inverted_element() const { return inverted_element_; }
    /// det F of that element at its worst Gauss point (<= 0)
    double inverted_det() const { return inverted_det_; }

private:
    Mat3 lumped_inertia_world(const std::vector<Vec3>& x, Vec3& centre) const;
    // the lumped inertia G about the lumped centre and the target inertia T, both world, now
    void rotation_inertias(const std::vector<Vec3>& x, Vec3& centre, Mat3& lumped, Mat3& target) const;

    MassScheme scheme_;
    Lame lame_;
    double beta_ = 0.0;
    double mass_ = 0.0;
    double omega_max_ = 0.0;
    double damping_power_ = 0.0;
    std::vector<Vec3> ref_;                          // reference node positions, block frame
    Vec3 ref_centre_ = Vec3::Zero();                 // centre of mass, block frame
    std::vector<Vec3> weighted_offset_;              // m·(X − X_c) per node, kg·m
    std::vector<std::array<int, 8>> elements_;
    Hex8Batch batch_;                                // elements packed for SIMD
    std::vector<double> lumped_;                     // row-sum node masses, kg
    std::vector<char> fixed_;
    AlignedDoubles element_forces_;                  // per element (batch layout), gathered per node
    std::vector<double> batch_energy_, batch_power_;
    std::vector<double> min_det_;                    // per element (batch layout): smallest det F
    int inverted_element_ = -1;
    double inverted_det_ = 1.0;
    std::vector<int> incidence_start_;               // node → its element forces, CSR
    std::vector<size_t> incidence_;                  // Hex8Batch::force_index of each incidence
    std::vector<int> ready_start_, ready_;           // batch → nodes whose last element it holds, CSR
    std::vector<int> first_batch_;                   // per node: batch of its first element
    // consistent mass, on the free nodes
    std::vector<int> free_index_;
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> consistent_;
    Eigen::SparseMatrix<double> consistent_matrix_;
    mutable Eigen::MatrixXd work_rhs_, work_sol_;    // free nodes × 3, preallocated for the step
    // barycentre / corrected: target rotational inertia of the rigid part, block axes
    Mat3 exact_inertia_ = Mat3::Zero();              // of the consistent mass = the exact one
    bool rotation_correction_ = false;
    Mat3 target_inertia_ = Mat3::Zero();
};

/// energy (J) taken by the mass damping αM of one implicit half kick v_new = (v_old + h·a)/(1 + α·h),
/// with the block's own M: exactly α·h·v_newᵀ M v_avg, v_avg = (v_old + v_new)/2 =
/// (1 + α·h/2)·v_new − (h/2)·a (h in s, α in 1/s, v_new in m/s, a in m/s²)
double mass_damping_loss(const DeformableBody& body, const std::vector<Vec3>& x, const std::vector<Vec3>& v_new,
                         const std::vector<Vec3>& a, double h, double alpha);

}  // namespace cairn::dem

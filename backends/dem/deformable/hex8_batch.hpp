#pragma once
/// The hex8 St. Venant–Kirchhoff internal force batched over elements for SIMD: 8 elements per
/// batch in structure-of-arrays layout. Same math as hex8_internal_force (the scalar reference),
/// arranged so that every lane does the same work:
///   ∂x/∂ξ at the Gauss points from the nodes' Walsh (sign-pattern) modes,
///   F = (∂x/∂ξ)·J⁻¹,  f_a = Σ_g (w_g·P_g·J_g⁻ᵀ)·∂N_a/∂ξ(g)  (back through the same modes).
/// Only J⁻¹ and w = det J are stored: once per element for parallelepipeds (constant Jacobian,
/// detected at build), per Gauss point otherwise.

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "dem/deformable/hex8.hpp"

namespace cairn::dem {

/// a heap array of doubles aligned for 512-bit vector loads
class AlignedDoubles {
public:
    /// resize to n zeroed values (contents are not kept)
    void assign_zero(size_t n);
    double* data() { return data_.get(); }
    const double* data() const { return data_.get(); }
    size_t size() const { return size_; }

private:
    struct Free {
        void operator()(double* p) const;
    };
    std::unique_ptr<double[], Free> data_;
    size_t size_ = 0;
};

/// elements of one mesh packed 8 per batch, with their reference Jacobians
class Hex8Batch {
public:
    /// elements per batch (SIMD lanes)
    static constexpr int kLanes = 8;
    /// doubles of element forces per batch: 8 nodes × 3 components × kLanes, lane fastest
    static constexpr int kForceStride = 8 * 3 * kLanes;

    Hex8Batch() = default;
    /// pack the elements (corner node indices, hex8 order) of reference nodes ref (m)
    Hex8Batch(const std::vector<Vec3>& ref, const std::vector<std::array<int, 8>>& elements);

    size_t batch_count() const { return batches_.size(); }
    size_t element_count() const { return elements_; }
    /// number of elements detected as parallelepipeds (constant Jacobian)
    size_t parallelepiped_count() const { return parallelepipeds_; }
    /// index of (element, local node a, component 0) in a force store; components at +kLanes
    static size_t force_index(size_t element, int a) {
        return (element / kLanes) * kForceStride + size_t(a) * 3 * kLanes + element % kLanes;
    }

    /// internal forces (N) of batch b for node positions x (m) into forces (kForceStride
    /// doubles at b·kForceStride, 64-byte aligned store); returns the batch's strain energy (J).
    /// With beta > 0 (s) adds the strain-rate damping force for velocities v (m/s) and sets
    /// power to its dissipated power (W), otherwise power = 0. min_det (kLanes doubles) receives
    /// each lane's smallest det F over its Gauss points (<= 0: the element is inverted).
    double compute(size_t b, const Lame& lame, const Vec3* x, const Vec3* v, double beta, double* forces,
                   double& power, double* min_det) const;

private:
    struct Batch {
        std::array<std::array<int, kLanes>, 8> node;  // node index of local node a, lane l
        bool parallelepiped = false;
        size_t geometry = 0;                          // offset in geometry_ of J⁻¹ and w
    };
    std::vector<Batch> batches_;
    // per batch: parallelepiped: [9 J⁻¹/8 entries][lanes], [w][lanes];
    // general: the same for each of the 8 Gauss points
    AlignedDoubles geometry_;
    size_t elements_ = 0;
    size_t parallelepipeds_ = 0;
};

/// floating-point operations of one element update without (beta = 0) or with damping, as
/// counted in Hex8Batch::compute (a fused multiply-add counts 2)
double hex8_batch_flops(bool damping);

}  // namespace cairn::dem

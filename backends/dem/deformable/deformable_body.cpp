#include "dem/deformable/deformable_body.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>
#include <map>

namespace cairn::dem {

namespace {

// ω_max² of one element: stiffness against row-sum (lumped) or consistent element mass
double element_omega2(const Hex8Reference& ref, const Lame& lm, double density, bool consistent) {
    Mat24 k = hex8_stiffness(ref, lm);
    Eigen::Matrix<double, 8, 8> mc = hex8_consistent_mass(ref, density);
    Mat24 m = Mat24::Zero();
    for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b)
            for (int d = 0; d < 3; ++d) {
                if (consistent) m(3 * a + d, 3 * b + d) = mc(a, b);
                else if (a == b) m(3 * a + d, 3 * a + d) = mc.row(a).sum();
            }
    Eigen::GeneralizedSelfAdjointEigenSolver<Mat24> es(k, m, Eigen::EigenvaluesOnly);
    return es.eigenvalues().maxCoeff();
}

// inertia tensor of point masses about a centre
Mat3 point_inertia(const Vec3& r, double m) {
    return m * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
}

}  // namespace

DeformableBody::DeformableBody(const Mesh& mesh, const Material& mat, MassScheme scheme, double beta,
                               const std::vector<char>& fixed_node)
    : scheme_(scheme), lame_(lame(mat.young, mat.poisson)), beta_(beta), ref_(mesh.nodes),
      elements_(mesh.elements), fixed_(fixed_node) {
    const size_t nn = ref_.size(), ne = elements_.size();
    lumped_.assign(nn, 0.0);
    std::vector<Eigen::Triplet<double>> mc;
    std::map<std::vector<long long>, double> omega_cache;
    Mat3 bary_inertia_about_origin = Mat3::Zero();
    Vec3 first = Vec3::Zero();
    std::vector<std::pair<Vec3, double>> centroids;
    for (const auto& e : elements_) {
        Corners c;
        for (int a = 0; a < 8; ++a) c[a] = ref_[e[a]];
        const Hex8Reference r = hex8_reference(c);
        auto me = hex8_consistent_mass(r, mat.density);
        for (int a = 0; a < 8; ++a) {
            lumped_[e[a]] += me.row(a).sum();
            for (int b = 0; b < 8; ++b) mc.emplace_back(e[a], e[b], me(a, b));
        }
        double m_el = me.sum();
        Vec3 centroid = trilinear_point(c, Vec3::Zero());
        centroids.emplace_back(centroid, m_el);
        // element frequency, cached by shape (meshes of boxes repeat one element)
        std::vector<long long> key;
        for (int a = 1; a < 8; ++a)
            for (int d = 0; d < 3; ++d) key.push_back(std::llround((c[a][d] - c[0][d]) * 1e9));
        auto it = omega_cache.find(key);
        if (it == omega_cache.end())
            it = omega_cache.emplace(key, element_omega2(r, lame_, mat.density, scheme == MassScheme::consistent)).first;
        omega_max_ = std::max(omega_max_, std::sqrt(it->second));
    }
    for (size_t n = 0; n < nn; ++n) {
        mass_ += lumped_[n];
        first += lumped_[n] * ref_[n];
    }
    ref_centre_ = first / mass_;
    // node → element incidence, for a deterministic gather of element forces
    incidence_start_.assign(nn + 1, 0);
    for (const auto& e : elements_)
        for (int a = 0; a < 8; ++a) ++incidence_start_[e[a] + 1];
    for (size_t n = 0; n < nn; ++n) incidence_start_[n + 1] += incidence_start_[n];
    incidence_.resize(incidence_start_[nn]);
    std::vector<int> fill(incidence_start_.begin(), incidence_start_.end() - 1);
    for (size_t el = 0; el < ne; ++el)
        for (int a = 0; a < 8; ++a) incidence_[fill[elements_[el][a]]++] = Hex8Batch::force_index(el, a);
    batch_ = Hex8Batch(ref_, elements_);
    element_forces_.assign_zero(batch_.batch_count() * Hex8Batch::kForceStride);
    batch_energy_.assign(batch_.batch_count(), 0.0);
    batch_power_.assign(batch_.batch_count(), 0.0);

    // exact inertia: the consistent mass integrates ρ·r⊗r exactly for trilinear geometry
    for (const auto& t : mc) {
        Vec3 ra = ref_[t.row()] - ref_centre_, rb = ref_[t.col()] - ref_centre_;
        exact_inertia_ += t.value() * (ra.dot(rb) * Mat3::Identity() - 0.5 * (ra * rb.transpose() + rb * ra.transpose()));
    }
    bool any_fixed = false;
    for (char f : fixed_) any_fixed |= f != 0;
    if (scheme_ == MassScheme::consistent) {
        // factorise the consistent mass on the free nodes once
        free_index_.assign(nn, -1);
        int nf = 0;
        for (size_t n = 0; n < nn; ++n)
            if (!fixed_[n]) free_index_[n] = nf++;
        std::vector<Eigen::Triplet<double>> red;
        for (const auto& t : mc)
            if (free_index_[t.row()] >= 0 && free_index_[t.col()] >= 0)
                red.emplace_back(free_index_[t.row()], free_index_[t.col()], t.value());
        consistent_matrix_.resize(nf, nf);
        consistent_matrix_.setFromTriplets(red.begin(), red.end());
        consistent_.compute(consistent_matrix_);
        work_rhs_.setZero(nf, 3);
        work_sol_.setZero(nf, 3);
    } else if ((scheme_ == MassScheme::barycentre || scheme_ == MassScheme::corrected) && !any_fixed) {
        rotation_correction_ = true;
        const Mat3& exact = exact_inertia_;
        if (scheme_ == MassScheme::corrected) {
            target_inertia_ = exact;
        } else {
            for (const auto& [c, m] : centroids) bary_inertia_about_origin += point_inertia(c - ref_centre_, m);
            // the paper's point masses at element barycentres; a single element has none about its
            // centre, so 1e-3 of the exact inertia keeps the mass matrix positive definite
            target_inertia_ = bary_inertia_about_origin + 1e-3 * exact;
        }
    }
}

double DeformableBody::add_internal_forces(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                           std::vector<Vec3>& f) {
    const long nb = long(batch_.batch_count()), nn = long(x.size());
    const Vec3* xp = x.data();
    const Vec3* vp = beta_ > 0.0 ? v.data() : nullptr;
    double* forces = element_forces_.data();
    // one parallel region: elements (into their own slots), then a fixed-order gather per node,
    // so the result does not depend on the thread count. Below ~16 batches a fork costs more
    // than it saves.
#pragma omp parallel if (nb >= 16)
    {
#pragma omp for schedule(static)
        for (long b = 0; b < nb; ++b)
            batch_energy_[b] = batch_.compute(size_t(b), lame_, xp, vp, beta_, forces, batch_power_[b]);
#pragma omp for schedule(static)
        for (long n = 0; n < nn; ++n) {
            double s0 = 0.0, s1 = 0.0, s2 = 0.0;
            for (int k = incidence_start_[n]; k < incidence_start_[n + 1]; ++k) {
                const double* p = forces + incidence_[k];
                s0 += p[0], s1 += p[Hex8Batch::kLanes], s2 += p[2 * Hex8Batch::kLanes];
            }
            f[n] -= Vec3(s0, s1, s2);
        }
    }
    double energy = 0.0;
    damping_power_ = 0.0;
    for (long b = 0; b < nb; ++b) energy += batch_energy_[b], damping_power_ += batch_power_[b];
    return energy;
}

Mat3 DeformableBody::lumped_inertia_world(const std::vector<Vec3>& x, Vec3& centre) const {
    centre.setZero();
    for (size_t n = 0; n < x.size(); ++n) centre += lumped_[n] * x[n];
    centre /= mass_;
    Mat3 g = Mat3::Zero();
    for (size_t n = 0; n < x.size(); ++n) g += point_inertia(x[n] - centre, lumped_[n]);
    return g;
}

void DeformableBody::accelerations(const std::vector<Vec3>& x, const std::vector<Vec3>& f, std::vector<Vec3>& a) {
    const size_t nn = x.size();
    if (scheme_ == MassScheme::consistent) {
        for (size_t n = 0; n < nn; ++n)
            if (free_index_[n] >= 0) work_rhs_.row(free_index_[n]) = f[n].transpose();
        work_sol_ = consistent_.solve(work_rhs_);   // sizes already match: no allocation
        for (size_t n = 0; n < nn; ++n)
            a[n] = free_index_[n] >= 0 ? Vec3(work_sol_.row(free_index_[n]).transpose()) : Vec3::Zero();
        return;
    }
    for (size_t n = 0; n < nn; ++n) a[n] = fixed_[n] ? Vec3::Zero() : Vec3(f[n] / lumped_[n]);
    if (!rotation_correction_) return;
    // rigid rotations get the target inertia T instead of the lumped G: a += (T⁻¹ − G⁻¹)τ × r
    Vec3 c;
    Mat3 g = lumped_inertia_world(x, c);
    Vec3 centre_ref;
    Mat3 rot;
    pose(x, centre_ref, rot);
    Mat3 t = rot * target_inertia_ * rot.transpose();
    Vec3 torque = Vec3::Zero();
    for (size_t n = 0; n < nn; ++n) torque += (x[n] - c).cross(f[n]);
    Vec3 delta = t.ldlt().solve(torque) - g.ldlt().solve(torque);
    for (size_t n = 0; n < nn; ++n) a[n] += delta.cross(x[n] - c);
}

double DeformableBody::kinetic_energy(const std::vector<Vec3>& x, const std::vector<Vec3>& v) const {
    double e = 0.0;
    if (scheme_ == MassScheme::consistent) {
        for (size_t n = 0; n < v.size(); ++n)
            if (free_index_[n] >= 0) work_rhs_.row(free_index_[n]) = v[n].transpose();
        work_sol_.noalias() = consistent_matrix_ * work_rhs_;
        return 0.5 * (work_rhs_.array() * work_sol_.array()).sum();
    }
    for (size_t n = 0; n < v.size(); ++n) e += 0.5 * lumped_[n] * v[n].squaredNorm();
    if (!rotation_correction_) return e;
    // + ½ Lᵀ C L with C = G⁻¹ (T − G) G⁻¹ on the lumped angular momentum L
    Vec3 c;
    Mat3 g = lumped_inertia_world(x, c);
    Vec3 centre_ref;
    Mat3 rot;
    pose(x, centre_ref, rot);
    Mat3 t = rot * target_inertia_ * rot.transpose();
    Vec3 l = Vec3::Zero();
    for (size_t n = 0; n < x.size(); ++n) l += lumped_[n] * (x[n] - c).cross(v[n]);
    Vec3 gl = g.ldlt().solve(l);
    return e + 0.5 * gl.dot((t - g) * gl);
}

void DeformableBody::pose(const std::vector<Vec3>& x, Vec3& centre, Mat3& rotation) const {
    centre.setZero();
    for (size_t n = 0; n < x.size(); ++n) centre += lumped_[n] * x[n];
    centre /= mass_;
    Mat3 a = Mat3::Zero();
    for (size_t n = 0; n < x.size(); ++n) a += lumped_[n] * (x[n] - centre) * (ref_[n] - ref_centre_).transpose();
    Eigen::JacobiSVD<Mat3> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Mat3 d = Mat3::Identity();
    d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
    rotation = svd.matrixU() * d * svd.matrixV().transpose();
}

void DeformableBody::motion(const std::vector<Vec3>& x, const std::vector<Vec3>& v, Vec3& velocity,
                            Vec3& omega) const {
    Vec3 c;
    Mat3 g = lumped_inertia_world(x, c);
    velocity.setZero();
    for (size_t n = 0; n < v.size(); ++n) velocity += lumped_[n] * v[n];
    velocity /= mass_;
    Vec3 l = Vec3::Zero();
    for (size_t n = 0; n < x.size(); ++n) l += lumped_[n] * (x[n] - c).cross(v[n] - velocity);
    omega = g.ldlt().solve(l);
}

Mat3 DeformableBody::inertia() const {
    if (rotation_correction_) return target_inertia_;
    if (scheme_ == MassScheme::consistent) return exact_inertia_;
    Mat3 i = Mat3::Zero();
    for (size_t n = 0; n < ref_.size(); ++n) i += point_inertia(ref_[n] - ref_centre_, lumped_[n]);
    return i;
}

}  // namespace cairn::dem

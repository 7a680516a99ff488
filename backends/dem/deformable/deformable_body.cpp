#include "dem/deformable/deformable_body.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <map>

#ifdef _OPENMP
#include <omp.h>
#endif

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
    for (size_t n = 0; n < nn; ++n) weighted_offset_.push_back(lumped_[n] * (ref_[n] - ref_centre_));
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
    // nodes by the batch of their last element (ready to gather after it), and their first batch
    {
        const int nb = int(batch_.batch_count());
        std::vector<int> last(nn, -1);
        first_batch_.assign(nn, nb);
        for (size_t el = 0; el < ne; ++el)
            for (int a = 0; a < 8; ++a) {
                const int n = elements_[el][a], b = int(el / Hex8Batch::kLanes);
                last[n] = std::max(last[n], b);
                first_batch_[n] = std::min(first_batch_[n], b);
            }
        ready_start_.assign(nb + 1, 0);
        for (size_t n = 0; n < nn; ++n)
            if (last[n] >= 0) ++ready_start_[last[n] + 1];
        for (int b = 0; b < nb; ++b) ready_start_[b + 1] += ready_start_[b];
        ready_.resize(ready_start_[nb]);
        std::vector<int> slot(ready_start_.begin(), ready_start_.end() - 1);
        for (size_t n = 0; n < nn; ++n)
            if (last[n] >= 0) ready_[slot[last[n]]++] = int(n);
    }
    batch_power_.assign(batch_.batch_count(), 0.0);
    min_det_.assign(batch_.batch_count() * Hex8Batch::kLanes, 1.0);

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
    const long nb = long(batch_.batch_count());
    const Vec3* xp = x.data();
    const Vec3* vp = beta_ > 0.0 ? v.data() : nullptr;
    double* forces = element_forces_.data();
    // the sum of a node's element forces, always in its incidence order: the result does not
    // depend on which thread gathers it
    auto gather = [&](int n) {
        double s0 = 0.0, s1 = 0.0, s2 = 0.0;
        for (int k = incidence_start_[n]; k < incidence_start_[n + 1]; ++k) {
            const double* p = forces + incidence_[k];
            s0 += p[0], s1 += p[Hex8Batch::kLanes], s2 += p[2 * Hex8Batch::kLanes];
        }
        f[n] -= Vec3(s0, s1, s2);
    };
    // each thread takes a contiguous range of batches and walks it in chunks, gathering a node as
    // soon as its last element is done (the element forces are still in cache); nodes that also
    // touch an earlier thread's range wait for the barrier. Below ~16 batches a fork costs more
    // than it saves.
    constexpr long kChunk = 16;
    if (nb < 16) {
        for (long b = 0; b < nb; ++b)
            batch_energy_[b] = batch_.compute(size_t(b), lame_, xp, vp, beta_, forces, batch_power_[b],
                                              min_det_.data() + b * Hex8Batch::kLanes);
        for (int n : ready_) gather(n);
    } else {
#pragma omp parallel
        {
            long t = 0, nt = 1;
#ifdef _OPENMP
            t = omp_get_thread_num();
            nt = omp_get_num_threads();
#endif
            const long b0 = nb * t / nt, b1 = nb * (t + 1) / nt;
            for (long c0 = b0; c0 < b1; c0 += kChunk) {
                const long c1 = std::min(c0 + kChunk, b1);
                for (long b = c0; b < c1; ++b)
                    batch_energy_[b] = batch_.compute(size_t(b), lame_, xp, vp, beta_, forces, batch_power_[b],
                                              min_det_.data() + b * Hex8Batch::kLanes);
                for (int k = ready_start_[c0]; k < ready_start_[c1]; ++k)
                    if (first_batch_[ready_[k]] >= b0) gather(ready_[k]);
            }
#pragma omp barrier
            for (int k = ready_start_[b0]; k < ready_start_[b1]; ++k)
                if (first_batch_[ready_[k]] < b0) gather(ready_[k]);
        }
    }
    double energy = 0.0;
    damping_power_ = 0.0;
    for (long b = 0; b < nb; ++b) energy += batch_energy_[b], damping_power_ += batch_power_[b];
    // the first inverted element, in element order (padding lanes repeat the last real element)
    inverted_element_ = -1;
    for (size_t e = 0; e < elements_.size(); ++e)
        if (min_det_[e] <= 0.0) {
            inverted_element_ = int(e);
            inverted_det_ = min_det_[e];
            break;
        }
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

void DeformableBody::rotation_inertias(const std::vector<Vec3>& x, Vec3& centre, Mat3& lumped, Mat3& target) const {
    lumped = lumped_inertia_world(x, centre);
    Vec3 centre_fit;
    Mat3 rot;
    pose(x, centre_fit, rot);
    target = rot * target_inertia_ * rot.transpose();
}

void DeformableBody::accelerations(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                   const std::vector<Vec3>& f, std::vector<Vec3>& a) {
    const size_t nn = x.size();
    if (scheme_ == MassScheme::consistent) {
        for (size_t n = 0; n < nn; ++n)
            if (free_index_[n] >= 0) work_rhs_.row(free_index_[n]) = f[n].transpose();
        // M⁻¹ = P⁻¹ L⁻ᵀ L⁻¹ P written out: Eigen's solve() allocates a temporary for the permutations
        const auto& perm = consistent_.permutationP().indices();
        if (perm.size() > 0) {
            for (Eigen::Index i = 0; i < perm.size(); ++i) work_sol_.row(perm[i]) = work_rhs_.row(i);
        } else {
            work_sol_ = work_rhs_;
        }
        consistent_.matrixL().solveInPlace(work_sol_);
        consistent_.matrixU().solveInPlace(work_sol_);
        if (perm.size() > 0) {
            for (Eigen::Index i = 0; i < perm.size(); ++i) work_rhs_.row(i) = work_sol_.row(perm[i]);
            work_sol_.swap(work_rhs_);
        }
        for (size_t n = 0; n < nn; ++n)
            a[n] = free_index_[n] >= 0 ? Vec3(work_sol_.row(free_index_[n]).transpose()) : Vec3::Zero();
        return;
    }
    for (size_t n = 0; n < nn; ++n) a[n] = fixed_[n] ? Vec3::Zero() : Vec3(f[n] / lumped_[n]);
    if (!rotation_correction_) return;
    // the lumped nodes alone turn as a body of inertia G: ω̇ = G⁻¹(τ − ω×Gω). The rigid rotation
    // must follow Euler's equation with the target inertia T, ω̇ = T⁻¹(τ − ω×Tω): add the
    // difference as a rigid angular acceleration, a += δ × r, with ω = G⁻¹L of the lumped nodes
    // (exact for a rigid motion). Without the gyroscopic terms this is the (T⁻¹ − G⁻¹)τ of the
    // mass matrix alone; they cancel only where T is proportional to G.
    Vec3 c;
    Mat3 g, t;
    rotation_inertias(x, c, g, t);
    Vec3 torque = Vec3::Zero(), momentum = Vec3::Zero();
    for (size_t n = 0; n < nn; ++n) {
        torque += (x[n] - c).cross(f[n]);
        momentum += lumped_[n] * (x[n] - c).cross(v[n]);
    }
    const auto g_ldlt = g.ldlt();
    const Vec3 w = g_ldlt.solve(momentum);
    const Vec3 delta = t.ldlt().solve(torque - w.cross(t * w)) - g_ldlt.solve(torque - w.cross(g * w));
    for (size_t n = 0; n < nn; ++n) a[n] += delta.cross(x[n] - c);
}

double DeformableBody::kinetic_energy(const std::vector<Vec3>& x, const std::vector<Vec3>& v) const {
    return 0.5 * mass_product(x, v, v);
}

double DeformableBody::mass_product(const std::vector<Vec3>& x, const std::vector<Vec3>& u,
                                    const std::vector<Vec3>& w) const {
    if (scheme_ == MassScheme::consistent) {
        for (size_t n = 0; n < w.size(); ++n)
            if (free_index_[n] >= 0) work_rhs_.row(free_index_[n]) = w[n].transpose();
        work_sol_.noalias() = consistent_matrix_ * work_rhs_;
        double e = 0.0;
        for (size_t n = 0; n < u.size(); ++n)
            if (free_index_[n] >= 0) e += u[n].dot(Vec3(work_sol_.row(free_index_[n]).transpose()));
        return e;
    }
    double e = 0.0;
    for (size_t n = 0; n < u.size(); ++n) e += lumped_[n] * u[n].dot(w[n]);
    if (!rotation_correction_) return e;
    // + L(u)ᵀ C L(w) with C = G⁻¹ (T − G) G⁻¹ on the lumped angular momenta L
    Vec3 c;
    Mat3 g, t;
    rotation_inertias(x, c, g, t);
    Vec3 lu = Vec3::Zero(), lw = Vec3::Zero();
    for (size_t n = 0; n < x.size(); ++n) {
        lu += lumped_[n] * (x[n] - c).cross(u[n]);
        lw += lumped_[n] * (x[n] - c).cross(w[n]);
    }
    const auto g_ldlt = g.ldlt();
    return e + g_ldlt.solve(lu).dot((t - g) * g_ldlt.solve(lw));
}

void DeformableBody::pose(const std::vector<Vec3>& x, Vec3& centre, Mat3& rotation) const {
    // one pass: Σ m(x − c)(X − X_c)ᵀ = Σ x·(m(X − X_c))ᵀ since Σ m(X − X_c) = 0
    double c0 = 0, c1 = 0, c2 = 0, a[3][3] = {};
    for (size_t n = 0; n < x.size(); ++n) {
        const double* p = x[n].data();
        const double* r = weighted_offset_[n].data();
        const double m = lumped_[n];
        c0 += m * p[0], c1 += m * p[1], c2 += m * p[2];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) a[i][j] += p[i] * r[j];
    }
    centre = Vec3(c0, c1, c2) / mass_;
    Mat3 am;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) am(i, j) = a[i][j];
    Eigen::JacobiSVD<Mat3> svd(am, Eigen::ComputeFullU | Eigen::ComputeFullV);
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

double mass_damping_loss(const DeformableBody& body, const std::vector<Vec3>& x, const std::vector<Vec3>& v_new,
                         const std::vector<Vec3>& a, double h, double alpha) {
    return alpha * h * ((1.0 + 0.5 * alpha * h) * body.mass_product(x, v_new, v_new) - 0.5 * h * body.mass_product(x, v_new, a));
}

}  // namespace cairn::dem

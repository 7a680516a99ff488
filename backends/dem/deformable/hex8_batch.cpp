#include "dem/deformable/hex8_batch.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>
#include <stdexcept>

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

namespace cairn::dem {

void AlignedDoubles::Free::operator()(double* p) const { std::free(p); }

void AlignedDoubles::assign_zero(size_t n) {
    const size_t bytes = ((n * sizeof(double) + 63) / 64) * 64;
    double* p = static_cast<double*>(std::aligned_alloc(64, bytes == 0 ? 64 : bytes));
    if (!p) throw std::bad_alloc();
    std::memset(p, 0, bytes == 0 ? 64 : bytes);
    data_.reset(p);
    size_ = n;
}

namespace {

constexpr int L = Hex8Batch::kLanes;
// one value per lane; GCC/Clang vector extension, lowered to the widest registers available
typedef double vd __attribute__((vector_size(L * sizeof(double))));

inline vd load(const double* p) {
    vd r;
    std::memcpy(&r, p, sizeof r);
    return r;
}
inline void store(double* p, vd v) { std::memcpy(p, &v, sizeof v); }
inline vd splat(double s) { return vd{} + s; }
inline vd fma(vd a, vd b, vd c) {
#if defined(__AVX512F__)
    return (vd)_mm512_fmadd_pd((__m512d)a, (__m512d)b, (__m512d)c);
#else
    return a * b + c;
#endif
}
inline double lane_sum(vd v) {
    double s = 0.0;
    for (int l = 0; l < L; ++l) s += v[l];   // fixed order: deterministic
    return s;
}

// out[c][slot] = p[3·node[l] + c] for the lanes l (Vec3 arrays are packed xyz triples)
inline void gather(const int* node, const double* p, vd out[3][8], int slot) {
#if defined(__AVX512F__)
    const __m256i idx = _mm256_mullo_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(node)),
                                           _mm256_set1_epi32(3));
    for (int c = 0; c < 3; ++c) out[c][slot] = (vd)_mm512_i32gather_pd(idx, p + c, 8);
#else
    for (int c = 0; c < 3; ++c)
        for (int l = 0; l < L; ++l) out[c][slot][l] = p[3 * node[l] + c];
#endif
}

// the corner signs of kCornerSigns, as compile-time constants
constexpr int kSign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                             {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
// Walsh index of corner a: bit d set where its sign along d is −1
constexpr int walsh_index(int a) {
    return (kSign[a][0] < 0 ? 1 : 0) | (kSign[a][1] < 0 ? 2 : 0) | (kSign[a][2] < 0 ? 4 : 0);
}

// in place: u[S] ← Σ_T (−1)^|S∧T| u[T]; with u[T_a] = x_a this gives the sign-pattern modes
// m_S = Σ_a (Π_{d∈S} s_ad)·x_a, and applied to modes it gives back Σ_S (Π s_ad)·φ_S per corner
inline void walsh(vd* u) {
    for (int d = 1; d < 8; d <<= 1)
        for (int i = 0; i < 8; ++i)
            if (!(i & d)) {
                const vd a = u[i], b = u[i | d];
                u[i] = a + b;
                u[i | d] = a - b;
            }
}

// the two directions other than k, ascending
constexpr int kOther[3][2] = {{1, 2}, {0, 2}, {0, 1}};

// 8·∂x_c/∂ξ_k at the 4 sign combinations (σ_d1, σ_d2) of the other two Gauss coordinates
// (index bit 0: σ_d1 > 0, bit 1: σ_d2 > 0), from the modes m of component c:
// 8·∂x/∂ξ_k = m_k + r_d1·m_{k,d1} + r_d2·m_{k,d2} + r_d1·r_d2·m_{k,d1,d2}
inline void natural_gradient(const vd* m, double g, vd out[3][4]) {
    const vd g01 = g * m[3], g02 = g * m[5], g12 = g * m[6], g2m = (g * g) * m[7];
    const vd mk[3] = {m[1], m[2], m[4]};
    const vd p1[3] = {g01, g01, g02};   // r_d1 mode of k: {0,1}, {0,1}, {0,2}
    const vd p2[3] = {g02, g12, g12};   // r_d2 mode of k: {0,2}, {1,2}, {1,2}
    for (int k = 0; k < 3; ++k) {
        const vd am = mk[k] - p1[k], ap = mk[k] + p1[k];
        const vd bm = p2[k] - g2m, bp = p2[k] + g2m;
        out[k][0] = am - bm;
        out[k][1] = ap - bp;
        out[k][2] = am + bm;
        out[k][3] = ap + bp;
    }
}

template <bool kParallelepiped, bool kDamping>
double batch_force(const std::array<std::array<int, L>, 8>& node, const double* geom, const Lame& lm,
                   const Vec3* x, const Vec3* v, double beta, double* out, double& power, double* min_det) {
    const double g = 1.0 / std::sqrt(3.0);
    // gather the nodes per component in Walsh order, then their modes
    vd xm[3][8], vm[3][8];
    for (int a = 0; a < 8; ++a) gather(node[a].data(), x[0].data(), xm, walsh_index(a));
    if (kDamping)
        for (int a = 0; a < 8; ++a) gather(node[a].data(), v[0].data(), vm, walsh_index(a));
    vd xg[3][3][4], vg[3][3][4];   // [component][k][sign combination]
    for (int c = 0; c < 3; ++c) {
        walsh(xm[c]);
        natural_gradient(xm[c], g, xg[c]);
        if (kDamping) {
            walsh(vm[c]);
            natural_gradient(vm[c], g, vg[c]);
        }
    }
    const vd two_mu = splat(2.0 * lm.mu), lambda = splat(lm.lambda), half_lambda = splat(0.5 * lm.lambda);
    const vd mu = splat(lm.mu), two_mu_beta = splat(2.0 * lm.mu * beta), lambda_beta = splat(lm.lambda * beta);
    vd energy = vd{}, pw = vd{};
    double det_min[L];   // per lane: the smallest det F over the Gauss points (inversion check)
    for (int l = 0; l < L; ++l) det_min[l] = 1e300;
    // acc[c][k]: Σ_g Q_ck·{1, σ_d1, σ_d2, σ_d1·σ_d2} with Q = w·P·J⁻ᵀ/8
    vd acc[3][3][4] = {};
    for (int gp = 0; gp < 8; ++gp) {
        const int sg[3] = {(gp & 1) ? 1 : -1, (gp & 2) ? 1 : -1, (gp & 4) ? 1 : -1};
        const double* gq = kParallelepiped ? geom : geom + gp * 10 * L;
        vd ji[3][3];   // J⁻¹/8
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) ji[k][j] = load(gq + (3 * k + j) * L);
        const vd w = load(gq + 9 * L);
        int combo[3];
        for (int k = 0; k < 3; ++k)
            combo[k] = (sg[kOther[k][0]] > 0 ? 1 : 0) | (sg[kOther[k][1]] > 0 ? 2 : 0);
        vd f[3][3], fd[3][3];
        for (int c = 0; c < 3; ++c)
            for (int j = 0; j < 3; ++j) {
                f[c][j] = fma(xg[c][2][combo[2]], ji[2][j], fma(xg[c][1][combo[1]], ji[1][j], xg[c][0][combo[0]] * ji[0][j]));
                if (kDamping)
                    fd[c][j] = fma(vg[c][2][combo[2]], ji[2][j], fma(vg[c][1][combo[1]], ji[1][j], vg[c][0][combo[0]] * ji[0][j]));
            }
        // det F: an element turned inside out has det F <= 0 at some Gauss point
        const vd det = f[0][0] * (f[1][1] * f[2][2] - f[1][2] * f[2][1]) -
                       f[0][1] * (f[1][0] * f[2][2] - f[1][2] * f[2][0]) +
                       f[0][2] * (f[1][0] * f[2][1] - f[1][1] * f[2][0]);
        for (int l = 0; l < L; ++l) det_min[l] = det[l] < det_min[l] ? det[l] : det_min[l];
        // Green–Lagrange strain E = ½(FᵀF − I), symmetric: 00 11 22 01 02 12
        constexpr int I[6] = {0, 1, 2, 0, 0, 1}, J[6] = {0, 1, 2, 1, 2, 2};
        vd e[6], s[6];
        for (int q = 0; q < 6; ++q) {
            const vd cq = fma(f[2][I[q]], f[2][J[q]], fma(f[1][I[q]], f[1][J[q]], f[0][I[q]] * f[0][J[q]]));
            e[q] = q < 3 ? 0.5 * (cq - 1.0) : 0.5 * cq;
        }
        const vd tr = e[0] + e[1] + e[2];
        const vd lt = lambda * tr;
        for (int q = 0; q < 6; ++q) s[q] = q < 3 ? fma(two_mu, e[q], lt) : two_mu * e[q];
        const vd ee = fma(e[2], e[2], fma(e[1], e[1], e[0] * e[0])) +
                      2.0 * fma(e[5], e[5], fma(e[4], e[4], e[3] * e[3]));
        energy = fma(w, fma(half_lambda, tr * tr, mu * ee), energy);
        if (kDamping) {
            // Kelvin–Voigt: Ė = sym(FᵀḞ), S_v = β·(2μĖ + λ·tr Ė·I)
            vd ed[6];
            for (int q = 0; q < 6; ++q) {
                const vd a = fma(f[2][I[q]], fd[2][J[q]], fma(f[1][I[q]], fd[1][J[q]], f[0][I[q]] * fd[0][J[q]]));
                if (q < 3) {
                    ed[q] = a;
                } else {
                    const vd b = fma(fd[2][I[q]], f[2][J[q]], fma(fd[1][I[q]], f[1][J[q]], fd[0][I[q]] * f[0][J[q]]));
                    ed[q] = 0.5 * (a + b);
                }
            }
            const vd ltd = lambda_beta * (ed[0] + ed[1] + ed[2]);
            vd sv[6];
            for (int q = 0; q < 6; ++q) sv[q] = q < 3 ? fma(two_mu_beta, ed[q], ltd) : two_mu_beta * ed[q];
            const vd sd = fma(sv[2], ed[2], fma(sv[1], ed[1], sv[0] * ed[0])) +
                          2.0 * fma(sv[5], ed[5], fma(sv[4], ed[4], sv[3] * ed[3]));
            pw = fma(w, sd, pw);
            for (int q = 0; q < 6; ++q) s[q] += sv[q];
        }
        for (int q = 0; q < 6; ++q) s[q] *= w;
        const vd sm[3][3] = {{s[0], s[3], s[4]}, {s[3], s[1], s[5]}, {s[4], s[5], s[2]}};
        for (int c = 0; c < 3; ++c) {
            vd p[3];   // row c of w·F·S
            for (int j = 0; j < 3; ++j) p[j] = fma(f[c][2], sm[2][j], fma(f[c][1], sm[1][j], f[c][0] * sm[0][j]));
            for (int k = 0; k < 3; ++k) {
                const vd qk = fma(p[2], ji[k][2], fma(p[1], ji[k][1], p[0] * ji[k][0]));
                const int s1 = sg[kOther[k][0]], s2 = sg[kOther[k][1]];
                acc[c][k][0] += qk;
                acc[c][k][1] = s1 > 0 ? acc[c][k][1] + qk : acc[c][k][1] - qk;
                acc[c][k][2] = s2 > 0 ? acc[c][k][2] + qk : acc[c][k][2] - qk;
                acc[c][k][3] = s1 * s2 > 0 ? acc[c][k][3] + qk : acc[c][k][3] - qk;
            }
        }
    }
    // back to the corners: φ_S is the coefficient of Π_{d∈S} s_ad in f_a
    for (int c = 0; c < 3; ++c) {
        const vd(&a)[3][4] = acc[c];
        vd phi[8];
        phi[0] = vd{};
        phi[1] = a[0][0];
        phi[2] = a[1][0];
        phi[4] = a[2][0];
        phi[3] = g * (a[0][1] + a[1][1]);   // k=0 with r_1, k=1 with r_0
        phi[5] = g * (a[0][2] + a[2][1]);   // k=0 with r_2, k=2 with r_0
        phi[6] = g * (a[1][2] + a[2][2]);   // k=1 with r_2, k=2 with r_1
        phi[7] = (g * g) * (a[0][3] + a[1][3] + a[2][3]);
        walsh(phi);
        for (int n = 0; n < 8; ++n) store(out + (3 * n + c) * L, phi[walsh_index(n)]);
    }
    for (int l = 0; l < L; ++l) min_det[l] = det_min[l];
    power = kDamping ? lane_sum(pw) : 0.0;
    return lane_sum(energy);
}

// modes of a reference element per component: m[c][S]
void reference_modes(const Corners& c, double m[3][8]) {
    for (int d = 0; d < 3; ++d) {
        vd u[8];
        for (int a = 0; a < 8; ++a) u[walsh_index(a)] = splat(c[a][d]);
        walsh(u);
        for (int s = 0; s < 8; ++s) m[d][s] = u[s][0];
    }
}

}  // namespace

Hex8Batch::Hex8Batch(const std::vector<Vec3>& ref, const std::vector<std::array<int, 8>>& elements)
    : elements_(elements.size()) {
    for (int a = 0; a < 8; ++a)
        for (int d = 0; d < 3; ++d)
            if (kSign[a][d] != kCornerSigns[a][d]) throw std::logic_error("hex8_batch: corner order changed");
    const size_t nb = (elements.size() + L - 1) / L;
    batches_.resize(nb);
    std::vector<Corners> corners(elements.size());
    std::vector<char> par(elements.size());
    size_t geometry_size = 0;
    for (size_t b = 0; b < nb; ++b) {
        Batch& batch = batches_[b];
        batch.parallelepiped = true;
        for (int l = 0; l < L; ++l) {
            const size_t el = std::min(b * L + l, elements.size() - 1);   // padding repeats a real element
            for (int a = 0; a < 8; ++a) batch.node[a][l] = elements[el][a];
            if (b * L + l >= elements.size()) continue;
            for (int a = 0; a < 8; ++a) corners[el][a] = ref[elements[el][a]];
            double m[3][8];
            reference_modes(corners[el], m);
            // affine map ⇔ the modes of two and three signs vanish
            double size = 0.0, twist = 0.0;
            for (int d = 0; d < 3; ++d) {
                for (int s : {1, 2, 4}) size = std::max(size, std::abs(m[d][s]));
                for (int s : {3, 5, 6, 7}) twist = std::max(twist, std::abs(m[d][s]));
            }
            par[el] = twist <= 1e-13 * size;
            parallelepipeds_ += par[el];
            batch.parallelepiped = batch.parallelepiped && par[el];
        }
        batch.geometry = geometry_size;
        geometry_size += (batch.parallelepiped ? 1 : 8) * 10 * L;
    }
    geometry_.assign_zero(geometry_size);
    const double g = 1.0 / std::sqrt(3.0);
    for (size_t el = 0; el < elements.size(); ++el) {
        const Batch& batch = batches_[el / L];
        double* base = geometry_.data() + batch.geometry + el % L;
        double m[3][8];
        reference_modes(corners[el], m);
        for (int gp = 0; gp < (batch.parallelepiped ? 1 : 8); ++gp) {
            const double r[3] = {(gp & 1) ? g : -g, (gp & 2) ? g : -g, (gp & 4) ? g : -g};
            Mat3 jac;   // ∂X_i/∂ξ_k
            for (int i = 0; i < 3; ++i) {
                const double* mi = m[i];
                if (batch.parallelepiped) {
                    jac(i, 0) = mi[1] / 8, jac(i, 1) = mi[2] / 8, jac(i, 2) = mi[4] / 8;
                } else {
                    jac(i, 0) = (mi[1] + r[1] * mi[3] + r[2] * mi[5] + r[1] * r[2] * mi[7]) / 8;
                    jac(i, 1) = (mi[2] + r[0] * mi[3] + r[2] * mi[6] + r[0] * r[2] * mi[7]) / 8;
                    jac(i, 2) = (mi[4] + r[0] * mi[5] + r[1] * mi[6] + r[0] * r[1] * mi[7]) / 8;
                }
            }
            const Mat3 inv = jac.inverse() / 8.0;
            double* q = base + gp * 10 * L;
            for (int k = 0; k < 3; ++k)
                for (int j = 0; j < 3; ++j) q[(3 * k + j) * L] = inv(k, j);
            q[9 * L] = jac.determinant();   // Gauss weight 1
        }
    }
}

double Hex8Batch::compute(size_t b, const Lame& lame, const Vec3* x, const Vec3* v, double beta, double* forces,
                          double& power, double* min_det) const {
    const Batch& batch = batches_[b];
    const double* geom = geometry_.data() + batch.geometry;
    double* out = forces + b * kForceStride;
    const bool damping = beta > 0.0 && v != nullptr;
    if (batch.parallelepiped)
        return damping ? batch_force<true, true>(batch.node, geom, lame, x, v, beta, out, power, min_det)
                       : batch_force<true, false>(batch.node, geom, lame, x, v, beta, out, power, min_det);
    return damping ? batch_force<false, true>(batch.node, geom, lame, x, v, beta, out, power, min_det)
                   : batch_force<false, false>(batch.node, geom, lame, x, v, beta, out, power, min_det);
}

double hex8_batch_flops(bool damping) {
    // per element, as coded above (fused multiply-add = 2; sign accumulations = 1)
    const double modes = 3 * 24, gradients = 3 * (4 + 3 * 8);
    const double per_gp = 54      // F = (∂x/∂ξ)·J⁻¹
                          + 14    // det F (inversion check)
                          + 30    // FᵀF
                          + 11    // E, tr E
                          + 10    // S
                          + 21    // energy
                          + 6     // w·S
                          + 54    // w·F·S
                          + 54    // ·J⁻ᵀ
                          + 36;   // mode sums
    const double back = 3 * (9 + 24);
    double flops = modes + gradients + 8 * per_gp + back;
    if (damping) flops += modes + gradients + 8 * (54 + 51 + 2 + 10 + 15 + 6);
    return flops;
}

}  // namespace cairn::dem

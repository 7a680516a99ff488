#include "block_limit_analysis.hpp"

#include <glpk.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "block_interfaces.hpp"
#include "error.hpp"
#include "geometry/overlap.hpp"

namespace cairn::oracle {

namespace {

/// the programme in columns: column 0 is λ, then one per friction-pyramid edge per contact
/// point; six equilibrium rows per free block (force, then moment about its centre of mass),
/// forces in units of the free blocks' mean weight, lengths of their mean size
struct Programme {
    std::vector<int> start{0};     // column j's entries are [start[j], start[j + 1])
    std::vector<int> rows;         // 0-based
    std::vector<double> values;
    std::vector<char> initial;     // per column: in the first restricted programme
    std::vector<double> rhs;       // per row
    int columns() const { return int(start.size()) - 1; }
    /// entry v in the open column; round-off below 1e-12 (the entries are of order 1) left
    /// out: GLPK's geometric-mean scaling turns a row holding 1e-16 beside 1 into one whose
    /// right-hand side falls below its feasibility tolerance
    void entry(int row, double v) {
        if (std::abs(v) < 1e-12) return;
        rows.push_back(row);
        values.push_back(v);
    }
    void close_column(bool in_first) {
        start.push_back(int(rows.size()));
        initial.push_back(in_first);
    }
};

/// (cos, sin) of k·π/4, exact zeros included
constexpr double kHalfRoot2 = 0.70710678118654752440;
constexpr double kOctagon[8][2] = {{1, 0}, {kHalfRoot2, kHalfRoot2}, {0, 1}, {-kHalfRoot2, kHalfRoot2},
                                   {-1, 0}, {-kHalfRoot2, -kHalfRoot2}, {0, -1}, {kHalfRoot2, -kHalfRoot2}};

/// the joint's first tangent: the live load's direction in its plane, else gravity's, else the
/// polygon's first edge (all turn with the assembly)
Vec3 first_tangent(const BlockInterface& c, const Vec3& live, const Vec3& gravity) {
    for (const Vec3& d : {live, gravity}) {
        const Vec3 t = d - c.normal.dot(d) * c.normal;
        if (t.norm() > 1e-6 * d.norm()) return t.normalized();
    }
    if (c.polygon.size() < 2) return c.normal.unitOrthogonal();   // an inset joint reduced to its centre
    const Vec3 e = c.polygon[1] - c.polygon[0];
    return (e - c.normal.dot(e) * c.normal).normalized();
}

/// the equilibrium of the free blocks (row[b]: block b's first row, −1 if fixed) under the
/// contact forces of the interfaces; the first restricted programme holds the pyramids' edges
/// along ±t1 (the normal force and the friction the live load calls for first)
Programme assemble(const std::vector<LimitBlock>& blocks, const std::vector<int>& row,
                   const std::vector<BlockInterface>& interfaces, const Vec3& gravity, const Vec3& live,
                   double friction, double f0, double l0) {
    Programme lp;
    int free_rows = 0;
    for (int r : row) free_rows = std::max(free_rows, r + 6);
    lp.rhs.assign(size_t(free_rows), 0.0);
    for (size_t b = 0; b < blocks.size(); ++b) {
        if (row[b] < 0) continue;
        const double m = blocks[b].mass;
        for (int k = 0; k < 3; ++k) {
            lp.entry(row[b] + k, m * live[k] / f0);
            lp.rhs[size_t(row[b] + k)] = -m * gravity[k] / f0;
        }
    }
    lp.close_column(true);
    // the pyramid's edges on the cone, at θ_k = k·π/4 from t1 (only the normal when μ = 0)
    const int edges = friction > 0.0 ? 8 : 1;
    for (const BlockInterface& c : interfaces) {
        const Vec3 t1 = first_tangent(c, live, gravity), t2 = c.normal.cross(t1);
        for (const Vec3& p : c.polygon)
            for (int k = 0; k < edges; ++k) {
                const Vec3 d = c.normal + friction * (kOctagon[k][0] * t1 + kOctagon[k][1] * t2);
                for (const auto& [b, sign] : {std::pair{c.first, 1.0}, std::pair{c.second, -1.0}}) {
                    if (row[b] < 0) continue;
                    const Vec3 moment = (p - blocks[b].centre).cross(d) / l0;
                    for (int i = 0; i < 3; ++i) lp.entry(row[b] + i, sign * d[i]);
                    for (int i = 0; i < 3; ++i) lp.entry(row[b] + 3 + i, sign * moment[i]);
                }
                lp.close_column(k % 4 == 0);
            }
    }
    return lp;
}

/// GLPK's problem over a growing subset of the programme's columns (column generation: a column
/// left out is added when its reduced cost at the current duals says it would raise λ)
class Restricted {
public:
    explicit Restricted(const Programme& p) : p_(p), lp_(glp_create_prob(), &glp_delete_prob), in_(p.columns(), 0) {
        glp_prob* g = lp_.get();
        glp_set_obj_dir(g, GLP_MAX);
        glp_add_rows(g, int(p.rhs.size()));
        for (size_t r = 0; r < p.rhs.size(); ++r) glp_set_row_bnds(g, int(r) + 1, GLP_FX, p.rhs[r], p.rhs[r]);
        std::vector<int> first;
        for (int j = 0; j < p.columns(); ++j)
            if (p.initial[size_t(j)]) first.push_back(j);
        add(first);
        glp_set_col_bnds(g, 1, GLP_DB, 0.0, kLimitLambdaCap);
        glp_set_obj_coef(g, 1, 1.0);
    }

    /// solve from the current basis (a cold start through GLPK's presolver if `cold`); false when
    /// no feasible point exists, throws on any other failure
    bool solve(bool cold) {
        glp_prob* g = lp_.get();
        glp_scale_prob(g, GLP_SF_AUTO);
        glp_smcp parm;
        glp_init_smcp(&parm);
        parm.msg_lev = GLP_MSG_OFF;
        parm.presolve = cold ? GLP_ON : GLP_OFF;
        // GLPK's default tolerances (1e-7) leave λ of a 400-brick wall 2e-6 short; with 1e-10 on
        // the reduced costs it agrees with the interior-point optimum to 1e-9
        parm.tol_bnd = 1e-9;
        parm.tol_dj = 1e-10;
        const int ret = glp_simplex(g, &parm);
        if (ret == GLP_ENOPFS) return false;
        if (ret != 0)
            throw Error("limit analysis: GLPK's simplex failed (glp_simplex returned " + std::to_string(ret) + ")");
        const int status = glp_get_status(g);
        if (status == GLP_NOFEAS) return false;
        if (status != GLP_OPT)
            throw Error("limit analysis: GLPK's simplex ended without an optimum (status " +
                        std::to_string(status) + ")");
        return true;
    }

    /// add the columns whose reduced cost at the current duals exceeds 1e-10 (λ per unit force);
    /// returns how many
    int price() {
        std::vector<double> y(p_.rhs.size());
        for (size_t r = 0; r < y.size(); ++r) y[r] = glp_get_row_dual(lp_.get(), int(r) + 1);
        std::vector<int> gain;
        for (int j = 0; j < p_.columns(); ++j) {
            if (in_[size_t(j)]) continue;
            double d = 0.0;   // the reduced cost: the objective has no entry in column j
            for (int k = p_.start[size_t(j)]; k < p_.start[size_t(j) + 1]; ++k)
                d -= y[size_t(p_.rows[size_t(k)])] * p_.values[size_t(k)];
            if (d > 1e-10) gain.push_back(j);
        }
        add(gain);
        return int(gain.size());
    }

    /// add every column left out; false if there was none
    bool add_rest() {
        std::vector<int> rest;
        for (int j = 0; j < p_.columns(); ++j)
            if (!in_[size_t(j)]) rest.push_back(j);
        add(rest);
        return !rest.empty();
    }

    glp_prob* get() { return lp_.get(); }

private:
    /// the columns, non-basic at zero (a feasible basis stays feasible)
    void add(const std::vector<int>& columns) {
        if (columns.empty()) return;
        glp_prob* g = lp_.get();
        int j = glp_add_cols(g, int(columns.size()));
        std::vector<int> ind{0};
        std::vector<double> val{0.0};
        for (int c : columns) {
            ind.resize(1);
            val.resize(1);
            for (int k = p_.start[size_t(c)]; k < p_.start[size_t(c) + 1]; ++k) {
                ind.push_back(p_.rows[size_t(k)] + 1);
                val.push_back(p_.values[size_t(k)]);
            }
            glp_set_mat_col(g, j, int(ind.size()) - 1, ind.data(), val.data());
            glp_set_col_bnds(g, j, GLP_LO, 0.0, 0.0);
            glp_set_col_stat(g, j, GLP_NL);
            in_[size_t(c)] = 1;
            ++j;
        }
    }

    const Programme& p_;
    std::unique_ptr<glp_prob, decltype(&glp_delete_prob)> lp_;
    std::vector<char> in_;   // per column of the programme: in GLPK's problem
};

/// the optimum over all the programme's columns (`optimum`; else any feasible point): columns
/// are priced in until none would raise λ; a restricted programme without a feasible point gets
/// every column. False if infeasible
bool solve_all(Restricted& lp, bool cold, bool optimum) {
    bool feasible = lp.solve(cold);
    for (;;) {
        if (feasible ? !optimum || lp.price() == 0 : !lp.add_rest()) return feasible;
        feasible = lp.solve(!feasible);
    }
}

void check_input(const std::vector<LimitBlock>& blocks, const Vec3& gravity, const Vec3& live, double friction) {
    if (!(friction >= 0.0) || !std::isfinite(friction))
        throw Error("limit analysis: friction must be finite and ≥ 0, got " + message_number(friction));
    if (!gravity.allFinite() || !live.allFinite()) throw Error("limit analysis: gravity and live load must be finite");
    const auto free_blocks = std::count_if(blocks.begin(), blocks.end(), [](const LimitBlock& b) { return !b.fixed; });
    if (free_blocks > kLimitMaxFreeBlocks)
        throw Error("limit analysis: " + std::to_string(free_blocks) + " free blocks, beyond the " +
                    std::to_string(kLimitMaxFreeBlocks) + " it solves within minutes");
    for (size_t b = 0; b < blocks.size(); ++b)
        if (!blocks[b].fixed && !(blocks[b].mass > 0.0 && std::isfinite(blocks[b].mass)))
            throw Error("limit analysis: block " + std::to_string(b) + " has mass " + message_number(blocks[b].mass) +
                        " kg; a free block needs a finite mass > 0");
}

/// the duals of the equilibrium rows: the blocks' virtual velocities (force rows) and angular
/// velocities (moment rows, in units of 1/l0), turned so that the live load does work, the
/// largest velocity 1
std::vector<LimitTwist> mechanism(glp_prob* g, const std::vector<LimitBlock>& blocks, const std::vector<int>& row,
                                  const Vec3& live, double l0) {
    std::vector<LimitTwist> out(blocks.size());
    double work = 0.0, largest = 0.0;
    for (size_t b = 0; b < blocks.size(); ++b) {
        if (row[b] < 0) continue;
        for (int k = 0; k < 3; ++k) {
            out[b].velocity[k] = glp_get_row_dual(g, row[b] + k + 1);
            out[b].angular[k] = glp_get_row_dual(g, row[b] + 3 + k + 1) / l0;
        }
        work += blocks[b].mass * live.dot(out[b].velocity);
        largest = std::max(largest, out[b].velocity.norm());
    }
    const double scale = largest > 0.0 ? (work < 0 ? -1.0 : 1.0) / largest : 0.0;
    for (LimitTwist& t : out) {
        t.velocity *= scale;
        t.angular *= scale;
    }
    return out;
}

}  // namespace

LimitAnalysisResult collapse_multiplier(const std::vector<LimitBlock>& blocks, const Vec3& gravity,
                                        const Vec3& live, double friction, double inset) {
    check_input(blocks, gravity, live, friction);
    LimitAnalysisResult result;
    // rows of the free blocks, their mean weight and size (the programme's units)
    std::vector<int> row(blocks.size(), -1);
    int free_blocks = 0;
    double weight = 0.0, size = 0.0;
    Aabb all;
    std::vector<Corners> corners;
    std::vector<bool> fixed;
    for (size_t b = 0; b < blocks.size(); ++b) {
        Aabb box;
        for (const Vec3& p : blocks[b].corners) box.add(p);
        all.add(box.lo);
        all.add(box.hi);
        corners.push_back(blocks[b].corners);
        fixed.push_back(blocks[b].fixed);
        if (blocks[b].fixed) continue;
        row[b] = 6 * free_blocks++;
        weight += blocks[b].mass * std::max(gravity.norm(), live.norm());
        size += (box.hi - box.lo).norm();
    }
    if (free_blocks == 0) {
        result.lambda = INFINITY;
        result.stands_at_zero = true;
        return result;
    }
    const double f0 = weight > 0.0 ? weight / free_blocks : 1.0, l0 = size / free_blocks;

    // contacts within 1e-5 of the assembly's size of each other: round-off of generated scenes
    auto interfaces = find_interfaces(corners, fixed, 1e-5 * (all.hi - all.lo).norm());
    for (BlockInterface& c : interfaces) c.polygon = inset_polygon(c.polygon, c.normal, inset);
    result.interfaces = int(interfaces.size());
    for (const BlockInterface& c : interfaces) result.contact_points += int(c.polygon.size());
    const Programme programme = assemble(blocks, row, interfaces, gravity, live, friction, f0, l0);

    // the largest λ, then whether λ = 0 is admissible too (the admissible λ form an interval)
    glp_term_out(GLP_OFF);
    Restricted lp(programme);
    if (!solve_all(lp, true, true)) return result;
    const double lambda = glp_get_col_prim(lp.get(), 1);
    if (lambda >= kLimitLambdaCap * (1 - 1e-9)) {
        result.lambda = INFINITY;
    } else {
        result.lambda = lambda;
        result.mechanism = mechanism(lp.get(), blocks, row, live, l0);
    }
    if (lambda <= 0.0) {
        result.stands_at_zero = true;
    } else {
        glp_set_col_bnds(lp.get(), 1, GLP_FX, 0.0, 0.0);
        result.stands_at_zero = solve_all(lp, false, false);
    }
    return result;
}

std::vector<LimitBlock> limit_blocks(const Scene& scene) {
    std::vector<LimitBlock> out;
    for (const BlockDef& d : scene.blocks) {
        LimitBlock b;
        b.corners = placed_corners(d.corners, d.position, d.orientation);
        const MassProperties mp = mass_properties(b.corners, scene.materials.at(d.material).density);
        b.mass = mp.mass;
        b.centre = mp.centre;
        b.fixed = d.fixed;
        out.push_back(b);
    }
    return out;
}

}  // namespace cairn::oracle

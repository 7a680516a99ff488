#pragma once
/// The mesh-inertia study: every mass scheme × mesh n on the rocking and impact scenes —
/// rotational inertia against the exact value and the closed forms, first impact and impact
/// velocity ratio against Housner, bounce period against its oracle, and the cost of each point.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backend/backend_info.hpp"

namespace cairn::study {

/// one scene of the study
struct StudyCase {
    std::string name;          ///< "rocking", "rocking_slender", "impact"
    std::string scene_path;    ///< the shipped scene file
    double kn = 0.0;           ///< contact stiffness used (kn = ks), N/m³
    bool in_plane = true;      ///< mesh [n, 1, n] (rocking about y) instead of [n, n, n]
    double after = 0.1;        ///< simulated time kept after the predicted event, s
};

/// one point of the study: a case, a scheme (or "rigid") and a mesh
struct StudyPoint {
    std::string case_name;
    std::string scheme;                   ///< lumped, consistent, barycentre, corrected, rigid
    int n = 0;                            ///< elements per side in the mesh (0 for rigid)
    std::array<int, 3> divisions{1, 1, 1};
    double kn = 0.0;                      ///< N/m³ (= ks)
    double grid_spacing = 0.0;            ///< contact hitting-point spacing, m (0: overlap contact, no grid)
    double mass = 0.0;                    ///< kg
    double ic_ratio = NAN;                ///< I_c / I_c,exact about the rocking axis (study's own assembly)
    double io_ratio = NAN;                ///< I_O / I_O,exact about the rocking edge (study's own assembly)
    double io_closed_form = NAN;          ///< docs/physics.md's closed form for the mesh (n × n in-plane)
    double io_engine_ratio = NAN;         ///< the engine's assembled I_O / I_O,exact (NaN: not asked)
    // rocking
    double t_impact = NAN;                ///< measured first impact, s
    double t_housner = NAN;               ///< Housner's exact t1 (exact inertia), s
    double t_predicted = NAN;             ///< t1 · √(io_ratio): a rigid block with the scheme's inertia, s
    double omega_ratio = NAN;             ///< measured ω after / ω before the first impact
    double omega_ratio_housner = NAN;     ///< 1 − (3/2) sin²α (exact inertia)
    double omega_ratio_scheme = NAN;      ///< 1 − 2 m b² / I_O with the scheme's I_O
    // impact
    double bounce = NAN;                  ///< measured bounce period, s
    double bounce_reference = NAN;        ///< DroppedBlock::bounce_period, s
    // cost
    double duration = 0.0;                ///< simulated time, s
    double dt = 0.0;                      ///< time step, s
    long long steps = 0;
    long long element_updates = 0;        ///< steps × elements of the studied block
    double wall_seconds = 0.0;            ///< median over the repeats, s
    std::string status;                   ///< "completed", or why not
    /// first-impact (rocking) or bounce-period (impact) relative error
    double event_error() const;
    /// impact velocity-ratio relative error against Housner's exact-inertia value
    double ratio_error() const { return omega_ratio / omega_ratio_housner - 1.0; }
};

/// Options of the study.
struct StudyOptions {
    std::vector<int> ns{1, 2, 4, 8};   ///< elements per side
    int repeats = 3;                   ///< runs per point (runs over 2 s: one); the wall time is their median
    int jobs = 2;                      ///< runs at a time
    bool quiet = false;                ///< no progress lines
};

/// the three cases of the study, from the scenarios directory
std::vector<StudyCase> default_cases(const std::string& scenarios_dir);

/// the scene of one point: the case's scene with kn, the model, mesh and mass scheme applied to the
/// reference block and the duration cut to just past the predicted event
Scene point_scene(const StudyCase& c, const std::string& scheme, int n);

/// the inertia columns of a point (no run)
StudyPoint inertia_point(const StudyCase& c, const std::string& scheme, int n, const BlockInertia& engine);

/// run the study on the run layer with dem of `backends`: every case × scheme × n, plus one rigid
/// point per case
std::vector<StudyPoint> run_study(const std::vector<StudyCase>& cases, const StudyOptions& options,
                                  const std::vector<BackendInfo>& backends, const BlockInertia& engine);

}  // namespace cairn::study

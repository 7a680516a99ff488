#pragma once
/// The contact study: the paper's rocking block (reading B, 0.7 × 1.0 m, released at 30°) at
/// several kn on the paper's node-to-face grid (its grid spacings) and on the overlap scheme (its
/// sub-divisions), rigid and meshed: the first impact against Housner and against the rigid block
/// on a Winkler base, the points that carry the contact, and the cost of each point. It shows how
/// the paper's answer depends on its grid and what the overlap scheme gives with fewer points.

#include <cmath>
#include <string>
#include <vector>

#include "backend/backend_info.hpp"

namespace cairn::study {

/// one point of the study: a kn, a scheme with its grid or sub-division, and a block model
struct ContactStudyPoint {
    double kn = 0.0;                  ///< normal and shear stiffness per area, N/m³
    std::string scheme;               ///< "paper" or "overlap"
    double grid_spacing = 0.0;        ///< paper scheme: hitting-point spacing, m (0: overlap)
    int subdivision = 0;              ///< overlap scheme: sub-contacts per face edge (0: paper)
    std::string model;                ///< "rigid" or "deformable" (the scene's [2,2,2] mesh)
    int points = 0;                   ///< contact points of the block standing on its base (hitting points or sub-contacts)
    double t_impact = NAN;            ///< measured first impact (θ back to 0), s
    double t_housner = NAN;           ///< Housner's exact first impact on a rigid base, s
    double t_winkler = NAN;           ///< the rigid block on a Winkler base of modulus kn, s
    double dt = 0.0;                  ///< time step, s
    long long steps = 0;
    double wall_seconds = NAN;        ///< median over the repeats, s
    std::string status;               ///< "completed", or why not
    /// first-impact error against Housner and against the Winkler base (fractions)
    double housner_error() const { return t_impact / t_housner - 1.0; }
    double winkler_error() const { return t_impact / t_winkler - 1.0; }
    /// the point's name in tables: "paper 0.1 m" or "overlap n = 4", with " (deformable)"
    std::string label() const;
};

/// Options of the study.
struct ContactStudyOptions {
    std::vector<double> kns{3e7, 3e8, 3e9};              ///< N/m³
    std::vector<double> spacings{0.2, 0.1, 0.05, 0.025};   ///< paper grid spacings, m
    std::vector<int> subdivisions{1, 2, 4, 8};           ///< overlap sub-divisions
    int repeats = 3;                                     ///< runs per point for the median wall time
    int jobs = 2;                                        ///< runs at a time
    bool quiet = false;
};

/// run the study on dem of `backends` with the scene `scene_path` (paper/rocking_winkler): per kn,
/// every paper grid and overlap sub-division on the rigid block, and the paper's 0.1 m grid and the
/// overlap's default sub-division on the meshed block. Points whose run did not complete carry the
/// reason in `status`.
std::vector<ContactStudyPoint> run_contact_study(const std::string& scene_path, const ContactStudyOptions& options,
                                            const std::vector<BackendInfo>& backends);

/// write the points as CSV (header first); read them back (throws cairn::Error naming file and line)
void write_contact_csv(const std::string& path, const std::vector<ContactStudyPoint>& points);
std::vector<ContactStudyPoint> read_contact_csv(const std::string& path);

}  // namespace cairn::study

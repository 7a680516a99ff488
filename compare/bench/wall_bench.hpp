#pragma once
/// The side-by-side throughput of the backends on a running-bond brick wall at the same time step
/// (the performance of the in-house engine): steps per second and their ratio to Bullet's at
/// the same dt (a cost per step; `cairn bench scale` compares cost at equal accuracy).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backend/backend_info.hpp"

namespace cairn::bench {

/// One way of setting up the wall.
struct WallSetup {
    std::string name;                   ///< e.g. "paper kn, touching"
    double kn = 3e7;                    ///< N/m³ (= ks)
    double dt = 1e-3;                   ///< s, the same for every backend
    bool placed = false;                ///< true: each course placed at its static penetration
    std::string contact_mode = "rigid"; ///< of the reference engines
};

/// the setups compared: the paper's soft joints released touching at dt 1e-3 s (as first measured),
/// and stiff joints (kn = 3e9) placed at their static penetrations at the engines' dt 1e-4 s
std::vector<WallSetup> wall_setups();

/// a wall of `courses` × `per_course` 0.4 × 0.2 × 0.2 m bricks in running bond on a fixed 5 × 1 ×
/// 0.5 m base (add_wall, odd courses shifted whole), kn = ks = setup.kn, μ = 0.6, dt = setup.dt
Scene wall_scene(int courses, int per_course, const WallSetup& setup);

/// One backend on one setup.
struct WallResult {
    std::string setup, backend, contact;   ///< contact: what the backend's contact is here
    double kn = 0.0, dt = 0.0;             ///< N/m³, s
    int blocks = 0;                        ///< free blocks
    int steps = 0;                         ///< steps per repeat
    double steps_per_second = 0.0;         ///< median over the repeats
    double ratio_to_bullet = 0.0;          ///< steps/s over Bullet's at the same dt (0: no Bullet): a cost
                                           ///< per step, not per simulated second at equal accuracy
    double top_settlement = 0.0;           ///< largest displacement of a top-course brick at the end, m
    std::string status;                    ///< "completed", "unstable: ...", "refused: ..."
};

/// run every backend on every setup one after the other (no other bench point runs meanwhile)
std::vector<WallResult> run_wall(const std::vector<std::string>& backends, const std::vector<WallSetup>& setups,
                                 int courses, int per_course, int steps, int repeats,
                                 const std::vector<BackendInfo>& infos, bool quiet);

/// call `row` with the fields of every line after the header of a csv text that has `fields` of them
void for_each_csv_row(const std::string& text, size_t fields,
                      const std::function<void(const std::vector<std::string>&)>& row);
/// a csv number field (empty: NaN)
double csv_number(const std::string& field);

/// wall.csv text, and its parse
std::string wall_csv(const std::vector<WallResult>& rows);
std::vector<WallResult> parse_wall_csv(const std::string& text);

}  // namespace cairn::bench

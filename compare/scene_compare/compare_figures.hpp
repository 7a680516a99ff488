#pragma once
/// The data files and figures of a comparison report: per variant and free block the history CSV
/// and the difference to the baseline, per variant the energy ledger over time, and the gnuplot
/// figures drawn from them (one colour per variant, scene_compare/palette.hpp).

#include <string>
#include <vector>

#include "scene_compare/block_history.hpp"
#include "validation/run_cases.hpp"

namespace cairn::scene_compare {

/// One run with its block histories.
struct VariantHistories {
    const validation::CaseRun* run = nullptr;
    std::vector<BlockHistory> blocks;   ///< one per free block
};

/// the CSV of one block history: "t [s],x [m],y [m],z [m],rotation angle [rad],speed [m/s]"
std::string history_csv(const BlockHistory& h);

/// the CSV of `run` minus `base` at the times of `run` that `base` covers: "t [s],distance to
/// baseline [m],rotation angle difference [rad],speed difference [m/s]"
std::string difference_csv(const BlockHistory& run, const BlockHistory& base);

/// the CSV of a run's energies and contact count over time (J; balance error = total − total at t = 0)
std::string energy_csv(const std::vector<Sample>& samples);

/// the data file names, relative to the output directory
std::string history_file(const std::string& variant, int free_block);
std::string difference_file(const std::string& variant, int free_block);
std::string energy_file(const std::string& variant);

/// write the data files under DIR/data for the free blocks `shown` (indices; the runs'
/// trajectory.csv hold every block); `base` indexes the baseline in `variants` (-1 = none)
void write_data(const std::vector<VariantHistories>& variants, int base, const std::vector<size_t>& shown,
                const std::string& dir);

/// draw DIR/figures/block<k>.png (histories), block<k>_diff.png (differences, when there is a
/// baseline) for the free blocks `shown` (indices) and energy.png; returns the images written
/// (relative to DIR) by name: "block<k>", "block<k>_diff", "energy"; failures are added to `note`
std::vector<std::string> draw_figures(const std::vector<VariantHistories>& variants, int base,
                                      const std::vector<std::string>& block_names, const std::vector<size_t>& shown,
                                      const std::string& dir, std::string& note);

}  // namespace cairn::scene_compare

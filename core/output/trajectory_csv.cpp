#include "output/trajectory_csv.hpp"

#include <cstdio>
#include <stdexcept>

#include "output/number_format.hpp"

namespace cairn {

std::vector<std::string> trajectory_columns(const Scene& scene) {
    // every name ends in its unit in brackets ("[-]": dimensionless)
    std::vector<std::string> cols{"t [s]"};
    for (const auto& p : scene.probes)
        for (const char* c : {".x [m]", ".y [m]", ".z [m]"}) cols.push_back(p.name + c);
    for (const auto& b : scene.blocks) {
        if (b.fixed) continue;
        for (const char* c : {".x [m]", ".y [m]", ".z [m]", ".qw [-]", ".qx [-]", ".qy [-]", ".qz [-]"})
            cols.push_back(b.name + c);
    }
    for (const char* c : {"E_kinetic [J]", "E_potential [J]", "E_contact [J]", "E_strain [J]", "E_dissipated [J]",
                          "W_external [J]", "E_balance_error [J]", "contacts [-]"})
        cols.push_back(c);
    return cols;
}

TrajectoryCsvWriter::TrajectoryCsvWriter(std::ostream& out, const Scene& scene)
    : out_(out), probes_(scene.probes.size()) {
    for (const auto& b : scene.blocks) free_blocks_ += b.fixed ? 0 : 1;
    const auto cols = trajectory_columns(scene);
    for (size_t i = 0; i < cols.size(); ++i) line_ += (i ? "," : "") + cols[i];
    out_ << line_ << '\n';
}

void TrajectoryCsvWriter::row(const Sample& s) {
    // a backend bug, not bad input: rows must match the header
    if (s.probes.size() != probes_ || s.blocks.size() != free_blocks_)
        throw std::logic_error("trajectory sample at t = " + std::to_string(s.t) +
                               " does not match the scene's probes and free blocks");
    if (first_) total0_ = s.energy.total();
    first_ = false;
    line_.clear();
    append_exact(line_, s.t);
    for (const auto& p : s.probes)
        for (int k = 0; k < 3; ++k) append_exact(line_, p[k], ',');
    for (const auto& b : s.blocks) {
        for (int k = 0; k < 3; ++k) append_exact(line_, b.position[k], ',');
        for (double q : {b.orientation.w(), b.orientation.x(), b.orientation.y(), b.orientation.z()})
            append_exact(line_, q, ',');
    }
    const Energies& e = s.energy;
    for (double x : {e.kinetic, e.potential, e.contact, e.strain, e.dissipated, e.external,
                     e.total() - total0_})
        append_exact(line_, x, ',');
    line_ += "," + std::to_string(s.contacts);
    out_ << line_ << '\n';
}

void write_trajectory_csv(std::ostream& out, const Scene& scene, const std::vector<Sample>& samples) {
    TrajectoryCsvWriter w(out, scene);
    for (const auto& s : samples) w.row(s);
}

TrajectoryCsvFile::TrajectoryCsvFile(std::string path) : file_(std::move(path)) {}

void TrajectoryCsvFile::begin(const Scene& scene, const RunResult&) {
    file_.open();
    writer_ = std::make_unique<TrajectoryCsvWriter>(file_.out(), scene);
    file_.check();
}

void TrajectoryCsvFile::sample(const Sample& s) {
    writer_->row(s);
    file_.check();
}

void TrajectoryCsvFile::end(const RunResult&) { file_.close(); }

}  // namespace cairn

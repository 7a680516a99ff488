#include "output/trajectory_csv.hpp"

#include <cstdio>
#include <stdexcept>

namespace cairn {

std::vector<std::string> trajectory_columns(const Scene& scene) {
    std::vector<std::string> cols{"t"};
    for (const auto& p : scene.probes)
        for (const char* c : {".x", ".y", ".z"}) cols.push_back(p.name + c);
    for (const auto& b : scene.blocks) {
        if (b.fixed) continue;
        for (const char* c : {".x", ".y", ".z", ".qw", ".qx", ".qy", ".qz"}) cols.push_back(b.name + c);
    }
    for (const char* c : {"E_kinetic", "E_potential", "E_contact", "E_strain", "E_dissipated",
                          "W_external", "E_balance_error", "contacts"})
        cols.push_back(c);
    return cols;
}

namespace {

/// append x with 17 significant digits (exact round trip of a double)
void put(std::string& line, double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, ",%.17g", x);
    line += buf;
}

}  // namespace

void write_trajectory_csv(std::ostream& out, const Scene& scene, const std::vector<Sample>& samples) {
    const auto cols = trajectory_columns(scene);
    std::string line;
    for (size_t i = 0; i < cols.size(); ++i) line += (i ? "," : "") + cols[i];
    out << line << '\n';
    const double total0 = samples.empty() ? 0.0 : samples.front().energy.total();
    size_t free_blocks = 0;
    for (const auto& b : scene.blocks) free_blocks += b.fixed ? 0 : 1;
    for (const auto& s : samples) {
        // a backend bug, not bad input: rows must match the header
        if (s.probes.size() != scene.probes.size() || s.blocks.size() != free_blocks)
            throw std::logic_error("trajectory sample at t = " + std::to_string(s.t) +
                                   " does not match the scene's probes and free blocks");
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.17g", s.t);
        line = buf;
        for (const auto& p : s.probes)
            for (int k = 0; k < 3; ++k) put(line, p[k]);
        for (const auto& b : s.blocks) {
            for (int k = 0; k < 3; ++k) put(line, b.position[k]);
            for (double q : {b.orientation.w(), b.orientation.x(), b.orientation.y(), b.orientation.z()})
                put(line, q);
        }
        const Energies& e = s.energy;
        for (double x : {e.kinetic, e.potential, e.contact, e.strain, e.dissipated, e.external,
                         e.total() - total0})
            put(line, x);
        line += "," + std::to_string(s.contacts);
        out << line << '\n';
    }
}

}  // namespace cairn

#pragma once
/// Writing trajectories: t, probes, free blocks' pose, energies, contact count; one row per sample,
/// written as the run goes.

#include <fstream>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "output/buffered_file.hpp"
#include "run/sample_sink.hpp"

namespace cairn {

/// column names, each with its unit in brackets: t [s], P.x [m] … per probe, B.x [m] … B.qz [-] per
/// free block, energies and the balance error [J], contacts [-]
std::vector<std::string> trajectory_columns(const Scene& scene);

/// Writes a trajectory row by row: the header on construction, then one row per sample with 17
/// significant digits; the balance error column is relative to the first row's total energy.
class TrajectoryCsvWriter {
public:
    TrajectoryCsvWriter(std::ostream& out, const Scene& scene);
    /// one row; std::logic_error if the sample does not match the header (a backend bug)
    void row(const Sample& s);

private:
    std::ostream& out_;
    size_t probes_ = 0;
    size_t free_blocks_ = 0;
    bool first_ = true;
    double total0_ = 0.0;   ///< J
    std::string line_;
};

/// write the header and one row per sample (TrajectoryCsvWriter over a vector)
void write_trajectory_csv(std::ostream& out, const Scene& scene, const std::vector<Sample>& samples);

/// A sink that writes the trajectory to a file as the run goes, through a large buffer; the file
/// is created at begin() and flushed, closed and fsynced at end(). Throws std::runtime_error (not
/// cairn::Error: a write failure is not bad input) naming the file when it cannot be written.
class TrajectoryCsvFile : public SampleSink {
public:
    explicit TrajectoryCsvFile(std::string path);
    void begin(const Scene& scene, const RunResult& run) override;
    void sample(const Sample& s) override;
    void end(const RunResult& run) override;
    const std::string& path() const { return file_.path(); }

private:
    BufferedFile file_;
    std::unique_ptr<TrajectoryCsvWriter> writer_;
};

}  // namespace cairn

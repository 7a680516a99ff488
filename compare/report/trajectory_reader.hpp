#pragma once
/// A run directory's trajectory read back row by row: trajectory.csv, else trajectory.partial.csv,
/// columns found by name (without their unit), every line and number checked.

#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

namespace cairn::report {

/// Reader of one run's trajectory CSV.
class TrajectoryReader {
public:
    /// open the trajectory of `run_dir` and read its header; throws cairn::Error naming the file
    explicit TrajectoryReader(const std::string& run_dir);
    /// the index of column `name` ("t", "A.qw"); throws cairn::Error naming the file and `hint`
    std::size_t column(const std::string& name, const std::string& hint = "") const;
    /// read the next row; false at the end of the file
    bool next();
    /// the number in column `c` of the current row; throws cairn::Error naming the file and line
    double number(std::size_t c) const;
    /// the file read
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::ifstream in_;
    std::vector<std::string> header_, fields_;
    int row_ = 1;
};

}  // namespace cairn::report

#include "report/trajectory_reader.hpp"

#include <cstdlib>
#include <filesystem>

#include "error.hpp"
#include "report/text.hpp"

namespace fs = std::filesystem;

namespace cairn::report {

namespace {

/// longest trajectory line accepted, characters (a row of 17-digit numbers for thousands of blocks)
constexpr std::size_t kMaxLine = 16u << 20;

/// read one line of at most kMaxLine characters; false at the end of the file
bool read_bounded_line(std::istream& in, std::string& line, const std::string& path) {
    line.clear();
    char c;
    while (in.get(c)) {
        if (c == '\n') return true;
        if (line.size() >= kMaxLine) throw Error(path + ": a line longer than " + std::to_string(kMaxLine) + " characters");
        line += c;
    }
    return !line.empty();
}

}  // namespace

TrajectoryReader::TrajectoryReader(const std::string& run_dir) {
    fs::path csv = fs::path(run_dir) / "trajectory.csv";
    if (!fs::exists(csv)) csv = fs::path(run_dir) / "trajectory.partial.csv";
    path_ = csv.string();
    in_.open(csv);
    if (!in_) throw Error(path_ + ": cannot read");
    std::string line;
    if (!read_bounded_line(in_, line, path_)) throw Error(path_ + ": empty");
    header_ = split_csv_line(line);
}

std::size_t TrajectoryReader::column(const std::string& name, const std::string& hint) const {
    // a column name without its unit ("t [s]" -> "t"; a name without one is kept)
    for (std::size_t i = 0; i < header_.size(); ++i) {
        const std::string& h = header_[i];
        const auto open = h.rfind(" [");
        if ((open != std::string::npos && h.back() == ']' ? h.substr(0, open) : h) == name) return i;
    }
    throw Error(path_ + ": no column " + name + hint);
}

bool TrajectoryReader::next() {
    std::string line;
    if (!read_bounded_line(in_, line, path_)) return false;
    fields_ = split_csv_line(line);
    ++row_;
    return true;
}

double TrajectoryReader::number(std::size_t c) const {
    if (c >= fields_.size()) throw Error(path_ + ": line " + std::to_string(row_) + " has too few fields");
    char* end = nullptr;
    const double v = std::strtod(fields_[c].c_str(), &end);
    if (fields_[c].empty() || *end != '\0')
        throw Error(path_ + ": line " + std::to_string(row_) + ": '" + fields_[c] + "' is not a number");
    return v;
}

}  // namespace cairn::report

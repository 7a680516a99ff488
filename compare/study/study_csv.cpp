// DIR/inertia.csv: one row per study point
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "error.hpp"
#include "output/atomic_write.hpp"
#include "study/study_report.hpp"

#include "report/text.hpp"

namespace cairn::study {

namespace {

const char* kHeader =
    "case,scheme,n,nx,ny,nz,kn,grid_spacing,mass,ic_ratio,io_ratio,io_closed_form,io_engine_ratio,"
    "t_impact,t_housner,t_predicted,impact_error,omega_ratio,omega_ratio_housner,omega_ratio_scheme,"
    "ratio_error,bounce,bounce_reference,bounce_error,duration,dt,steps,element_updates,wall_seconds,status";

double to_num(const std::string& s) { return s.empty() ? NAN : std::stod(s); }

}  // namespace

void write_inertia_csv(const std::string& path, const std::vector<StudyPoint>& points) {
    write_file_atomic(path, [&](std::ostream& o) {
        o << kHeader << "\n";
        for (const auto& p : points) {
            const bool rocking = std::isfinite(p.t_housner);
            std::string status;
            for (char c : p.status) status += c == '"' ? std::string("\"\"") : std::string(1, c);
            o << p.case_name << "," << p.scheme << "," << p.n << "," << p.divisions[0] << "," << p.divisions[1]
              << "," << p.divisions[2] << "," << report::number_text(p.kn, 10) << "," << report::number_text(p.grid_spacing, 10) << "," << report::number_text(p.mass, 10)
              << "," << report::number_text(p.ic_ratio, 10) << "," << report::number_text(p.io_ratio, 10) << "," << report::number_text(p.io_closed_form, 10) << ","
              << report::number_text(p.io_engine_ratio, 10) << "," << report::number_text(p.t_impact, 10) << "," << report::number_text(p.t_housner, 10) << ","
              << report::number_text(p.t_predicted, 10) << "," << (rocking ? report::number_text(p.event_error(), 10) : "") << "," << report::number_text(p.omega_ratio, 10)
              << "," << report::number_text(p.omega_ratio_housner, 10) << "," << report::number_text(p.omega_ratio_scheme, 10) << ","
              << (rocking ? report::number_text(p.ratio_error(), 10) : "") << "," << report::number_text(p.bounce, 10) << "," << report::number_text(p.bounce_reference, 10)
              << "," << (rocking ? "" : report::number_text(p.event_error(), 10)) << "," << report::number_text(p.duration, 10) << "," << report::number_text(p.dt, 10) << ","
              << p.steps << "," << p.element_updates << "," << report::number_text(p.wall_seconds, 10) << ",\"" << status << "\"\n";
        }
    });
}

std::vector<StudyPoint> read_inertia_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot open the inertia study's CSV (run `cairn study inertia` first)");
    std::string line;
    std::getline(in, line);
    if (line != kHeader) throw Error(path + ":1: not an inertia study CSV (unexpected header)");
    std::vector<StudyPoint> out;
    for (int ln = 2; std::getline(in, line); ++ln) {
        if (line.empty()) continue;
        const auto f = report::split_csv_line(line);
        if (f.size() != 30) throw Error(path + ":" + std::to_string(ln) + ": expected 30 fields, found " +
                                        std::to_string(f.size()));
        try {
            StudyPoint p;
            p.case_name = f[0];
            p.scheme = f[1];
            p.n = std::stoi(f[2]);
            p.divisions = {std::stoi(f[3]), std::stoi(f[4]), std::stoi(f[5])};
            p.kn = to_num(f[6]);
            p.grid_spacing = to_num(f[7]);
            p.mass = to_num(f[8]);
            p.ic_ratio = to_num(f[9]);
            p.io_ratio = to_num(f[10]);
            p.io_closed_form = to_num(f[11]);
            p.io_engine_ratio = to_num(f[12]);
            p.t_impact = to_num(f[13]);
            p.t_housner = to_num(f[14]);
            p.t_predicted = to_num(f[15]);
            p.omega_ratio = to_num(f[17]);
            p.omega_ratio_housner = to_num(f[18]);
            p.omega_ratio_scheme = to_num(f[19]);
            p.bounce = to_num(f[21]);
            p.bounce_reference = to_num(f[22]);
            p.duration = to_num(f[24]);
            p.dt = to_num(f[25]);
            p.steps = std::stoll(f[26]);
            p.element_updates = std::stoll(f[27]);
            p.wall_seconds = to_num(f[28]);
            p.status = f[29];
            out.push_back(p);
        } catch (const std::logic_error&) {
            throw Error(path + ":" + std::to_string(ln) + ": a field is not a number");
        }
    }
    return out;
}

}  // namespace cairn::study

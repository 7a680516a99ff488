#pragma once
/// Writing the inertia study: DIR/inertia.csv, figures (gnuplot), DIR/inertia.md and .html, and the
/// section the validation report can include.

#include <string>
#include <vector>

#include "report/document.hpp"
#include "study/inertia_study.hpp"

namespace cairn::study {

/// write the points as CSV (one row per point, header first)
void write_inertia_csv(const std::string& path, const std::vector<StudyPoint>& points);
/// read a CSV written by write_inertia_csv; throws cairn::Error naming the file and line
std::vector<StudyPoint> read_inertia_csv(const std::string& path);

/// write DIR/figures/inertia_*.dat, .gp and .png; returns the PNG paths relative to DIR (empty and a
/// note when gnuplot is missing or fails)
std::vector<std::string> write_inertia_figures(const std::string& dir, const std::vector<StudyPoint>& points,
                                               std::string& note);

/// the plain recommendation drawn from the points (cheapest point within 1 % per rocking case, …)
std::string recommendation(const std::vector<StudyPoint>& points);

/// add the study to a report: what was run, the tables, the figures (paths prefixed by
/// `figure_prefix`), the recommendation and the corrected scheme's limits
void add_inertia_section(report::Document& doc, const std::vector<StudyPoint>& points,
                         const std::vector<std::string>& figures, const std::string& figure_prefix = "",
                         double total_wall_seconds = NAN);

/// add the section of a study directory written by `cairn study inertia` (DIR/inertia.csv and
/// DIR/figures/inertia_*.png), figure paths prefixed by `figure_prefix` (the study dir relative to
/// the including document); false, and nothing added, when DIR has no inertia.csv
bool add_inertia_report_section(report::Document& doc, const std::string& study_dir, const std::string& figure_prefix);

/// write DIR/inertia.csv, the figures, DIR/inertia.md and DIR/inertia.html
void write_inertia_study(const std::string& dir, const std::vector<StudyPoint>& points, double total_wall_seconds);

}  // namespace cairn::study

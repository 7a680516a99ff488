#pragma once
/// Writing the contact study: DIR/contact.csv, a figure (gnuplot), DIR/contact.md and .html, and
/// the section the validation report can include.

#include <string>
#include <vector>

#include "report/document.hpp"
#include "study/contact_study.hpp"

namespace cairn::study {

/// add the study to a report: what was run, a table per kn, the figure (path prefixed by
/// `figure_prefix`) and what it shows
void add_contact_section(report::Document& doc, const std::vector<ContactStudyPoint>& points,
                         const std::vector<std::string>& figures, const std::string& figure_prefix = "",
                         double total_wall_seconds = NAN);

/// add the section of a directory written by `cairn study contact`; false, and nothing added,
/// when DIR has no contact.csv
bool add_contact_report_section(report::Document& doc, const std::string& dir, const std::string& figure_prefix);

/// write DIR/contact.csv, DIR/figures/contact_*.png, DIR/contact.md and DIR/contact.html
void write_contact_study(const std::string& dir, const std::vector<ContactStudyPoint>& points, double total_wall_seconds);

}  // namespace cairn::study

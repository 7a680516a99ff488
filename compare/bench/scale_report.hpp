#pragma once
/// The scale section of the bench report: cost per simulated second and peak memory against the
/// number of bricks, per backend, with the fitted exponents and a log-log figure.

#include <string>

#include "report/document.hpp"

namespace cairn::bench {

/// add the section from DIR's scale.csv and scale_accuracy.csv (nothing when they are missing);
/// the figure goes to DIR/figures/scale_cost.png, a gnuplot problem into `note`
void add_scale_section(report::Document& d, const std::string& dir, std::string& note);

}  // namespace cairn::bench

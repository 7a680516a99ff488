#include "report/palette.hpp"

#include <map>

namespace cairn::report {

std::string variant_colour(const std::string& variant) {
    // black is kept for the analytic curve
    static const std::map<std::string, std::string> colours = {
        {"dem-rigid", "#1f77b4"},      {"dem-deformable", "#17becf"}, {"bullet-rigid", "#d62728"},
        {"bullet-matched", "#ff7f0e"}, {"ode-rigid", "#2ca02c"},      {"ode-matched", "#bcbd22"},
        {"mujoco-rigid", "#9467bd"},   {"mujoco-matched", "#e377c2"},
    };
    const auto it = colours.find(variant);
    return it == colours.end() ? "#7f7f7f" : it->second;
}

}  // namespace cairn::report

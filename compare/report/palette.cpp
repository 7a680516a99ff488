#include "report/palette.hpp"

#include <map>

namespace cairn::report {

namespace {

struct Colour {
    const char* rgb;
    const char* name;
};

Colour colour_of(const std::string& variant) {
    // black is kept for the analytic curve
    static const std::map<std::string, Colour> colours = {
        {"dem-rigid", {"#1f77b4", "blue"}},        {"dem-deformable", {"#17becf", "cyan"}},
        {"bullet-rigid", {"#d62728", "red"}},      {"bullet-matched", {"#ff7f0e", "orange"}},
        {"ode-rigid", {"#2ca02c", "green"}},       {"ode-matched", {"#bcbd22", "olive"}},
        {"mujoco-rigid", {"#9467bd", "purple"}},   {"mujoco-matched", {"#e377c2", "pink"}},
    };
    const auto it = colours.find(variant);
    return it == colours.end() ? Colour{"#7f7f7f", "grey"} : it->second;
}

}  // namespace

std::string variant_colour(const std::string& variant) { return colour_of(variant).rgb; }
std::string variant_colour_name(const std::string& variant) { return colour_of(variant).name; }

}  // namespace cairn::report

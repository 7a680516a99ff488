#pragma once
/// One colour per variant, the same in every figure of every report (compare and validate).

#include <string>

namespace cairn::report {

/// "#rrggbb" of a variant ("dem-rigid", "bullet-matched", ...); the known variants have fixed
/// colours (the engine's hue, darker for rigid contact), any other name a fixed grey
std::string variant_colour(const std::string& variant);

/// the colour of variant_colour in words ("blue", "orange", ...), for tables and captions
std::string variant_colour_name(const std::string& variant);

}  // namespace cairn::report

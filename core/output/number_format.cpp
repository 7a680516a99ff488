#include "output/number_format.hpp"

#include <cmath>
#include <cstdio>

namespace cairn {

std::string number_format(const char* format, double v, const char* not_finite) {
    if (not_finite && !std::isfinite(v)) return not_finite;
    char b[64];
    std::snprintf(b, sizeof b, format, v);
    return b;
}

std::string number_text(double v, int digits) {
    if (!std::isfinite(v)) return "";
    return message_number(v, digits);
}

std::string message_number(double v, int digits) {
    if (v == 0.0) v = 0.0;   // −0 prints as 0
    char b[48];
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    return b;
}

std::string percent_text(double relative) { return number_format("%+.3f %%", 100.0 * relative); }

std::string fixed_text(double v, int decimals) {
    char b[48];
    std::snprintf(b, sizeof b, "%.*f", decimals, v);
    return b;
}

void append_exact(std::string& out, double v, char sep) {
    char b[40];
    if (sep) out += sep;
    std::snprintf(b, sizeof b, "%.17g", v);
    out += b;
}

}  // namespace cairn

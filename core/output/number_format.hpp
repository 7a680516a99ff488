#pragma once
/// Numbers as text: the one module through which cairn prints a number, in CSV columns, reports,
/// messages and scene files alike. Every function is printf underneath (C locale), so the same
/// double gives the same text on every machine.

#include <string>

namespace cairn {

/// v through a printf format holding one double conversion and any text around it ("%.3g s",
/// "%+.2f %%"); NaN and infinity as printf writes them, or `not_finite` when one is given
std::string number_format(const char* format, double v, const char* not_finite = nullptr);

/// v with `digits` significant digits (%.*g); "" for NaN or infinity (an empty CSV field)
std::string number_text(double v, int digits = 6);

/// v with `digits` significant digits (%.*g) for a message: 1e+30, 0.0111, nan, inf
std::string message_number(double v, int digits = 4);

/// a relative value as a signed percentage with 3 decimals ("+1.234 %")
std::string percent_text(double relative);

/// v with a fixed number of decimals (%.*f)
std::string fixed_text(double v, int decimals);

/// appends v with 17 significant digits to `out` (reads back as the same double), after `sep`
/// when one is given (a CSV row's comma)
void append_exact(std::string& out, double v, char sep = '\0');

}  // namespace cairn

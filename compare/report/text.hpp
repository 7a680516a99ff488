#pragma once
/// Numbers as text and CSV fields, shared by every writer and reader of the compare layer.

#include <string>
#include <vector>

namespace cairn::report {

/// v with `digits` significant digits (printf %g); "" for NaN or infinity
std::string number_text(double v, int digits = 6);
/// a relative value as a signed percentage with 3 decimals ("+1.234 %")
std::string percent_text(double relative);
/// v with a fixed number of decimals
std::string fixed_text(double v, int decimals);
/// a CSV field, quoted when it holds a comma, a quote or a newline (newlines become spaces)
std::string csv_field(const std::string& s);
/// text safe inside HTML element content and quoted attribute values (& < > " ' escaped)
std::string html_text(const std::string& s);
/// the fields of one CSV line; a quoted field may hold commas and "" for a quote
std::vector<std::string> split_csv_line(const std::string& line);

}  // namespace cairn::report

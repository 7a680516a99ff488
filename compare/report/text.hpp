#pragma once
/// CSV fields and HTML text, shared by every writer and reader of the compare layer; numbers as
/// text are core's (output/number_format.hpp), named here as well.

#include <string>
#include <vector>

#include "output/number_format.hpp"

namespace cairn::report {

using cairn::fixed_text;
using cairn::number_text;
using cairn::percent_text;
/// a CSV field, quoted when it holds a comma, a quote or a newline (newlines become spaces)
std::string csv_field(const std::string& s);
/// text safe inside HTML element content and quoted attribute values (& < > " ' escaped)
std::string html_text(const std::string& s);
/// the fields of one CSV line; a quoted field may hold commas and "" for a quote
std::vector<std::string> split_csv_line(const std::string& line);

}  // namespace cairn::report

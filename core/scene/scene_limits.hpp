#pragma once
/// Limits on scene text checked before the TOML parser sees it, and on the names that become CSV
/// column names (docs/scenes.md, "Limits").

#include <cstddef>
#include <string>

namespace cairn {

/// largest scene file (or --set value) accepted, bytes
constexpr std::size_t kMaxSceneBytes = 16u << 20;
/// most parts of one dotted key or table header (a.b.c has 3)
constexpr int kMaxKeyParts = 32;
/// deepest nesting of arrays and inline tables (a table header's brackets count too)
constexpr int kMaxNesting = 32;

/// throw cairn::Error naming `source`, the line and the limit when `text` is larger than
/// kMaxSceneBytes, has a dotted key or header of more than kMaxKeyParts parts, or nests arrays or
/// inline tables deeper than kMaxNesting
void check_toml_limits(const std::string& text, const std::string& source);

/// empty when `text` is valid UTF-8 without control characters (tab allowed when `allow_tab`),
/// otherwise what is wrong ("a control character (0x0a)", "invalid UTF-8 at byte 3")
std::string text_problem(const std::string& text, bool allow_tab);

/// `text` with control characters and invalid bytes shown as \xNN (for messages)
std::string printable(const std::string& text);

/// empty when `name` can be a CSV column name (not empty, valid UTF-8, no control character, no
/// ',' or '"'), otherwise what is wrong
std::string column_name_problem(const std::string& name);

}  // namespace cairn

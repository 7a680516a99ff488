#pragma once
/// "Did you mean ...": the closest of a list of names to a mistyped one.

#include <string>
#include <vector>

namespace cairn {

/// edit distance (insertions, deletions, substitutions, each 1) between a and b
int edit_distance(const std::string& a, const std::string& b);

/// the candidate closest to `word` when it is close enough to be a typo (distance at most
/// max(2, a third of the word's length)), else ""
std::string closest_name(const std::string& word, const std::vector<std::string>& candidates);

/// " (did you mean 'x'?)" with the closest candidate, or "" when none is close
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace cairn

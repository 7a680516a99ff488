#pragma once
/// The 3-D replay page of a case in a report: every variant that produced samples, side by side,
/// written beside the report (docs/visualisation.md).

#include <string>

#include "validation/run_cases.hpp"

namespace cairn::report {

/// write DIR/`file` (relative, e.g. "replay.html") with the replay of every run of `c` that has
/// samples, and return `file`; "" with `note` saying why when there is no page (this cairn was
/// built without the replay, or no run produced samples). The frames are capped per run
/// (kMaxReplayFrames, kMaxReplayNumbers), so the page stays bounded for any run length.
std::string write_case_replay(const validation::CaseResult& c, const std::string& dir, const std::string& file,
                              std::string& note);

}  // namespace cairn::report

#pragma once
/// The --backends option of the commands that run several backends (compare, study, bench).

#include <string>
#include <vector>

#include "backend/backend_info.hpp"

namespace cairn {

/// the backends named by --backends, in the order given ("all" or none = every available one, in
/// the registry's order); throws cairn::Error "--backends NAME: no such backend (did you mean
/// ...?); available: ..." for a name the registry does not hold
std::vector<std::string> chosen_backends(const std::vector<std::string>& given);

/// the registry's facts of each named backend, in that order (names already checked)
std::vector<BackendInfo> backend_infos(const std::vector<std::string>& names);

}  // namespace cairn

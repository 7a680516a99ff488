#pragma once
/// The analytic reference kinds a scene may name in [reference], and the numeric parameters each
/// one takes (SI units; angles in rad). The one place this list lives.

#include <string>
#include <vector>

namespace cairn {

/// one reference kind and the names of its optional numeric parameters
struct ReferenceKind {
    std::string name;                     ///< e.g. "housner"
    std::vector<std::string> parameters;  ///< e.g. {"theta0", "axis_x", "axis_y", "axis_z"}
};

/// every known kind, in documentation order
const std::vector<ReferenceKind>& reference_kinds();

/// the kind with this name, or nullptr
const ReferenceKind* find_reference_kind(const std::string& name);

}  // namespace cairn

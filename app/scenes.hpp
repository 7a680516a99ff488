#pragma once
/// The scenes shipped with cairn: where they live, their names, and resolving a name to a file.

#include <string>
#include <vector>

namespace cairn {

/// One shipped scene file.
struct SceneEntry {
    std::string name;   ///< path under the scenarios dir without ".toml", e.g. "paper/stability"
    std::string path;   ///< full path of the file
};

/// the scenarios dir: $CAIRN_SCENARIOS if set, else the one of the source tree
std::string scenarios_dir();

/// every *.toml under the scenarios dir, sorted by name
std::vector<SceneEntry> shipped_scenes();

/// a path to an existing file is taken as is; otherwise a scene name ("paper/stability") is looked
/// up in the scenarios dir; throws cairn::Error when neither exists
std::string resolve_scene(const std::string& arg);

}  // namespace cairn

#include "scenes.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "error.hpp"
#include "suggest.hpp"

namespace fs = std::filesystem;

namespace cairn {

std::string scenarios_dir() {
    if (const char* env = std::getenv("CAIRN_SCENARIOS"); env && *env) return env;
    return CAIRN_SCENARIOS_DIR;
}

std::vector<SceneEntry> shipped_scenes() {
    std::vector<SceneEntry> list;
    const fs::path root = scenarios_dir();
    std::error_code ec;
    if (!fs::is_directory(root, ec)) return list;
    for (const auto& f : fs::recursive_directory_iterator(root, ec)) {
        if (!f.is_regular_file() || f.path().extension() != ".toml") continue;
        fs::path rel = fs::relative(f.path(), root);
        if (*rel.begin() == "sweeps") continue;   // sweep plans (cairn sweep), not scenes
        rel.replace_extension();
        list.push_back({rel.generic_string(), f.path().string()});
    }
    std::sort(list.begin(), list.end(),
              [](const SceneEntry& a, const SceneEntry& b) { return a.name < b.name; });
    return list;
}

std::string resolve_scene(const std::string& arg) {
    std::error_code ec;
    if (fs::is_regular_file(arg, ec)) return arg;
    fs::path candidate = fs::path(scenarios_dir()) / arg;
    if (candidate.extension() != ".toml") candidate += ".toml";
    if (fs::is_regular_file(candidate, ec)) return candidate.string();
    std::vector<std::string> names;
    for (const auto& s : shipped_scenes()) names.push_back(s.name);
    std::string name = arg;
    if (name.size() > 5 && name.compare(name.size() - 5, 5, ".toml") == 0) name.resize(name.size() - 5);
    throw Error("no scene '" + arg + "': not a file, and not a scene name in " + scenarios_dir() +
                did_you_mean(name, names) + " (cairn list shows the scenes)");
}

}  // namespace cairn

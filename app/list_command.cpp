#include <algorithm>
#include <iostream>

#include "commands.hpp"
#include "error.hpp"
#include "registry.hpp"
#include "scene/scene_io.hpp"
#include "scenes.hpp"

namespace cairn {

namespace {

/// characters (not bytes) of a UTF-8 string, for aligning columns
size_t width_of(const std::string& s) {
    size_t n = 0;
    for (unsigned char c : s) n += (c & 0xC0) != 0x80;
    return n;
}

/// `s` padded with spaces to `width` characters plus a gap of two
std::string padded(const std::string& s, size_t width) {
    return s + std::string(width - std::min(width, width_of(s)) + 2, ' ');
}

/// the first line of a scene's description, or why it cannot be loaded
std::string describe(const SceneEntry& s) {
    try {
        const Scene scene = load_scene(s.path);
        return scene.description.substr(0, scene.description.find('\n'));
    } catch (const Error& e) {
        return std::string("(cannot load: ") + e.what() + ")";
    }
}

}  // namespace

int list_command() {
    const auto scenes = shipped_scenes();
    std::cout << "scenes in " << scenarios_dir() << ":\n";
    if (scenes.empty()) std::cout << "  (none)\n";
    size_t width = 0;
    for (const auto& s : scenes) width = std::max(width, width_of(s.name));
    for (const auto& s : scenes) std::cout << "  " << padded(s.name, width) << describe(s) << "\n";
    std::cout << "\nbackends:\n";
    for (const auto& b : available_backends()) {
        std::cout << "  " << b.name << ": " << b.description << "\n";
        size_t fw = 0;
        for (const auto& f : b.capabilities) fw = std::max(fw, width_of(to_string(f.feature)));
        for (const auto& f : b.capabilities) {
            std::cout << "    " << padded(to_string(f.feature), fw);
            if (f.how.empty()) std::cout << to_string(f.support) << "\n";
            else std::cout << padded(to_string(f.support), 11) << f.how << "\n";
        }
    }
    return kExitOk;
}

}  // namespace cairn

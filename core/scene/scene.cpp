#include "scene/scene.hpp"

namespace cairn {

int Scene::block_index(const std::string& block_name) const {
    for (std::size_t i = 0; i < blocks.size(); ++i)
        if (blocks[i].name == block_name) return static_cast<int>(i);
    return -1;
}

const char* to_string(Shape s) {
    switch (s) {
        case Shape::box: return "box";
        case Shape::hexahedron: return "hexahedron";
    }
    return "?";
}

const char* to_string(BlockModel m) {
    switch (m) {
        case BlockModel::rigid: return "rigid";
        case BlockModel::deformable: return "deformable";
    }
    return "?";
}

const char* to_string(MassScheme m) {
    switch (m) {
        case MassScheme::lumped: return "lumped";
        case MassScheme::consistent: return "consistent";
        case MassScheme::barycentre: return "barycentre";
        case MassScheme::corrected: return "corrected";
    }
    return "?";
}

const char* to_string(ContactScheme s) {
    return s == ContactScheme::paper ? "paper" : "overlap";
}

const char* to_string(ContactDampingRule r) {
    switch (r) {
        case ContactDampingRule::none: return "none";
        case ContactDampingRule::ratio: return "ratio";
        case ContactDampingRule::time: return "time";
    }
    return "?";
}

}  // namespace cairn

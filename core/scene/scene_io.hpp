#pragma once
/// Reading scene files (TOML) into a validated Scene. Every error is a cairn::Error whose message
/// names the file, the line, the key and the bad value; nothing is half-read.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"

namespace cairn {

/// A command-line override `key=value`: a dotted key path and its value as TOML text
/// (a bare word that is not valid TOML is taken as a string).
struct Override {
    std::string key;     ///< e.g. "contact.friction" or "blocks.A.position"
    std::string value;   ///< e.g. "0.6", "[0, 0, 1]", "auto"
};

/// parse "key=value"; throws cairn::Error if there is no '=' or the key is empty
Override parse_override(const std::string& text);

/// read, override and validate a scene file
Scene load_scene(const std::string& path, const std::vector<Override>& overrides = {});

/// the same from TOML text; `source` names it in messages (a path, or e.g. "<test>")
Scene parse_scene(const std::string& toml_text, const std::string& source,
                  const std::vector<Override>& overrides = {});

/// set every free block's model: "rigid" or "deformable"; empty = the scene's own; throws
/// cairn::Error naming --model for any other value
void apply_model(Scene& scene, const std::string& model);

/// the validated scene with every parameter (after overrides), for run.json
nlohmann::json scene_to_json(const Scene& scene);

}  // namespace cairn

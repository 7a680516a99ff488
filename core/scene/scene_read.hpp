#pragma once
/// Internal to the scene loader: building a Scene from a parsed (and overridden) document.

#include <string>

#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace cairn::scene_detail {

/// validate the whole document and build the Scene; `source` is the scene file's path
Scene read_scene(const Sources& src, const toml::table& root, const std::string& source);

/// [blocks.NAME] (needs scene.materials)
void read_blocks(const TableReader& root, Scene& scene);
/// blocks may overlap at t = 0 by at most this fraction of the smaller block's shortest edge
/// (touching blocks, and the small initial penetrations of a scene set at its static rest)
constexpr double kOverlapTolerance = 0.01;
/// refuse two blocks (not both fixed) that overlap at t = 0 by more than the tolerance
void check_overlaps(const TableReader& root, const Scene& scene);
/// [loads.NAME] (needs scene.blocks)
void read_loads(const TableReader& root, Scene& scene);
/// [ground_motion] (needs scene.blocks and scene.source): adds one body load per free block and component
void read_ground_motion(const TableReader& root, Scene& scene);
/// the body loads −m·a_g(t)·direction of scene.ground_motion, one per free block and component
void add_ground_motion_loads(Scene& scene);
/// [probes.NAME] (needs scene.blocks)
void read_probes(const TableReader& root, Scene& scene);

/// the index of the block named by `item` (a string), failing if there is none
int block_named(const Item& item, const Scene& scene);
/// a sub-table of `parent` as a reader of its own keys (the value must be a table)
TableReader sub_table(const TableReader& parent, const std::string& key,
                      const std::vector<std::string>& allowed);

}  // namespace cairn::scene_detail

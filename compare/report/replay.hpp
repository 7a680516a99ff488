#pragma once
/// The interactive 3-D replay of runs (docs/visualisation.md): a self-contained HTML page (three.js
/// bundled in, works offline) with the blocks posed per sample, play/pause, a time slider, a time
/// readout, orbit controls, and one view per run side by side.

#include <array>
#include <string>
#include <vector>

#include "backend/backend.hpp"

namespace cairn {

/// One block as the replay draws it.
struct ReplayBlock {
    std::string name;               ///< block name (shown nowhere but kept for tooltips)
    bool fixed = false;             ///< drawn grey at its scene pose
    std::array<Vec3, 8> corners;    ///< fixed: world, m; free: block frame about the centre of mass, m
};

/// One run's replay: its blocks and the pose of every free block per frame.
struct ReplayRun {
    std::string label;                      ///< shown above the view (e.g. the backend)
    std::vector<ReplayBlock> blocks;        ///< Scene::blocks order
    Vec3 up = Vec3::UnitZ();                ///< the view's up: against the scene's gravity (z without gravity)
    std::vector<double> t;                  ///< frame times, s
    std::vector<std::vector<double>> poses; ///< per frame: x, y, z (m), qw, qx, qy, qz per free block
    long long stride = 1;                   ///< samples per frame (doubles when the frames pass kMaxReplayFrames)
    long long seen = 0;                     ///< samples offered to add_frame
};

/// frames kept per run at most: beyond, every other frame goes and the stride doubles (bounded
/// memory and page size for any run length)
constexpr size_t kMaxReplayFrames = 4000;
/// pose numbers kept per run at most (about 10 MB of page): a scene of many blocks keeps fewer
/// frames, down to kMinReplayFrames
constexpr size_t kMaxReplayNumbers = 1000000;
constexpr size_t kMinReplayFrames = 100;

/// the frame limit of a run with `free_blocks` free blocks
size_t replay_frame_limit(size_t free_blocks);

/// the blocks of `scene` for a replay labelled `label`, no frames yet
ReplayRun replay_run(const std::string& label, const Scene& scene);

/// add a sample as a frame (keeping every stride-th sample)
void add_frame(ReplayRun& run, const Sample& s);

/// true when this build has the replay script (node and npm were found when cairn was built)
bool replay_available();

/// the whole page of the runs, titled `title`; throws cairn::Error when !replay_available()
std::string replay_html(const std::string& title, const std::vector<ReplayRun>& runs);

}  // namespace cairn

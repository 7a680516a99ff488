#pragma once
/// A run's 3-D view for ParaView, written as the run goes: per output sample one .vtu of the
/// blocks as hexahedral cells and one .vtu of the contact points as vertex cells, and two .pvd
/// collections that make time series of them (docs/visualisation.md).

#include <string>
#include <utility>
#include <vector>

#include "backend/backend.hpp"
#include "output/vtk_writer.hpp"

namespace cairn {

/// the VTK grid of every block of `scene` in the state `s`: fixed blocks from the scene, rigid
/// blocks posed by their sampled centre and orientation, deformable blocks (backend.block_mesh)
/// as their elements. Cell fields block_id, velocity (m/s), angular_velocity (rad/s),
/// rotation_angle (rad, from the initial orientation); point fields block_id, velocity (m/s)
VtkGrid blocks_grid(const Scene& scene, const Sample& s, const Backend& backend);

/// the contact points as vertex cells with point fields normal, normal_force (N), shear_force (N),
/// block_a, block_b
VtkGrid contacts_grid(const std::vector<ContactPoint>& contacts);

/// `name` with every character but letters, digits, '-' and '_' replaced by '_', at most 64
/// characters, "scene" when empty: safe as a file name
std::string safe_file_stem(const std::string& name);

/// Writes the files of a run's samples into one directory.
class VtkSeries {
public:
    /// write into `dir` (created if missing); the .pvd files are named after the scene
    VtkSeries(const Scene& scene, std::string dir);
    /// write blocks_NNNNNN.vtu and contacts_NNNNNN.vtu of one sample, reading meshes and
    /// contact points from `backend` (which must be in the sampled state)
    void add(const Sample& s, const Backend& backend);
    /// write NAME.pvd and NAME_contacts.pvd listing every sample added
    void finish();

private:
    const Scene& scene_;
    std::string dir_, stem_;
    std::vector<std::pair<double, std::string>> blocks_, contacts_;   // (t in s, file)
};

}  // namespace cairn

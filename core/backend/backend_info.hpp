#pragma once
/// What every layer may know about a backend: its name, what it represents of a scene, whether two
/// of its runs may overlap, how it is made. The registry (backends/registry.hpp) is the only place
/// that lists the backends; compare and the run layer take these facts as values.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "backend/capabilities.hpp"

namespace cairn {

/// How a backend's contact works.
enum class ContactModel {
    penalty,   ///< springs per hitting point (kn per unit area), elastic-then-Coulomb shear
    rigid,     ///< a rigid-contact solver (impulses or constraints); "matched" mode adds springs
};

/// makes a new backend
using BackendFactory = std::function<std::unique_ptr<Backend>()>;

/// the rotational inertia (kg·m², block axes, about the block's centre) of block b of a scene as
/// the engine's own model assembles it
using BlockInertia = std::function<Mat3(const Scene& scene, int block)>;

/// The facts of one backend.
struct BackendInfo {
    std::string name;                           ///< registry name, e.g. "dem"
    std::string description;                    ///< one line
    std::vector<FeatureSupport> capabilities;   ///< the capability matrix row
    ContactModel contact = ContactModel::rigid;     ///< its own contact
    std::string solver;                         ///< its contact solver and settings, one line
    /// two runs may go on at once in one process (false: a library with global state)
    bool thread_safe = true;
    BackendFactory make;                        ///< a new backend
    /// its own assembled inertia of a deformable block (the mesh-inertia study); empty: not told
    BlockInertia block_inertia;
};

/// how `backend` represents `feature` (its capability row; none when the row does not name it)
Support support_of(const BackendInfo& backend, Feature feature);

/// the facts named `name` in `list`; throws cairn::Error naming the available ones otherwise
const BackendInfo& find_backend(const std::vector<BackendInfo>& list, const std::string& name);

}  // namespace cairn

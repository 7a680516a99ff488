#pragma once
/// What `cairn validate` runs: the paper's cases, and per case the variants (backend, contact mode,
/// block model) whose results its analytic references can judge.

#include <string>
#include <vector>

#include "backend/backend_info.hpp"
#include "cases/case_analysis.hpp"
#include "scene/scene.hpp"

namespace cairn::validation {

/// One way of running a case.
struct Variant {
    std::string name;                    ///< e.g. "dem-rigid", "bullet-matched"
    std::string backend;                 ///< registry name
    std::string contact_mode = "rigid";  ///< RunOptions::contact_mode of the reference engines
    std::string model = "rigid";         ///< model of every free block: "rigid" or "deformable"
    /// the contact as reports name it: "penalty" for dem, else the engine's mode
    std::string contact_label() const { return backend == "dem" ? "penalty" : contact_mode; }
    /// true when the contact is a penalty spring (dem, or an engine in matched mode)
    bool penalty() const { return backend == "dem" || contact_mode == "matched"; }
};

/// the contact a variant's runs have, for the case analyses (the reference block's mesh divisions
/// across its base come from `scene` when the variant is deformable)
cases::ContactKind contact_kind(const Variant& v, const Scene& scene);

/// the paper's validation cases, in report order (scene names under scenarios/paper/)
const std::vector<std::string>& paper_cases();

/// the variants of one backend: a penalty engine (dem) runs rigid blocks and, when it represents
/// them, deformable ones; a rigid-contact engine runs each of `modes` ("rigid", "matched") it can
/// take — "matched" only when it stands in some penalty stiffness (its capability row)
std::vector<Variant> backend_variants(const BackendInfo& backend, const std::vector<std::string>& modes);

/// the variants that make sense for `scene` among `backends` (in that order): the penalty engine's
/// block models always; the rigid-contact engines in each contact mode the scene's reference kind
/// can judge (cases::CaseKind::contact_modes); none for a scene without a reference. Throws
/// cairn::Error for a reference kind without a CaseKind, or a scene its oracles cannot model
/// (cases::CaseKind::check).
std::vector<Variant> variants_for(const Scene& scene, const std::vector<BackendInfo>& backends);

}  // namespace cairn::validation

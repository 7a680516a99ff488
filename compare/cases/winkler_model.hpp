#pragma once
/// The rigid block on a no-tension Winkler base (oracle::WinklerRocking) as the model of a scene's
/// reference block on dem's overlap contact, rocking about a given axis: shared by the kinds that
/// judge dem against it (winkler_rocking, ground_rocking).

#include <string>
#include <vector>

#include "analytic/winkler_rocking.hpp"
#include "cases/case_analysis.hpp"

namespace cairn::cases {

/// the oracle of the scene's reference block rocking about the unit block-frame axis `axis`
/// (horizontal): its extent across the axis, up and along it, the scene's contact law, its faces
/// cut as dem cuts them (mesh divisions × the overlap sub-division)
oracle::WinklerRocking winkler_model(const Scene& scene, ContactKind contact, const Vec3& axis);

/// why a variant's contact is not the Winkler model's (rigid contact, an engine's matched contact,
/// the paper scheme, damping by time, too many cells), or empty when the oracle models it
std::string winkler_unmodelled(const Scene& scene, ContactKind contact, const Vec3& axis);

/// θ of the oracle's samples at the given ascending times, linear between them (rad)
std::vector<double> winkler_angles(const oracle::WinklerTrace& tr, const std::vector<double>& t);

}  // namespace cairn::cases

#pragma once
// scenes built in code for the reference-engine tests (no scene file needed)

#include <memory>
#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "cases/case_analysis.hpp"
#include "scene/scene.hpp"
#include "scene/scene_builder.hpp"
#include "support/scene_builder.hpp"

namespace cairn::test {

/// an empty scene: stone (2600 kg/m³, E = 30 GPa, ν = 0.2), kn = ks = 3e7 N/m³, μ = 0.6, dt = 1e-4 s
Scene base_scene(const std::string& name);

/// add an axis-aligned box with its centre at `centre` (m); returns its index
using cairn::add_box;

/// add a box-shaped block given as a general hexahedron (Shape::hexahedron); returns its index
int add_hexahedron_box(Scene& scene, const std::string& name, const Vec3& size, const Vec3& centre,
                       bool fixed);

/// the reference-engine backends built into this binary (every registered name except "dem")
std::vector<std::string> engine_names();

/// every backend built into this binary, the in-house dem included
std::vector<std::string> all_backend_names();

/// the backends with a matched (penalty) contact mode: all but those whose capability row has no
/// penalty stiffness (siconos: rigid non-smooth contact only)
std::vector<std::string> matched_backend_names();

/// true when `engine` has the matched contact mode
bool has_matched_mode(const std::string& engine);

/// a backend `engine` built for `scene` in contact mode `mode` ("rigid" or "matched")
std::unique_ptr<Backend> build_backend(const std::string& engine, const Scene& scene, const std::string& mode);

/// the run of `scene` on `engine` in contact mode `mode` at the backend's own step, sampled every
/// `every` seconds (and at the end); throws cairn::Error naming the engine if it goes unstable
std::vector<Sample> sampled_run(const std::string& engine, const Scene& scene, const std::string& mode = "rigid",
                                double every = 1e-3);

/// checks that every judged metric of an analysis passes (each shown with its basis when one does
/// not); returns how many were judged
int check_judged(const cases::CaseAnalysis& a);

/// the metric of an analysis named `name` (fails the test when there is none)
const metrics::Metric& find_metric(const cases::CaseAnalysis& a, const std::string& name);

/// the text of a shipped scene file, `relative` to scenarios/ (e.g. "structures/column_pushover.toml"),
/// to edit before parse_scene; fails the test when it cannot be read
std::string shipped_scene_text(const std::string& relative);

/// rotation angle about y of a rotation that is a pure y rotation, rad
double angle_about_y(const Quat& q);

}  // namespace cairn::test

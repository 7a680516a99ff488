// Google Benchmark of the in-house engine's kernels: hex8 internal forces and a whole step,
// in element updates per second, for meshes of 1 to 32³ elements on 1 and 2 threads.
// internal_force: box mesh (parallelepipeds, one J⁻¹ per element); _distorted: general trilinear
// elements (J⁻¹ per Gauss point, 8x the geometry traffic); _damped: with β strain-rate damping.
// GFLOPs counts the batched kernel's flops per element (dem::hex8_batch_flops) per real second.
// On a shared machine compare CPU time too: real time includes waiting for the core.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "bench/wall_bench.hpp"
#include "dem/dem_backend.hpp"
#include "dem/deformable/deformable_body.hpp"
#include "dem/deformable/hex8_batch.hpp"
#include "dem/mesh.hpp"
#include "geometry/hexahedron.hpp"
#include "run/core_pool.hpp"
#include "scene/scene_builder.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

namespace {

// the corners of a 1 m cube, distorted (a general trilinear mesh: J⁻¹ per Gauss point) or not
// (parallelepipeds: one J⁻¹ per element)
Corners cube(bool distorted) {
    Corners c = box_corners(Vec3(1, 1, 1));
    if (distorted) c[6] += Vec3(0.1, 0.05, 0.08), c[1] += Vec3(0.04, -0.03, 0.0);
    return c;
}

// internal forces of an n³ mesh of a 1 m cube with a small smooth deformation; beta in µs
void internal_force_case(benchmark::State& state, bool distorted, double beta) {
    const int n = int(state.range(0));
    set_openmp_threads(int(state.range(1)));
    dem::Mesh mesh = dem::make_mesh(cube(distorted), {n, n, n});
    dem::DeformableBody body(mesh, test::stone(), MassScheme::lumped, beta,
                             std::vector<char>(mesh.nodes.size(), 0));
    std::vector<Vec3> x = mesh.nodes, v(x.size(), Vec3::Zero()), f(x.size());
    for (auto& p : x) p += 1e-4 * Vec3(std::sin(3 * p.y()), std::cos(2 * p.z()), std::sin(p.x()));
    for (auto& w : v) w = Vec3(0.01, -0.02, 0.03);
    for (auto _ : state) {
        std::fill(f.begin(), f.end(), Vec3::Zero());
        benchmark::DoNotOptimize(body.add_internal_forces(x, v, f));
    }
    const double updates = double(state.iterations()) * double(body.element_count());
    state.SetItemsProcessed(int64_t(updates));
    state.counters["elements"] = double(body.element_count());
    // useful flops of the batched kernel (padding lanes not counted), per second of real time
    state.counters["GFLOPs"] = benchmark::Counter(updates * dem::hex8_batch_flops(beta > 0) * 1e-9,
                                                  benchmark::Counter::kIsRate);
}

void internal_force(benchmark::State& state) { internal_force_case(state, false, 0.0); }
void internal_force_distorted(benchmark::State& state) { internal_force_case(state, true, 0.0); }
void internal_force_damped(benchmark::State& state) { internal_force_case(state, false, 1e-6); }

// a scene of one deformable n³ cube; `on_base`: resting on a fixed rigid cube (contact included),
// otherwise spinning in free flight (no contact: the element path of the step alone)
Scene cube_scene(int n, bool on_base) {
    Scene s = test::stone_scene(0.6);
    s.name = "bench";
    BlockDef& a = s.blocks[add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5), false)];
    a.model = BlockModel::deformable;
    a.mesh.divisions = {n, n, n};
    if (on_base) add_box(s, "B", Vec3(1, 1, 1), Vec3(0, 0, -0.5), true);
    else a.angular_velocity = Vec3(1.0, 2.0, 0.5);
    return s;
}

// whole dem steps, in element updates per second
void steps(benchmark::State& state, bool on_base) {
    const int n = int(state.range(0));
    set_openmp_threads(int(state.range(1)));
    Scene s = cube_scene(n, on_base);
    auto backend = dem_backend_info().make();
    backend->build(s, RunOptions{});
    for (auto _ : state) benchmark::DoNotOptimize(backend->step());
    state.SetItemsProcessed(state.iterations() * int64_t(n) * n * n);
}

// whole steps of an n³ deformable cube resting on a fixed rigid cube (contact included)
void whole_step(benchmark::State& state) { steps(state, true); }

// whole steps of an n³ deformable cube spinning in free flight (no contact)
void whole_step_free(benchmark::State& state) { steps(state, false); }

// steps of the 300-brick running-bond wall of `cairn bench wall` (30 courses of 10 bricks of
// 0.4 × 0.2 × 0.2 m at kn = 3e9 N/m³, each course at its static penetration, dt = 1e-4 s), with
// the paper's grid (sub 0: its default 0.1 m spacing) or the overlap scheme with sub×sub
// sub-contacts per hitting face: the cost of contact at the same kn. The wall is not at rest
// (the top course is shifted whole by half a brick: its end brick, its centre over the edge of the
// course below, tips): each repetition steps the same kWallSteps from the same start, so both
// schemes time the same motion
constexpr int kWallSteps = 2000;   // 0.2 s of the wall's motion at dt = 1e-4 s

void wall_step(benchmark::State& state) {
    set_openmp_threads(int(state.range(1)));
    Scene s = bench::wall_scene(30, 10, bench::wall_setups()[1]);
    s.contact.scheme = state.range(0) == 0 ? ContactScheme::paper : ContactScheme::overlap;
    if (state.range(0) > 0) s.contact.subdivision = int(state.range(0));
    auto backend = dem_backend_info().make();
    backend->build(s, RunOptions{});
    for (auto _ : state) benchmark::DoNotOptimize(backend->step());
    state.SetItemsProcessed(state.iterations());
}

void meshes(benchmark::internal::Benchmark* b) {
    for (int threads : {1, 2})
        for (int n : {1, 2, 4, 8, 16, 32}) b->Args({n, threads});
    b->ArgNames({"n", "threads"})->UseRealTime();
}

}  // namespace

BENCHMARK(internal_force)->Apply(meshes);
BENCHMARK(internal_force_distorted)->Apply(meshes);
BENCHMARK(internal_force_damped)->Apply(meshes);
BENCHMARK(whole_step)->Apply(meshes);
BENCHMARK(whole_step_free)->Apply(meshes);
BENCHMARK(wall_step)
    ->ArgsProduct({{0, 1, 2, 4}, {1, 2}})
    ->ArgNames({"sub", "threads"})
    ->Iterations(kWallSteps)
    ->UseRealTime();
BENCHMARK_MAIN();

/// \file
/// \brief Timings of the shape builders: mesh decomposition in the three modes (L-bracket,
/// U-fixture, a 2,000-triangle torus), verified exact hulls of 8..2,000 points, and the
/// circumscribed cylinder and sphere polytopes.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

#include "geometry/mesh_fixtures.hpp"
#include "grpvss/exact/circumscribed_shapes.hpp"
#include "grpvss/exact/mesh_decomposition.hpp"
#include "grpvss/exact/mesh_point_hull.hpp"

namespace {

using grpvss::TriangleMesh;
using namespace grpvss::geometry;
namespace meshes = grpvss::testing::meshes;

void decompose(benchmark::State& state, const TriangleMesh& mesh) {
  DecompositionOptions options;
  options.mode = static_cast<DecomposeMode>(state.range(0));
  std::size_t pieces = 0;
  for (auto _ : state) {
    const ConvexPieces result = decompose_mesh(mesh, options);
    pieces = result.pieces.size();
    benchmark::DoNotOptimize(pieces);
  }
  state.counters["pieces"] = static_cast<double>(pieces);
  state.SetLabel(std::string(decompose_mode_name(options.mode)));
}

void BM_DecomposeLBracket(benchmark::State& state) { decompose(state, meshes::l_bracket()); }
void BM_DecomposeUFixture(benchmark::State& state) { decompose(state, meshes::u_fixture()); }
/// The U-fixture with every triangle split 64-fold: 1,792 triangles in STL layout (no shared
/// vertices), still 2 reflex edges — the usual CAD mesh: many triangles per flat face.
void BM_DecomposeUFixture1792(benchmark::State& state) {
  decompose(state, meshes::subdivided(meshes::u_fixture(), 3));
}
/// Torus, 50 x 20 segments: 2,000 triangles, 1,000 vertices, genus 1, ~1,000 reflex edges.
void BM_DecomposeTorus2000(benchmark::State& state) {
  decompose(state, meshes::torus(50, 20, 3.0, 1.0));
}

BENCHMARK(BM_DecomposeLBracket)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecomposeUFixture)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecomposeUFixture1792)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecomposeTorus2000)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);
// The exact mode on the torus takes minutes (Nef decomposition into ~1,300 pieces): only
// with GRPVSS_LONG_BENCH=1.
[[maybe_unused]] const bool kLongTorus = std::getenv("GRPVSS_LONG_BENCH") != nullptr &&
                        benchmark::RegisterBenchmark("BM_DecomposeTorus2000", BM_DecomposeTorus2000)
                            ->Arg(2)
                            ->Iterations(1)
                            ->Unit(benchmark::kSecond) != nullptr;

/// Verified exact hull (mesh_point_hull: CGAL hull + exact containment of every point) of
/// n points on a sphere (all of them extreme: the worst case).
void BM_MeshPointHull(benchmark::State& state) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < state.range(0); ++i) {
    points.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized() * 100.0);
  }
  std::vector<ShapeWarning> warnings;
  for (auto _ : state) {
    benchmark::DoNotOptimize(mesh_point_hull(points, 0.0, "bench", "points", warnings));
  }
}
BENCHMARK(BM_MeshPointHull)->Arg(8)->Arg(32)->Arg(128)->Arg(512)->Arg(2000)->Unit(benchmark::kMillisecond);

void BM_CircumscribedCylinder(benchmark::State& state) {
  const double overshoot = 1.0 / static_cast<double>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(circumscribed_cylinder(0.05, 0.3, overshoot));
}
BENCHMARK(BM_CircumscribedCylinder)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_CircumscribedSphere(benchmark::State& state) {
  const double overshoot = 1.0 / static_cast<double>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(circumscribed_sphere(0.05, overshoot));
}
BENCHMARK(BM_CircumscribedSphere)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace

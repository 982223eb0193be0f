// Big hulls (issue #22 point 4; docs/performance.md#big-hulls): the geometry core on convex
// hulls of 8 to 2,000 vertices, as real CAD link meshes have them (the UR5e's collision
// meshes have 73-998 vertices). Hull A: N points on the unit sphere (seeded, every point a
// vertex); B: its copy turned about z and moved 2.1 along x (separated by ~0.1) or 1.9
// (overlapping). Arg: N.
#include <cmath>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include "grpvss/exact/certified_query.hpp"
#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/exact_contact.hpp"
#include "grpvss/exact/polytope_skeleton.hpp"
#include "grpvss/geometry/gjk.hpp"
#include "grpvss/geometry/hull_skeleton.hpp"

namespace grpvss::geometry {
namespace {

using Points = std::vector<Eigen::Vector3d>;

Points sphere_points(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Points points;
  while (static_cast<int>(points.size()) < n) {
    Eigen::Vector3d p(normal(rng), normal(rng), normal(rng));
    if (p.norm() > 1e-3) points.push_back(p.normalized());
  }
  return points;
}

Points moved(const Points& points, double dx) {
  const Eigen::Isometry3d X =
      Eigen::Translation3d(dx, 0.0, 0.0) * Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ());
  Points out;
  for (const auto& p : points) out.push_back(X * p);
  return out;
}

std::vector<Eigen::Vector3d> directions() {
  return sphere_points(64, 7);
}

void big_hull_args(benchmark::internal::Benchmark* b) {
  for (int n : {8, 32, 128, 512, 2000}) b->Arg(n);
}

// The exact hull (ConvexPolytope::from_points), what a cell builds once per link mesh.
void BM_BigHullFromPoints(benchmark::State& state) {
  const Points a = sphere_points(state.range(0), 1);
  for (auto _ : state) benchmark::DoNotOptimize(ConvexPolytope::from_points(a));
}
BENCHMARK(BM_BigHullFromPoints)->Apply(big_hull_args)->Unit(benchmark::kMicrosecond);

// One support query by a linear scan (64 directions per iteration; counter per_query).
void BM_BigHullSupportScan(benchmark::State& state) {
  const Points a = sphere_points(state.range(0), 1);
  const auto ds = directions();
  for (auto _ : state) {
    for (const auto& d : ds) benchmark::DoNotOptimize(support_index(a, d));
  }
  state.counters["per_query"] = benchmark::Counter(
      64.0 * state.iterations(), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BigHullSupportScan)->Apply(big_hull_args)->Unit(benchmark::kMicrosecond);

// The same queries by climbing the vertex graph, each from the previous answer (as GJK's
// warm-started climbs along a motion).
void BM_BigHullSupportClimb(benchmark::State& state) {
  const Points a = sphere_points(state.range(0), 1);
  const HullSkeleton skeleton = hull_skeleton(ConvexPolytope::from_points(a), state.range(0));
  const auto ds = directions();
  int at = 0;
  for (auto _ : state) {
    for (const auto& d : ds) {
      at = climb_support_index(a, skeleton, at, d);
      benchmark::DoNotOptimize(at);
    }
  }
  state.counters["per_query"] = benchmark::Counter(
      64.0 * state.iterations(), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BigHullSupportClimb)->Apply(big_hull_args)->Unit(benchmark::kMicrosecond);

// The certified pair query with its separation witness (separated pair), without and with
// the skeleton of A for GJK's supports.
void BM_BigHullCertifiedWitness(benchmark::State& state) {
  const Points a = sphere_points(state.range(0), 1);
  const Points b = moved(a, 2.1);
  for (auto _ : state) benchmark::DoNotOptimize(certified_pair_query(a, b));
}
BENCHMARK(BM_BigHullCertifiedWitness)->Apply(big_hull_args)->Unit(benchmark::kMicrosecond);

void BM_BigHullCertifiedWitnessClimb(benchmark::State& state) {
  const Points a = sphere_points(state.range(0), 1);
  const Points b = moved(a, 2.1);
  const HullSkeleton skeleton = hull_skeleton(ConvexPolytope::from_points(a), state.range(0));
  int hint = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(certified_pair_query(a, b, nullptr, &skeleton, &hint));
  }
}
BENCHMARK(BM_BigHullCertifiedWitnessClimb)->Apply(big_hull_args)->Unit(benchmark::kMicrosecond);

// The overlap proof (overlapping pair).
void BM_BigHullCertifiedOverlap(benchmark::State& state) {
  const Points a = sphere_points(state.range(0), 1);
  const Points b = moved(a, 1.9);
  for (auto _ : state) benchmark::DoNotOptimize(certified_pair_query(a, b));
}
BENCHMARK(BM_BigHullCertifiedOverlap)->Apply(big_hull_args)->Unit(benchmark::kMicrosecond);

// The exact check on prebuilt exact hulls (classify_exact), separated pair.
void BM_BigHullClassifyExact(benchmark::State& state) {
  const ConvexPolytope a = ConvexPolytope::from_points(sphere_points(state.range(0), 1));
  const ConvexPolytope b = ConvexPolytope::from_points(moved(a.vertices(), 2.1));
  for (auto _ : state) benchmark::DoNotOptimize(classify_exact(a, b));
  state.SetLabel(to_string(classify_exact(a, b)));
}
BENCHMARK(BM_BigHullClassifyExact)->Apply(big_hull_args)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace grpvss::geometry

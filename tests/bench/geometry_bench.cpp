// Google Benchmark suite for the geometry stage: exact expansion, certified pair queries,
// exact classification, witnesses, interference points and one whole IBM 7545 configuration
// against 2 and 500 obstacles. Numbers and the command are in docs/performance.md.

#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "grpvss/geometry/broadphase.hpp"
#include "grpvss/geometry/centroid_cull.hpp"
#include "grpvss/exact/certified_query.hpp"
#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/exact_contact.hpp"
#include "grpvss/exact/minkowski_offset.hpp"
#include "grpvss/geometry/separation_witness.hpp"
#include "support/random_shapes.hpp"

namespace grpvss::geometry {
namespace {

using Eigen::Vector3d;
using Points = std::vector<Vector3d>;

// Every "x,y,z" line of a thesis data file, in order (the io stage does the real parsing;
// the bench only needs the points).
Points read_xyz_lines(const std::string& relative, int skip_lines) {
  std::ifstream in(std::string(GRPVSS_SOURCE_DIR) + "/" + relative);
  std::string line;
  Points points;
  for (int n = 0; std::getline(in, line); ++n) {
    if (n < skip_lines || std::count(line.begin(), line.end(), ',') != 2) continue;
    for (char& c : line) if (c == ',') c = ' ';
    std::istringstream fields(line);
    Vector3d p;
    fields >> p.x() >> p.y() >> p.z();
    points.push_back(p);
  }
  return points;
}

// The 11 hulls (16 points each, link frames) of data/ibm7545/robot.txt: links 0..4 own
// 4, 2, 2, 2, 1 hulls.
struct RobotHulls {
  std::vector<Points> hulls_L;
  std::vector<int> link_of_hull;
};

RobotHulls ibm7545_hulls() {
  const Points all = read_xyz_lines("data/ibm7545/robot.txt", 10);
  if (all.size() != 176) throw std::runtime_error("robot.txt: expected 176 hull points");
  RobotHulls robot;
  const int hulls_per_link[] = {4, 2, 2, 2, 1};
  int h = 0;
  for (int link = 0; link < 5; ++link) {
    for (int k = 0; k < hulls_per_link[link]; ++k, ++h) {
      robot.hulls_L.emplace_back(all.begin() + 16 * h, all.begin() + 16 * (h + 1));
      robot.link_of_hull.push_back(link);
    }
  }
  return robot;
}

std::vector<Points> thesis_obstacles() {
  const Points all = read_xyz_lines("data/ibm7545/environment.txt", 3);
  return {Points(all.begin(), all.begin() + 16), Points(all.begin() + 16, all.end())};
}

// A fixed configuration: link frames placed by fixed rigid transforms (the kinematics stage
// is not needed to measure geometry cost).
std::vector<Eigen::Isometry3d> fixed_link_poses() {
  std::vector<Eigen::Isometry3d> X_WL;
  for (int link = 0; link < 5; ++link) {
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.translate(Vector3d(4.0 * link, 2.0 * link, 0.0));
    X.rotate(Eigen::AngleAxisd(0.35 * link, Vector3d::UnitZ()));
    X_WL.push_back(X);
  }
  return X_WL;
}

Points transformed(const Eigen::Isometry3d& X_WL, const Points& p_L) {
  Points p_W;
  p_W.reserve(p_L.size());
  for (const auto& p : p_L) p_W.push_back(X_WL * p);
  return p_W;
}

// ---------------------------------------------------------------- expansion
void BM_ExpandHull(benchmark::State& state) {
  const auto shape = static_cast<OffsetShape>(state.range(0));
  const ConvexPolytope hull = ConvexPolytope::from_points(ibm7545_hulls().hulls_L[0]);
  for (auto _ : state) {
    benchmark::DoNotOptimize(minkowski_offset(hull, 0.5, shape));
  }
  state.SetLabel(shape == OffsetShape::kCube ? "cube" : "rhombicuboctahedron");
}
BENCHMARK(BM_ExpandHull)
    ->Arg(static_cast<int>(OffsetShape::kCube))
    ->Arg(static_cast<int>(OffsetShape::kRhombicuboctahedron))
    ->Unit(benchmark::kMicrosecond);

// ---------------------------------------------------------------- pairs
enum PairKind { kSeparatedPair = 0, kTouchingPair = 1, kOverlappingPair = 2 };

// A rotated 16-point prism and a second set separated by 1.0, exactly touching (point
// reflection through an extreme vertex, exact on a 2^-20 grid) or overlapping by ~0.5.
std::pair<Points, Points> make_pair(int kind) {
  std::mt19937_64 rng(1988);
  Points a = test::random_prism(rng, Vector3d::Zero(), 2.0);
  for (auto& p : a) {
    for (int k = 0; k < 3; ++k) p[k] = std::ldexp(std::round(std::ldexp(p[k], 20)), -20);
  }
  const Vector3d n = Vector3d(1.0, 0.5, 0.25).normalized();
  const Vector3d extreme = a[support_index(a, n)];
  Points b;
  for (const auto& p : a) b.push_back(2.0 * extreme - p);
  if (kind == kSeparatedPair) b = test::translated(b, n);
  if (kind == kOverlappingPair) b = test::translated(b, -0.5 * n);
  return {a, b};
}

void BM_CertifiedPairQuery(benchmark::State& state) {
  const auto [a, b] = make_pair(static_cast<int>(state.range(0)));
  const CertifiedPairResult first = certified_pair_query(a, b, nullptr);
  for (auto _ : state) {
    benchmark::DoNotOptimize(certified_pair_query(a, b, nullptr));
  }
  state.SetLabel(std::string(to_string(first.contact)) + " by " + to_string(first.decided_by));
}
BENCHMARK(BM_CertifiedPairQuery)
    ->Arg(kSeparatedPair)->Arg(kTouchingPair)->Arg(kOverlappingPair)
    ->Unit(benchmark::kMicrosecond);

void BM_CertifiedPairQueryWarmStart(benchmark::State& state) {
  const auto [a, b] = make_pair(kSeparatedPair);
  const CertifiedPairResult first = certified_pair_query(a, b, nullptr);
  const Vector3d previous_normal = first.witness->normal;
  for (auto _ : state) {
    benchmark::DoNotOptimize(certified_pair_query(a, b, &previous_normal));
  }
  state.SetLabel("separated, warm start from previous witness");
}
BENCHMARK(BM_CertifiedPairQueryWarmStart)->Unit(benchmark::kMicrosecond);

void BM_PairClassifyExact(benchmark::State& state) {
  const auto [a, b] = make_pair(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(classify_exact(a, b));
  }
  state.SetLabel(to_string(classify_exact(a, b)));
}
BENCHMARK(BM_PairClassifyExact)
    ->Arg(kSeparatedPair)->Arg(kTouchingPair)->Arg(kOverlappingPair)
    ->Unit(benchmark::kMicrosecond);

void BM_PairExactSeparationWitness(benchmark::State& state) {
  const auto [a, b] = make_pair(kSeparatedPair);
  for (auto _ : state) {
    benchmark::DoNotOptimize(exact_separation_witness(a, b));
  }
  state.SetLabel("separated, exact fallback witness");
}
BENCHMARK(BM_PairExactSeparationWitness)->Unit(benchmark::kMicrosecond);

void BM_InterferencePoints(benchmark::State& state) {
  const auto [a, b] = make_pair(kOverlappingPair);
  std::size_t count = 0;
  for (auto _ : state) {
    const auto points = interference_points(a, b);
    count = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  state.SetLabel("overlapping, " + std::to_string(count) + " points");
}
BENCHMARK(BM_InterferencePoints)->Unit(benchmark::kMicrosecond);

// Same pair on prebuilt exact hulls (a static obstacle, or an offset built once): the
// interference computation alone, without the two convex_hull_3 calls.
void BM_InterferencePointsPrebuilt(benchmark::State& state) {
  const auto [a, b] = make_pair(kOverlappingPair);
  const ConvexPolytope pa = ConvexPolytope::from_points(a);
  const ConvexPolytope pb = ConvexPolytope::from_points(b);
  std::size_t count = 0;
  for (auto _ : state) {
    const auto points = interference_points(pa, pb);
    count = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  state.SetLabel("overlapping, prebuilt hulls, " + std::to_string(count) + " points");
}
BENCHMARK(BM_InterferencePointsPrebuilt)->Unit(benchmark::kMicrosecond);

// What the verifier pays per interfering step: the placed link hull's POINTS are hulled
// from the link-frame template (ConvexPolytope::from_points_like; proofs/placed-hull.md),
// the static obstacle's hull was built once, then the exact interference points.
void BM_InterferencePointsPlacedFromTemplate(benchmark::State& state) {
  const auto [a, b] = make_pair(kOverlappingPair);
  // The link frame: a pose of a; the template is the exact hull there.
  std::mt19937_64 rng(4341);
  Eigen::Isometry3d X_WL = Eigen::Isometry3d::Identity();
  X_WL.linear() = test::random_rotation(rng);
  X_WL.translation() = Vector3d(0.25, -0.5, 0.125);
  Points a_L;
  for (const auto& p_W : a) a_L.push_back(X_WL.inverse() * p_W);
  const ConvexPolytope template_L = ConvexPolytope::from_points(ConvexPolytope::from_points(a_L).vertices());
  Points a_W;
  for (const auto& p_L : template_L.vertices()) a_W.push_back(X_WL * p_L);
  const ConvexPolytope pb = ConvexPolytope::from_points(b);
  const bool from_template = ConvexPolytope::from_template(a_W, template_L).has_value();
  std::size_t count = 0;
  for (auto _ : state) {
    const ConvexPolytope pa = ConvexPolytope::from_points_like(a_W, template_L);
    const auto points = interference_points(pa, pb);
    count = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  state.SetLabel(std::string("overlapping, placed hull from template") +
                 (from_template ? "" : " (FELL BACK)") + ", " + std::to_string(count) + " points");
}
BENCHMARK(BM_InterferencePointsPlacedFromTemplate)->Unit(benchmark::kMicrosecond);

// Exact hull of one rotated 16-point prism (the per-call cost of the point-set overloads).
void BM_HullFromPoints(benchmark::State& state) {
  const auto [a, b] = make_pair(kOverlappingPair);
  for (auto _ : state) benchmark::DoNotOptimize(ConvexPolytope::from_points(a));
  state.SetLabel("rotated 16-point prism");
}
BENCHMARK(BM_HullFromPoints)->Unit(benchmark::kMicrosecond);

// ---------------------------------------------------------------- one configuration
struct Scene {
  RobotHulls robot;
  std::vector<Points> obstacles_W;
  std::vector<CertifiedSphere> obstacle_spheres;
  StaticObstacleIndex index;
};

// 500 obstacles: random 16-point prisms (radius 2) in a 400-inch cube around the robot,
// none closer than 60 inches to the origin, plus 4 placed next to robot hulls.
Scene make_scene(int obstacle_count) {
  Scene scene;
  scene.robot = ibm7545_hulls();
  if (obstacle_count == 2) {
    scene.obstacles_W = thesis_obstacles();
  } else {
    std::mt19937_64 rng(4341);
    std::uniform_real_distribution<double> coordinate(-200.0, 200.0);
    const auto X_WL = fixed_link_poses();
    const int near = 4;
    for (int k = 0; k < near; ++k) {
      const int h = (3 * k + 1) % static_cast<int>(scene.robot.hulls_L.size());
      const Points hull_W = transformed(X_WL[scene.robot.link_of_hull[h]], scene.robot.hulls_L[h]);
      const Vector3d tip = hull_W[support_index(hull_W, Vector3d::UnitX())];
      scene.obstacles_W.push_back(test::random_prism(rng, tip + Vector3d(2.5, 0.0, 0.0), 2.0));
    }
    while (static_cast<int>(scene.obstacles_W.size()) < obstacle_count) {
      const Vector3d c(coordinate(rng), coordinate(rng), coordinate(rng));
      if (c.norm() < 60.0) continue;
      scene.obstacles_W.push_back(test::random_prism(rng, c, 2.0));
    }
  }
  for (const auto& o : scene.obstacles_W) scene.obstacle_spheres.push_back(certified_sphere(o));
  scene.index = StaticObstacleIndex(scene.obstacles_W);
  return scene;
}

// Everything a certified step does for geometry at one configuration: place the 11 hulls,
// broadphase, certified sphere cull, certified pair query on the survivors.
void BM_Configuration(benchmark::State& state) {
  const Scene scene = make_scene(static_cast<int>(state.range(0)));
  const auto X_WL = fixed_link_poses();
  const double margin = 1.0;  // tolerance 0.5 plus 0.5 of clearance wanted
  std::vector<int> candidates;
  int queries = 0, culled = 0, overlapping = 0;
  for (auto _ : state) {
    queries = culled = overlapping = 0;
    for (std::size_t h = 0; h < scene.robot.hulls_L.size(); ++h) {
      const Points hull_W = transformed(X_WL[scene.robot.link_of_hull[h]], scene.robot.hulls_L[h]);
      scene.index.candidates(Aabb::of_points(hull_W), margin, candidates);
      if (candidates.empty()) continue;
      const CertifiedSphere sphere = certified_sphere(hull_W);
      for (const int o : candidates) {
        if (certified_sphere_cull(sphere, scene.obstacle_spheres[o], margin).culled) {
          ++culled;
          continue;
        }
        ++queries;
        const CertifiedPairResult r = certified_pair_query(hull_W, scene.obstacles_W[o], nullptr);
        overlapping += r.contact != Contact::kSeparated;
        benchmark::DoNotOptimize(r);
      }
    }
  }
  state.SetLabel(std::to_string(scene.obstacles_W.size()) + " obstacles: " +
                 std::to_string(culled) + " sphere-culled, " + std::to_string(queries) +
                 " pair queries, " + std::to_string(overlapping) + " in contact");
}
BENCHMARK(BM_Configuration)->Arg(2)->Arg(500)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace grpvss::geometry

// Cost that grows with what is near, not with the cell (issue 22.5): the IBM 7545's clear
// two-move path (joint 1 swings 0 -> 2 -> 0 deg, about 12 in. from the sample's two
// obstacles) among N far-away unit boxes 300-800 in. away, as the resource test's
// many-obstacle cell. docs/performance.md#far-obstacles.
//
// - BM_VerifyAmongFarObstacles/N: what a cold `grpvss verify` does after reading its robot:
//   parse the environment text, build the cell (offsets, broadphase; obstacle hulls on first
//   use), verify the path certified. Counter `built`: obstacles whose exact hull was built.
// - BM_EagerObstacleHulls/N: the peer, what the cell did before: every obstacle's exact hull
//   (twice: its vertices, then the hull of its vertices) and certified sphere, up front.
#include <string>

#include <benchmark/benchmark.h>

#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "support/data_paths.hpp"

namespace {

using grpvss::test::kIbm7545Data;

// The sample environment's two obstacles and `far` unit boxes (2 in. tall) on a 5 in. grid.
std::string environment_text(int far) {
  const grpvss::Environment sample = grpvss::io::read_environment_file(kIbm7545Data + "environment.txt");
  std::string text = "90.\n1.\n" + std::to_string(far + 2) + "\n";
  for (const grpvss::HullPoints& hull : sample.obstacles) {
    text += "HULL " + std::to_string(hull.points.size()) + "\n";
    for (const Eigen::Vector3d& p : hull.points) {
      text += std::to_string(p.x()) + "," + std::to_string(p.y()) + "," + std::to_string(p.z()) + "\n";
    }
  }
  for (int i = 0; i < far; ++i) {
    const int x = 300 + 5 * (i % 100), y = -250 + 5 * (i / 100);
    text += "HULL 8\n";
    for (int corner = 0; corner < 8; ++corner) {
      text += std::to_string(x + (corner & 1)) + "," + std::to_string(y + ((corner >> 1) & 1)) +
              "," + std::to_string(2 * ((corner >> 2) & 1)) + "\n";
    }
  }
  return text;
}

constexpr const char* kSwingPath = "2\n1\n2.,3.\n0.,3.\n0.,3.\n0.,3.\n1\n0.,3.\n0.,3.\n0.,3.\n0.,3.\n";

void BM_VerifyAmongFarObstacles(benchmark::State& state) {
  const grpvss::RobotModel robot = grpvss::io::read_robot_file(kIbm7545Data + "robot.txt");
  const std::string text = environment_text(static_cast<int>(state.range(0)));
  const grpvss::PathProgram program = grpvss::io::parse_path_file(kSwingPath, "swing.txt", robot);
  const auto kinematics = grpvss::motion::make_kinematics_access(
      robot, grpvss::motion::select_ik({}, robot, "robot.txt"));
  grpvss::certify::SetupRequest request;
  request.tolerance = 0.5;
  const grpvss::certify::VerificationSetup setup = grpvss::certify::resolve_setup(request);
  int built = 0;
  grpvss::certify::VerificationRun last;
  for (auto _ : state) {
    const grpvss::Environment environment = grpvss::io::parse_environment_file(text, "far.txt");
    const grpvss::certify::RobotCell cell(robot, environment, setup.cell);
    last = grpvss::certify::verify(cell, program, kinematics, setup.run);
    built = cell.obstacles().built_count();
    benchmark::DoNotOptimize(last);
  }
  state.counters["built"] = built;
  state.counters["steps"] = static_cast<double>(last.result.steps.size());
  state.counters["verdict"] = static_cast<double>(static_cast<int>(last.result.verdict));
}
BENCHMARK(BM_VerifyAmongFarObstacles)
    ->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_EagerObstacleHulls(benchmark::State& state) {
  const grpvss::Environment environment = grpvss::io::parse_environment_file(
      environment_text(static_cast<int>(state.range(0))), "far.txt");
  for (auto _ : state) {
    for (const grpvss::HullPoints& obstacle : environment.obstacles) {
      const auto vertices = grpvss::geometry::ConvexPolytope::from_points(obstacle.points).vertices();
      benchmark::DoNotOptimize(grpvss::geometry::ConvexPolytope::from_points(vertices));
      benchmark::DoNotOptimize(grpvss::geometry::certified_sphere(vertices));
    }
  }
}
BENCHMARK(BM_EagerObstacleHulls)
    ->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace

// Planning cost of the motion stage on the thesis's output-sample path (IBM 7545).
#include <string>

#include <benchmark/benchmark.h>

#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/trajectory.hpp"
#include "support/data_paths.hpp"

namespace {

using grpvss::test::kIbm7545Data;

void BM_PlanOutputSamplePath(benchmark::State& state) {
  const grpvss::RobotModel robot = grpvss::io::read_robot_file(kIbm7545Data + "robot.txt");
  const grpvss::PathProgram program =
      grpvss::io::read_path_file(kIbm7545Data + "path-output-sample.txt", robot);
  const auto access = grpvss::motion::make_kinematics_access(
      robot, grpvss::motion::select_ik({}, robot, "robot.txt"));
  grpvss::motion::MotionModel options;
  options.cp_spacing = 0.5;
  for (auto _ : state) {
    auto trajectory = grpvss::motion::Trajectory::plan(robot, program, access, options);
    benchmark::DoNotOptimize(trajectory);
  }
}
BENCHMARK(BM_PlanOutputSamplePath);

void BM_TrapezoidEvaluation(benchmark::State& state) {
  const auto profile = grpvss::motion::TrapezoidProfile::plan(0.0, 1.0, 0.05, 0.035, 0.031);
  double t = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(profile.at(t));
    t += 1e-3;
    if (t > profile.duration()) t = 0.0;
  }
}
BENCHMARK(BM_TrapezoidEvaluation);

}  // namespace

// Cost of the planner-trajectory stage: reading, the variation bound a certified step needs
// (rounded and exact), enclosures, and the exact limit check.
#include <string>

#include <benchmark/benchmark.h>

#include "grpvss/io/trajectory_file.hpp"
#include "grpvss/motion/exact_joint_variation.hpp"
#include "grpvss/motion/joint_limit_check.hpp"
#include "grpvss/motion/joint_trajectory_motion.hpp"

namespace {

using grpvss::motion::JointTrajectoryMotion;

JointTrajectoryMotion overshoot_motion() {
  return JointTrajectoryMotion(grpvss::io::read_trajectory_file(
      std::string(GRPVSS_SOURCE_DIR) + "/data/trajectories/overshoot.json"));
}

/// A 6-joint CSV with velocities and `rows` waypoints 0.01 s apart (a dense planner output).
std::string dense_csv(int rows) {
  std::string text = "time,j1,j2,j3,j4,j5,j6,j1.vel,j2.vel,j3.vel,j4.vel,j5.vel,j6.vel\n";
  for (int k = 0; k < rows; ++k) {
    text += std::to_string(0.01 * k);
    for (int j = 0; j < 12; ++j) text += "," + std::to_string(0.001 * ((k * (j + 3)) % 997));
    text += "\n";
  }
  return text;
}

// One certified step inside the overshoot piece (all six joints, the elbow not monotone).
void BM_VariationBoundOfAStep(benchmark::State& state) {
  const JointTrajectoryMotion motion = overshoot_motion();
  for (auto _ : state) benchmark::DoNotOptimize(motion.variation_bound(1.6, 1.9));
}
BENCHMARK(BM_VariationBoundOfAStep);

void BM_VariationBoundFromSamplesOfAStep(benchmark::State& state) {
  const JointTrajectoryMotion motion = overshoot_motion();
  for (auto _ : state) benchmark::DoNotOptimize(motion.variation_bound_from_samples(1.6, 1.9));
}
BENCHMARK(BM_VariationBoundFromSamplesOfAStep);

void BM_ExactVariationBoundOfAStep(benchmark::State& state) {
  const JointTrajectoryMotion motion = overshoot_motion();
  for (auto _ : state) benchmark::DoNotOptimize(grpvss::motion::exact_variation_bound(motion, 1.6, 1.9));
}
BENCHMARK(BM_ExactVariationBoundOfAStep);

void BM_QAt(benchmark::State& state) {
  const JointTrajectoryMotion motion = overshoot_motion();
  double t = 0.5;
  for (auto _ : state) {
    benchmark::DoNotOptimize(motion.q_at(t));
    t = t < 2.4 ? t + 0.0137 : 0.5;
  }
}
BENCHMARK(BM_QAt);

void BM_ReadDenseCsv(benchmark::State& state) {
  const std::string text = dense_csv(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(grpvss::io::parse_trajectory_csv(text, "dense.csv"));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_ReadDenseCsv)->Arg(1000);

// The exact limit check of a dense 6-joint trajectory (per piece and joint: Q(sqrt D) arithmetic).
void BM_LimitCheckOfDenseTrajectory(benchmark::State& state) {
  const JointTrajectoryMotion motion(grpvss::io::parse_trajectory_csv(dense_csv(static_cast<int>(state.range(0))), "dense.csv"));
  const grpvss::motion::JointLimits limits{Eigen::VectorXd::Constant(6, -10), Eigen::VectorXd::Constant(6, 10),
                                           Eigen::VectorXd::Constant(6, 1e6)};
  for (auto _ : state) benchmark::DoNotOptimize(grpvss::motion::first_limit_violation(motion, limits));
  state.SetItemsProcessed(state.iterations() * motion.piece_count());
}
BENCHMARK(BM_LimitCheckOfDenseTrajectory)->Arg(1000);

}  // namespace

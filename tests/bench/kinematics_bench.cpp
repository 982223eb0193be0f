// Forward kinematics, hull placement and IK timings (Google Benchmark; no assertions).
#include <random>

#include <benchmark/benchmark.h>

#include "grpvss/io/robot_file.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/ibm7545_ik.hpp"
#include "grpvss/kinematics/numeric_ik.hpp"

namespace {

using namespace grpvss;
using namespace grpvss::kinematics;

RobotModel load(const char* relative) {
  return io::read_robot_file(std::string(GRPVSS_SOURCE_DIR) + "/" + relative);
}

Eigen::VectorXd middle(const RobotModel& model) {
  Eigen::VectorXd q(model.joint_count());
  for (int i = 0; i < model.joint_count(); ++i) {
    const Joint& joint = model.joints[static_cast<std::size_t>(i)];
    q[i] = 0.3 * joint.minimum + 0.7 * joint.maximum;
  }
  return q;
}

void BM_ForwardKinematicsAndHullPoints(benchmark::State& state, const char* file) {
  const RobotModel model = load(file);
  const KinematicChain chain = make_chain(model);
  Workspace ws(model);
  const Eigen::VectorXd q = middle(model);
  for (auto _ : state) {
    forward_kinematics(chain, q, ws);
    place_hull_points(model, ws);
    benchmark::DoNotOptimize(ws.hull_points_W.back().back().back());
  }
}
BENCHMARK_CAPTURE(BM_ForwardKinematicsAndHullPoints, ibm7545, "data/ibm7545/robot.txt");
BENCHMARK_CAPTURE(BM_ForwardKinematicsAndHullPoints, puma560, "data/puma560/robot.txt");

void BM_Ibm7545ClosedFormIk(benchmark::State& state) {
  const RobotModel model = load("data/ibm7545/robot.txt");
  const auto ik = make_ibm7545_ik(model);
  const Eigen::VectorXd q = middle(model);
  const Eigen::Isometry3d target = end_effector_pose(make_chain(model), q);
  for (auto _ : state) benchmark::DoNotOptimize(ik->solve(target, q));
}
BENCHMARK(BM_Ibm7545ClosedFormIk);

void BM_NumericIk(benchmark::State& state, const char* file, bool exhaustive) {
  const RobotModel model = load(file);
  NumericIkOptions options;
  options.exhaustive = exhaustive;
  const auto ik = make_numeric_ik(model, options);
  const Eigen::VectorXd q = middle(model);
  Eigen::VectorXd q_near = q;
  q_near.array() += 0.05;  // a nearby start, as in CP tracking
  const Eigen::Isometry3d target = end_effector_pose(make_chain(model), q);
  for (auto _ : state) benchmark::DoNotOptimize(ik->solve(target, q_near));
}
BENCHMARK_CAPTURE(BM_NumericIk, puma560_exhaustive, "data/puma560/robot.txt", true)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_NumericIk, puma560_first, "data/puma560/robot.txt", false)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

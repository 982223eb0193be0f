// Closed-form OPW and UR IK against the numeric solver on the same robots (Google Benchmark;
// no assertions). One target per robot: FK of a configuration inside the limits; q_near a
// little away from it, as in CP tracking.
#include <benchmark/benchmark.h>

#include "grpvss/io/robot_file.hpp"
#include "grpvss/kinematics/analytic_ik.hpp"
#include "grpvss/kinematics/family_recognition.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/numeric_ik.hpp"
#include "support/industrial_robots.hpp"

namespace {

using namespace grpvss;
using namespace grpvss::kinematics;

Eigen::VectorXd inside(const KinematicChain& chain) {
  Eigen::VectorXd q(chain.joint_count());
  for (int i = 0; i < chain.joint_count(); ++i) {
    const ChainJoint& joint = chain.joints[static_cast<std::size_t>(i)];
    q[i] = 0.3 * joint.minimum + 0.7 * joint.maximum;
  }
  return q;
}

RobotModel puma560() {
  return io::read_robot_file(std::string(GRPVSS_SOURCE_DIR) + "/data/puma560/robot.txt");
}

AnalyticIk analytic(const KinematicChain& chain) {
  if (auto opw = recognise_opw(chain).model) return AnalyticIk(chain, *opw);
  return AnalyticIk(chain, *recognise_ur(chain).model);
}

void run_solve(benchmark::State& state, const InverseKinematics& ik, const KinematicChain& chain) {
  const Eigen::VectorXd q = inside(chain);
  const Eigen::Isometry3d target = end_effector_pose(chain, q);
  const Eigen::VectorXd q_near = q.array() + 0.05;
  for (auto _ : state) benchmark::DoNotOptimize(ik.solve(target, q_near));
}

void BM_AnalyticSolve(benchmark::State& state, int robot) {
  const KinematicChain chain = robot == 0   ? make_chain(puma560())
                               : robot == 1 ? test::kr6_r700_chain()
                               : robot == 2 ? make_chain(test::ur5e_dh_model())
                                            : test::ur5e_chain_from_urdf();
  run_solve(state, analytic(chain), chain);
}
BENCHMARK_CAPTURE(BM_AnalyticSolve, opw_puma560, 0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_AnalyticSolve, opw_kr6_r700, 1)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_AnalyticSolve, ur_ur5e_dh, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_AnalyticSolve, ur_ur5e_urdf_refined, 3)->Unit(benchmark::kMicrosecond);

void BM_AnalyticAllSolutions(benchmark::State& state, int robot) {
  const KinematicChain chain = robot == 0 ? test::irb2400_chain() : make_chain(test::ur5e_dh_model());
  const AnalyticIk ik = analytic(chain);
  const Eigen::Isometry3d target = end_effector_pose(chain, inside(chain));
  for (auto _ : state) benchmark::DoNotOptimize(ik.solutions(target));
}
BENCHMARK_CAPTURE(BM_AnalyticAllSolutions, opw_irb2400, 0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_AnalyticAllSolutions, ur_ur5e_dh, 1)->Unit(benchmark::kMicrosecond);

void BM_NumericSolveSameRobot(benchmark::State& state, int robot, bool exhaustive) {
  const RobotModel model = robot == 0 ? puma560() : test::ur5e_dh_model();
  NumericIkOptions options;
  options.exhaustive = exhaustive;
  run_solve(state, *make_numeric_ik(model, options), make_chain(model));
}
BENCHMARK_CAPTURE(BM_NumericSolveSameRobot, puma560_first, 0, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_NumericSolveSameRobot, puma560_exhaustive, 0, true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_NumericSolveSameRobot, ur5e_dh_first, 1, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_NumericSolveSameRobot, ur5e_dh_exhaustive, 1, true)->Unit(benchmark::kMicrosecond);

void BM_RecogniseFamily(benchmark::State& state) {
  const KinematicChain chain = test::ur5e_chain_from_urdf();
  for (auto _ : state) benchmark::DoNotOptimize(recognise_ur(chain));
}
BENCHMARK(BM_RecogniseFamily)->Unit(benchmark::kMicrosecond);

}  // namespace

namespace {

void BM_ModelInverse(benchmark::State& state, int family) {
  const OpwParameters opw{0.025, -0.035, 0.0, 0.400, 0.315, 0.365, 0.080};
  const UrParameters ur{0.1625, -0.425, -0.3922, 0.1333, 0.0997, 0.0996};
  const ModelAngles theta{0.3, 0.4, 0.5, 0.6, 0.7, 0.8};
  const Eigen::Isometry3d X_BF = family == 0 ? opw_forward(opw, theta) : ur_forward(ur, theta);
  for (auto _ : state) {
    if (family == 0) benchmark::DoNotOptimize(opw_inverse(opw, X_BF));
    else benchmark::DoNotOptimize(ur_inverse(ur, X_BF));
  }
}
BENCHMARK_CAPTURE(BM_ModelInverse, opw_all_8_branches, 0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModelInverse, ur_all_8_branches, 1)->Unit(benchmark::kMicrosecond);

}  // namespace

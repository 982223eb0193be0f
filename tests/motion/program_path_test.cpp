// motion::resolve_program (docs/robot-programs.md#verifying-a-program) on real cells: a Cartesian
// target built from FK(q) through arbitrary base, work-object and tool frames resolves to q;
// every closed-form solution of a pose comes back when its own KUKA Status/Turn or ABB confdata
// is named; joint targets outside a limit, of the wrong size, and refused motion kinds throw
// InputError naming the motion's file and line.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/cell/model_inputs.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/kinematics/analytic_ik.hpp"
#include "grpvss/kinematics/automatic_ik.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/kinematics/vendor_configuration.hpp"
#include "grpvss/motion/program_path.hpp"

namespace grpvss::motion {
namespace {

const std::string kSource = GRPVSS_SOURCE_DIR;

cell::ModelInputs load(const std::string& cell_file) {
  cell::ModelSources sources;
  sources.cell_file = kSource + cell_file;
  return cell::load_model_inputs(sources);
}

Eigen::Isometry3d pose(const Eigen::Vector3d& p, double angle, const Eigen::Vector3d& axis) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  X.translation() = p;
  return X;
}

ProgramMotion cartesian_motion(const Eigen::Isometry3d& X_BT, ArmConfiguration configuration) {
  ProgramMotion motion;
  motion.file = "p.src";
  motion.line = 7;
  CartesianTarget target;
  target.p_BT = X_BT.translation();
  target.R_BT = Eigen::Quaterniond(X_BT.linear());
  target.configuration = std::move(configuration);
  motion.target = target;
  return motion;
}

Eigen::VectorXd home_of(const RobotModel& robot) {
  Eigen::VectorXd q(robot.joint_count());
  for (int j = 0; j < robot.joint_count(); ++j) q[j] = robot.joints[static_cast<std::size_t>(j)].home;
  return q;
}

TEST(ProgramPath, APoseThroughBaseWorkObjectAndToolResolvesToTheJointsItCameFrom) {
  const cell::ModelInputs model = load("/tests/data/cells/ur5e-post-no-self.yaml");
  const auto ik = kinematics::make_automatic_ik(model.robot);
  const kinematics::KinematicChain chain = kinematics::make_chain(model.robot);
  const ProgramFrames frames{pose({0.1, -0.2, 0.3}, 0.4, {1, 2, 3}), pose({0, 0, 0.05}, 0.3, {0, 1, 1})};
  const Eigen::Isometry3d X_RB = pose({0.5, 0.1, -0.1}, 1.2, {0, 0, 1});
  const Eigen::Isometry3d X_FT = pose({0.01, 0.02, 0.15}, 0.7, {1, 0, 0});
  for (const Eigen::VectorXd& q : {Eigen::VectorXd((Eigen::VectorXd(6) << -0.6, -1.4, 1.5, -1.2, -1.57, 0.2).finished()),
                                   Eigen::VectorXd((Eigen::VectorXd(6) << 2.0, -0.7, -1.9, 0.4, 1.1, -2.5).finished())}) {
    // The robot model's end effector E is where X_FE puts it; the program's target is the TCP
    // in B: X_BT = X_RB^-1 X_WR^-1 X_WE X_FE^-1 X_FT.
    const Eigen::Isometry3d X_WE = kinematics::end_effector_pose(chain, q);
    const Eigen::Isometry3d X_BT =
        X_RB.inverse() * frames.X_WR.inverse() * X_WE * frames.X_FE.inverse() * X_FT;
    RobotProgram program;
    ProgramMotion motion = cartesian_motion(X_BT, UrNearestJoints{q});
    motion.X_RB = X_RB;
    motion.X_FT = X_FT;
    program.motions.push_back(motion);
    const ProgramPath path = resolve_program(program, model.robot, frames, *ik, home_of(model.robot));
    ASSERT_EQ(path.motions.size(), 1u);
    EXPECT_TRUE(path.motions[0].cartesian);
    EXPECT_LT((path.motions[0].q - q).norm(), 1e-9) << path.motions[0].q.transpose();
    const auto& segment = std::get<PtpJointSegment>(path.path.segments[0].spec);
    EXPECT_EQ(segment.target, path.motions[0].q);
    EXPECT_EQ(segment.velocity, Eigen::VectorXd::Constant(6, kDefaultProgramJointSpeed));
    EXPECT_EQ(path.path.segments[0].source_line, 7);
  }
}

TEST(ProgramPath, EverySolutionComesBackWhenItsOwnStatusTurnOrConfdataIsNamed) {
  const cell::ModelInputs model = load("/data/sixaxis/cell.yaml");
  const auto ik = kinematics::make_automatic_ik(model.robot);
  const auto* analytic = dynamic_cast<const kinematics::AnalyticIk*>(ik.get());
  ASSERT_NE(analytic, nullptr);
  ASSERT_NE(analytic->opw(), nullptr);
  const ProgramFrames frames{model.X_WR, model.X_FE};
  const Eigen::VectorXd q0 = (Eigen::VectorXd(6) << 0.3, -0.4, 0.5, 0.6, -0.7, 0.2).finished();
  const Eigen::Isometry3d X_WE = kinematics::end_effector_pose(analytic->chain(), q0);
  const Eigen::Isometry3d X_BT = frames.X_WR.inverse() * X_WE;
  const auto solutions = analytic->solutions(X_WE);
  ASSERT_GE(solutions.size(), 4u);
  int distinct = 0;
  for (const kinematics::ConfiguredSolution& solution : solutions) {
    const kinematics::KukaStatusTurn st = kinematics::kuka_status_turn(*analytic->opw(), solution.q);
    const kinematics::AbbConfdata cf = kinematics::abb_confdata(*analytic->opw(), solution.q);
    for (const ArmConfiguration& configuration :
         {ArmConfiguration(KrlStatusTurn{st.status, st.turn}),
          ArmConfiguration(RapidConfData{cf.cf1, cf.cf4, cf.cf6, cf.cfx})}) {
      RobotProgram program;
      program.motions.push_back(cartesian_motion(X_BT, configuration));
      const ProgramPath path =
          resolve_program(program, model.robot, frames, *ik, Eigen::VectorXd::Zero(6));
      // The named configuration identifies this solution among all of them.
      EXPECT_LT((path.motions[0].q - solution.q).norm(), 1e-9) << solution.q.transpose();
      // Independently of the selection: the joints put E at the target.
      const Eigen::Isometry3d reached = kinematics::end_effector_pose(analytic->chain(), path.motions[0].q);
      EXPECT_LT((reached.matrix() - X_WE.matrix()).norm(), 1e-9);
    }
    distinct += (solution.q - q0).norm() > 1e-6 ? 1 : 0;
  }
  EXPECT_EQ(distinct, static_cast<int>(solutions.size()) - 1);  // q0 is one of them
}

TEST(ProgramPath, JointTargetsAreCheckedAgainstTheRobot) {
  const cell::ModelInputs model = load("/tests/data/cells/ur5e-post-no-self.yaml");
  const auto ik = kinematics::make_automatic_ik(model.robot);
  RobotProgram program;
  ProgramMotion motion;
  motion.file = "p.script";
  motion.line = 3;
  motion.target = JointTarget{(Eigen::VectorXd(6) << 0, -1.5, 1.5, 0, 7.0, 0).finished()};
  program.motions.push_back(motion);
  try {
    resolve_program(program, model.robot, {}, *ik, home_of(model.robot));
    FAIL() << "a joint beyond its limit was accepted";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "p.script:3: expected joint 5 (wrist_2_joint) within its limits "
                               "[-360, 360] deg, found 401.07 deg");
  }
  program.motions[0].target = JointTarget{Eigen::VectorXd::Zero(5)};
  EXPECT_THROW(resolve_program(program, model.robot, {}, *ik, home_of(model.robot)), InputError);
  program.motions.clear();
  EXPECT_THROW(resolve_program(program, model.robot, {}, *ik, home_of(model.robot)), InputError);
}

TEST(ProgramPath, LinearCircularAndBlendedMotionsThrowWithTheirLine) {
  const cell::ModelInputs model = load("/tests/data/cells/ur5e-post-no-self.yaml");
  const auto ik = kinematics::make_automatic_ik(model.robot);
  ProgramMotion motion;
  motion.file = "p.script";
  motion.line = 12;
  motion.target = JointTarget{home_of(model.robot)};
  for (int variant = 0; variant < 3; ++variant) {
    RobotProgram program;
    ProgramMotion refused = motion;
    if (variant == 0) refused.kind = MotionKind::kLinear;
    if (variant == 1) refused.kind = MotionKind::kCircular;
    if (variant == 2) refused.blend = MotionBlend{BlendKind::kDistance, 0.02};
    program.motions.push_back(refused);
    try {
      resolve_program(program, model.robot, {}, *ik, home_of(model.robot));
      FAIL() << "variant " << variant << " was accepted";
    } catch (const InputError& error) {
      EXPECT_EQ(std::string(error.what()).rfind("p.script:12: expected a joint motion (movej)", 0), 0u)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace grpvss::motion

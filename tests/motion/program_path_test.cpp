// motion::resolve_program (docs/robot-programs.md#verifying-a-program) on real cells: a Cartesian
// target built from FK(q) through arbitrary base, work-object and tool frames resolves to q;
// every closed-form solution of a pose comes back when its own KUKA Status/Turn or ABB confdata
// is named; a linear motion is a CP line of E to its target re-stated for E, with its own speed,
// ending in the joints followed along it (a turning line under another tool, or one whose target
// names other joints, throws); joint targets outside a limit, of the wrong size, and refused motion kinds throw
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
#include "grpvss/motion/kinematics_access.hpp"
#include "support/data_paths.hpp"


namespace grpvss::motion {
namespace {

using grpvss::test::kSourceDir;

cell::ModelInputs load(const std::string& cell_file) {
  cell::ModelSources sources;
  sources.cell_file = kSourceDir + cell_file;
  return cell::load_model_inputs(sources);
}

Eigen::Isometry3d pose_about_axis(const Eigen::Vector3d& p, double angle, const Eigen::Vector3d& axis) {
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
  const ProgramFrames frames{pose_about_axis({0.1, -0.2, 0.3}, 0.4, {1, 2, 3}), pose_about_axis({0, 0, 0.05}, 0.3, {0, 1, 1})};
  const Eigen::Isometry3d X_RB = pose_about_axis({0.5, 0.1, -0.1}, 1.2, {0, 0, 1});
  const Eigen::Isometry3d X_FT = pose_about_axis({0.01, 0.02, 0.15}, 0.7, {1, 0, 0});
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

TEST(ProgramPath, CircularAndBlendedMotionsThrowWithTheirLine) {
  const cell::ModelInputs model = load("/tests/data/cells/ur5e-post-no-self.yaml");
  const auto ik = kinematics::make_automatic_ik(model.robot);
  ProgramMotion motion;
  motion.file = "p.script";
  motion.line = 12;
  motion.target = JointTarget{home_of(model.robot)};
  for (int variant = 1; variant < 3; ++variant) {
    RobotProgram program;
    ProgramMotion refused = motion;
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

ProgramMotion linear_motion(ProgramTarget target, int line) {
  ProgramMotion motion;
  motion.kind = MotionKind::kLinear;
  motion.file = "p.script";
  motion.line = line;
  motion.target = std::move(target);
  return motion;
}

ProgramMotion joint_motion(const Eigen::VectorXd& q) {
  ProgramMotion motion;
  motion.file = "p.script";
  motion.line = 2;
  motion.target = JointTarget{q};
  return motion;
}

// The orientation change of a CP line target, applied to the start (Eq. 4-18).
Eigen::Matrix3d line_end_rotation(const WorldTarget& target, const Eigen::Matrix3d& R_start) {
  return Eigen::AngleAxisd(target.angle, target.axis_W.normalized()).toRotationMatrix() * R_start;
}

const Eigen::VectorXd kLineStart = (Eigen::VectorXd(6) << -0.5, -1.4, 1.5, -1.2, -1.57, 0.2).finished();
const Eigen::VectorXd kLineEnd = (Eigen::VectorXd(6) << -0.3, -1.3, 1.2, -1.1, -1.4, 0.5).finished();

TEST(ProgramPath, ALinearMoveIsACpLineOfEWithItsOwnSpeedEndingInTheJointsFollowedAlongIt) {
  const cell::ModelInputs model = load("/tests/data/cells/ur5e-post-no-self.yaml");
  const auto ik = kinematics::make_automatic_ik(model.robot);
  const kinematics::KinematicChain chain = kinematics::make_chain(model.robot);
  // The program's TCP is the cell's E (X_FT = X_FE): the TCP line is E's line.
  const ProgramFrames frames{pose_about_axis({0.1, -0.2, 0.3}, 0.4, {1, 2, 3}), pose_about_axis({0, 0, 0.05}, 0.3, {0, 1, 1})};
  const Eigen::Isometry3d X_RB = pose_about_axis({0.5, 0.1, -0.1}, 1.2, {0, 0, 1});
  const Eigen::Isometry3d X_WE_start = kinematics::end_effector_pose(chain, kLineStart);
  const Eigen::Isometry3d X_WE_end = kinematics::end_effector_pose(chain, kLineEnd);
  const Eigen::Isometry3d X_BT = X_RB.inverse() * frames.X_WR.inverse() * X_WE_end * frames.X_FE.inverse() * frames.X_FE;
  ProgramMotion line = linear_motion(CartesianTarget{X_BT.translation(), Eigen::Quaterniond(X_BT.linear()), {}}, 5);
  line.X_RB = X_RB;
  line.X_FT = frames.X_FE;
  line.speed.tcp_speed = 0.3;
  RobotProgram program;
  program.motions = {joint_motion(kLineStart), line};
  const ProgramPath path = resolve_program(program, model.robot, frames, *ik, home_of(model.robot));
  ASSERT_EQ(path.path.segments.size(), 2u);
  const auto* cp = std::get_if<CpLineSegment>(&path.path.segments[1].spec);
  ASSERT_NE(cp, nullptr);
  EXPECT_EQ(path.path.segments[1].source_line, 5);
  EXPECT_EQ(cp->speed, 0.3);
  EXPECT_LT((cp->target.position_W - X_WE_end.translation()).norm(), 1e-12);
  EXPECT_LT((line_end_rotation(cp->target, X_WE_start.linear()) - X_WE_end.linear()).norm(), 1e-12);
  // Followed from kLineStart, the line ends in the joints its end pose was computed from.
  EXPECT_TRUE(path.motions[1].linear);
  EXPECT_LT((path.motions[1].q - kLineEnd).cwiseAbs().maxCoeff(), 1e-9) << path.motions[1].q.transpose();
  EXPECT_EQ(describe_program_motion(path, "p.script"),
            "program p.script (URScript), synchronized PTP and CP lines, 2 motions (1 joint target, "
            "0 poses by IK, 1 straight TCP line), exact stops");
}

TEST(ProgramPath, AMovelToJointsEndsAtTheirPoseAndKeptOrientationUnderAnotherToolIsTranslated) {
  const cell::ModelInputs model = load("/tests/data/cells/ur5e-post-no-self.yaml");
  const auto ik = kinematics::make_automatic_ik(model.robot);
  const kinematics::KinematicChain chain = kinematics::make_chain(model.robot);
  const ProgramFrames frames{model.X_WR, Eigen::Isometry3d::Identity()};
  // movel(q): the pose q reaches, as UR does; a tool 100 mm along z other than E (identity).
  ProgramMotion to_joints = linear_motion(JointTarget{kLineEnd}, 4);
  to_joints.X_FT = pose_about_axis({0, 0, 0.1}, 0.0, {0, 0, 1});
  // Then up by 50 mm keeping the orientation: E moves on the TCP's line translated.
  const Eigen::Isometry3d X_WE_end = kinematics::end_effector_pose(chain, kLineEnd);
  Eigen::Isometry3d X_RT_up = frames.X_WR.inverse() * X_WE_end * to_joints.X_FT;
  X_RT_up.translation().z() += 0.05;
  ProgramMotion up = linear_motion(CartesianTarget{X_RT_up.translation(), Eigen::Quaterniond(X_RT_up.linear()), {}}, 5);
  up.X_FT = to_joints.X_FT;
  RobotProgram program;
  program.motions = {joint_motion(kLineStart), to_joints, up};
  // A turning line under another tool is refused: its E path is no straight line.
  try {
    resolve_program(program, model.robot, frames, *ik, home_of(model.robot));
    FAIL() << "a turning line under another tool was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(
                  "p.script:4: expected a movel whose TCP is the cell's end effector E, or one that "
                  "keeps the tool's orientation: a straight TCP line that turns is no straight line "
                  "of E under another tool; set the cell's `tool` to the program's tool, found tool "
                  "with its TCP at (0, 0, 100) mm in the flange, the cell's E at (0, 0, 0) mm, and "
                  "the orientation turning by ",
                  0),
              0u)
        << error.what();
  }
  program.motions[1].X_FT = Eigen::Isometry3d::Identity();  // TCP = E: the turning line is E's
  const ProgramPath path = resolve_program(program, model.robot, frames, *ik, home_of(model.robot));
  ASSERT_EQ(path.path.segments.size(), 3u);
  const auto& to_end = std::get<CpLineSegment>(path.path.segments[1].spec);
  EXPECT_LT((to_end.target.position_W - X_WE_end.translation()).norm(), 1e-12);
  EXPECT_FALSE(to_end.speed.has_value());  // no v given: the run's CP speed
  EXPECT_LT((path.motions[1].q - kLineEnd).cwiseAbs().maxCoeff(), 1e-9);
  const auto& raise = std::get<CpLineSegment>(path.path.segments[2].spec);
  EXPECT_LT(std::abs(raise.target.angle), 1e-15);  // a kept orientation: no turn but rounding
  EXPECT_LT((raise.target.position_W - (X_WE_end.translation() + Eigen::Vector3d(0, 0, 0.05))).norm(), 1e-12);
  const Eigen::Isometry3d reached = kinematics::end_effector_pose(chain, path.motions[2].q);
  EXPECT_LT((reached.translation() - raise.target.position_W).norm(), 1e-9);
  EXPECT_LT((reached.linear() - X_WE_end.linear()).norm(), 1e-9);
}

TEST(ProgramPath, ALineEndingInOtherJointsThanItsTargetNamesThrows) {
  const cell::ModelInputs model = load("/data/sixaxis/cell.yaml");
  const auto ik = kinematics::make_automatic_ik(model.robot);
  const auto* analytic = dynamic_cast<const kinematics::AnalyticIk*>(ik.get());
  ASSERT_NE(analytic, nullptr);
  const Eigen::VectorXd q0 = (Eigen::VectorXd(6) << 0.3, -0.4, 0.5, 0.6, -0.7, 0.2).finished();
  const Eigen::VectorXd q_near = (Eigen::VectorXd(6) << 0.25, -0.35, 0.45, 0.55, -0.65, 0.15).finished();
  const Eigen::Isometry3d X_WE = kinematics::end_effector_pose(analytic->chain(), q0);
  // movel to joints of another solution of the same pose: the line from q_near reaches q0.
  for (const kinematics::ConfiguredSolution& solution : analytic->solutions(X_WE)) {
    if ((solution.q - q0).norm() < 1e-6) continue;
    if (first_joint_outside_limits(model.robot, solution.q) >= 0) continue;
    RobotProgram program;
    program.motions = {joint_motion(q_near), linear_motion(JointTarget{solution.q}, 9)};
    try {
      resolve_program(program, model.robot, {model.X_WR, model.X_FE}, *ik, Eigen::VectorXd::Zero(6));
      FAIL() << "a line to other joints was accepted: " << solution.q.transpose();
    } catch (const InputError& error) {
      EXPECT_EQ(std::string(error.what()).rfind(
                    "p.script:9: expected the configuration the line's target names (its joints) "
                    "reached along the line from the previous target, found the line ends at joints "
                    "(17.19, -22.92, 28.65, 34.38, -40.11, 11.46) deg, the target names (",
                    0),
                0u)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace grpvss::motion

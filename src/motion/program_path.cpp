#include "grpvss/motion/program_path.hpp"

#include <cmath>
#include <optional>
#include <utility>
#include <variant>

#include <fmt/core.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/kinematics/analytic_ik.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/kinematics/solution_selection.hpp"
#include "grpvss/motion/cp_line.hpp"
#include "grpvss/motion/kinematics_access.hpp"

namespace grpvss::motion {
namespace {

constexpr double kPi = 3.14159265358979323846;

const char* joint_statement(ProgramLanguage language) {
  switch (language) {
    case ProgramLanguage::kUrScript: return "movej";
    case ProgramLanguage::kKrl: return "PTP";
    case ProgramLanguage::kRapid: return "MoveJ or MoveAbsJ";
  }
  return "a joint motion";
}

const char* linear_statement(ProgramLanguage language) {
  switch (language) {
    case ProgramLanguage::kUrScript: return "movel";
    case ProgramLanguage::kKrl: return "LIN";
    case ProgramLanguage::kRapid: return "MoveL";
  }
  return "a linear motion";
}

const char* circular_statement(ProgramLanguage language) {
  switch (language) {
    case ProgramLanguage::kUrScript: return "movec";
    case ProgramLanguage::kKrl: return "CIRC";
    case ProgramLanguage::kRapid: return "MoveC";
  }
  return "a circular motion";
}

// "blend radius r = 0.05 m", "C_DIS", "zone z10": how the program wrote the approximation.
std::string describe_blend(const MotionBlend& blend) {
  if (!blend.name.empty()) return "zone " + blend.name;
  if (blend.radius) return fmt::format("blend radius r = {:g} m", *blend.radius);
  return "an approximated (blended) end";
}

// Each refusal names the statement, what the verifier would need, and why it is not given.
void refuse_unmodelled(const ProgramMotion& motion, ProgramLanguage language) {
  const std::string expected = fmt::format(
      "a joint motion ({}) ending in an exact stop: the verifier models a program as synchronized "
      "PTP motions",
      joint_statement(language));
  if (motion.kind == MotionKind::kCircular) {
    throw InputError(motion.file, motion.line, expected,
                     fmt::format("{}: circular moves are not modelled", circular_statement(language)));
  }
  if (motion.blend.kind != BlendKind::kExactStop) {
    throw InputError(motion.file, motion.line, expected,
                     fmt::format("{}: the blended corner leaves the joint-space line and no bound "
                                 "on it is proven; use an exact stop (UR r=0, KUKA without "
                                 "C_PTP/C_DIS/C_VEL/C_ORI, ABB fine)",
                                 describe_blend(motion.blend)));
  }
}

std::string joint_label(const RobotModel& robot, int j) {
  const std::string& name = robot.joints[static_cast<std::size_t>(j)].name;
  return name.empty() ? fmt::format("joint {}", j + 1) : fmt::format("joint {} ({})", j + 1, name);
}

void check_joint_target(const ProgramMotion& motion, const RobotModel& robot,
                        const Eigen::VectorXd& q) {
  if (q.size() != robot.joint_count()) {
    throw InputError(motion.file, motion.line,
                     fmt::format("{} joint values (the robot's joints)", robot.joint_count()),
                     fmt::format("{}", q.size()));
  }
  const int j = first_joint_outside_limits(robot, q);
  if (j < 0) return;
  const Joint& joint = robot.joints[static_cast<std::size_t>(j)];
  const double degrees = 180.0 / kPi;
  throw InputError(motion.file, motion.line,
                   fmt::format("{} within its limits [{:.4g}, {:.4g}] deg", joint_label(robot, j),
                               joint.minimum * degrees, joint.maximum * degrees),
                   fmt::format("{:.6g} deg", q[j] * degrees));
}

const kinematics::AnalyticIk* opw_solver(const ProgramMotion& motion,
                                         const kinematics::InverseKinematics& ik,
                                         const char* data) {
  const auto* analytic = dynamic_cast<const kinematics::AnalyticIk*>(&ik);
  if (analytic == nullptr || analytic->opw() == nullptr) {
    throw InputError(motion.file, motion.line,
                     fmt::format("a robot with the OPW closed-form IK (--ik auto or opw): {} names "
                                 "a configuration only it resolves",
                                 data),
                     "IK " + ik.name());
  }
  return analytic;
}

// The solution the controller takes for X_WE, as the program's configuration selects it.
std::optional<Eigen::VectorXd> configured_solution(const ProgramMotion& motion,
                                                   const CartesianTarget& target,
                                                   const Eigen::Isometry3d& X_WE,
                                                   const kinematics::InverseKinematics& ik,
                                                   const Eigen::VectorXd& q_now) {
  if (const auto* st = std::get_if<KrlStatusTurn>(&target.configuration)) {
    if (st->status) {
      return kinematics::solution_with_status_turn(*opw_solver(motion, ik, "a KRL Status (S)"),
                                                   X_WE, *st->status, st->turn, q_now);
    }
  }
  if (const auto* conf = std::get_if<RapidConfData>(&target.configuration)) {
    const kinematics::AbbConfdata abb{conf->cf1, conf->cf4, conf->cf6, conf->cfx};
    return kinematics::solution_with_confdata(*opw_solver(motion, ik, "a RAPID confdata"), X_WE,
                                              abb, q_now);
  }
  Eigen::VectorXd q_near = q_now;
  if (const auto* near = std::get_if<UrNearestJoints>(&target.configuration)) {
    if (near->qnear.size() == q_now.size()) q_near = near->qnear;
  }
  kinematics::IkSolution solution = ik.solve(X_WE, q_near);
  if (solution.status != kinematics::IkStatus::kSolved) return std::nullopt;
  return std::move(solution.q);
}

std::string configuration_text(const ArmConfiguration& configuration) {
  if (const auto* st = std::get_if<KrlStatusTurn>(&configuration)) {
    return fmt::format("S {} T {}", st->status ? std::to_string(*st->status) : "unset",
                       st->turn ? std::to_string(*st->turn) : "unset");
  }
  if (const auto* conf = std::get_if<RapidConfData>(&configuration)) {
    return fmt::format("confdata [{},{},{},{}]", conf->cf1, conf->cf4, conf->cf6, conf->cfx);
  }
  return "the solution nearest the current joints";
}

Eigen::VectorXd resolve_pose(const ProgramMotion& motion, const CartesianTarget& target,
                             const ProgramFrames& frames, const kinematics::InverseKinematics& ik,
                             const Eigen::VectorXd& q_now) {
  const Eigen::Isometry3d X_WE =
      frames.X_WR * motion.X_RB * target.X_BT() * motion.X_FT.inverse() * frames.X_FE;
  std::optional<Eigen::VectorXd> q = configured_solution(motion, target, X_WE, ik, q_now);
  if (!q) {
    throw InputError(motion.file, motion.line,
                     fmt::format("a pose the robot reaches within its joint limits in {} ({})",
                                 configuration_text(target.configuration), ik.name()),
                     fmt::format("no solution for the flange at p_WF = ({:.4f}, {:.4f}, {:.4f}) m",
                                 (X_WE * frames.X_FE.inverse()).translation().x(),
                                 (X_WE * frames.X_FE.inverse()).translation().y(),
                                 (X_WE * frames.X_FE.inverse()).translation().z()));
  }
  return *q;
}

// Spacing (m) at which a program's line is followed from the previous joints to find the joints
// it ends in: the controller's continuous IK, as the planner's CP sampling follows it.
constexpr double kLineFollowSpacing = 1e-3;
// A program's TCP is the cell's E when their poses in the flange agree to this (m, and rad).
constexpr double kSameToolTolerance = 1e-9;

KinematicsAccess program_kinematics(const RobotModel& robot, const kinematics::InverseKinematics& ik) {
  KinematicsAccess access;
  access.forward = [chain = kinematics::make_chain(robot)](const Eigen::VectorXd& q) {
    return kinematics::end_effector_pose(chain, q);
  };
  access.inverse = [&ik](const Eigen::Isometry3d& X_WE,
                         const Eigen::VectorXd& q_near) -> std::optional<Eigen::VectorXd> {
    kinematics::IkSolution solution = ik.solve(X_WE, q_near);
    if (solution.status != kinematics::IkStatus::kSolved) return std::nullopt;
    return std::move(solution.q);
  };
  return access;
}

// The line's end as the cell's E: a pose re-stated through the program's frames, or (movel with
// joints, as UR does) the forward kinematics of its joints.
Eigen::Isometry3d line_end_X_WE(const ProgramMotion& motion, const ProgramFrames& frames,
                                const RobotModel& robot, const KinematicsAccess& kinematics) {
  if (const auto* joints = std::get_if<JointTarget>(&motion.target)) {
    check_joint_target(motion, robot, joints->q);
    return kinematics.forward(joints->q);
  }
  const auto& target = std::get<CartesianTarget>(motion.target);
  return frames.X_WR * motion.X_RB * target.X_BT() * motion.X_FT.inverse() * frames.X_FE;
}

std::string vector_text(const Eigen::Vector3d& v, double scale) {
  return fmt::format("({:.4g}, {:.4g}, {:.4g})", v.x() * scale, v.y() * scale, v.z() * scale);
}

// A straight TCP line is a straight line of E only when TCP = E or the orientation is kept
// (then E's line is the TCP's, translated).
void require_line_of_e(const ProgramMotion& motion, ProgramLanguage language,
                       const ProgramFrames& frames, double turn_angle) {
  const double tool_difference = (motion.X_FT.matrix() - frames.X_FE.matrix()).cwiseAbs().maxCoeff();
  if (tool_difference <= kSameToolTolerance || turn_angle <= kSameToolTolerance) return;
  const Eigen::Vector3d p_FT = motion.X_FT.translation();
  const Eigen::Vector3d p_FE = frames.X_FE.translation();
  throw InputError(
      motion.file, motion.line,
      fmt::format("a {} whose TCP is the cell's end effector E, or one that keeps the tool's "
                  "orientation: a straight TCP line that turns is no straight line of E under "
                  "another tool; set the cell's `tool` to the program's tool",
                  linear_statement(language)),
      fmt::format("tool {}with its TCP at {} mm in the flange, the cell's E at {} mm, and the "
                  "orientation turning by {:.4g} deg",
                  motion.tool_name.empty() ? "" : motion.tool_name + " ", vector_text(p_FT, 1e3),
                  vector_text(p_FE, 1e3), turn_angle * 180.0 / kPi));
}

// The CP line from X_WE_start to X_WE_end (Eq. 4-17/4-18: the turn applies to the start's
// orientation in the world frame, as the controller's slerp does).
WorldTarget line_target(const Eigen::Isometry3d& X_WE_start, const Eigen::Isometry3d& X_WE_end) {
  WorldTarget target;
  target.position_W = X_WE_end.translation();
  const Eigen::AngleAxisd turn(X_WE_end.linear() * X_WE_start.linear().transpose());
  if (turn.angle() > 0.0) {
    target.axis_W = turn.axis();
    target.angle = turn.angle();
  }
  return target;
}

std::string degrees_text(const Eigen::VectorXd& q) {
  std::string text;
  for (Eigen::Index j = 0; j < q.size(); ++j) text += fmt::format("{}{:.4g}", j ? ", " : "", q[j] * 180.0 / kPi);
  return "(" + text + ") deg";
}

// The configuration the line's target demands (KRL S/T, RAPID confdata, movel's joints) must be
// the one the line reaches from the previous target; the controller would stop otherwise.
void require_reached_configuration(const ProgramMotion& motion, const Eigen::Isometry3d& X_WE_end,
                                   const kinematics::InverseKinematics& ik,
                                   const Eigen::VectorXd& q_reached) {
  std::optional<Eigen::VectorXd> demanded;
  std::string named;
  if (const auto* joints = std::get_if<JointTarget>(&motion.target)) {
    demanded = joints->q;
    named = "its joints";
  } else {
    const auto& target = std::get<CartesianTarget>(motion.target);
    const auto* st = std::get_if<KrlStatusTurn>(&target.configuration);
    const bool configured = (st && st->status) || std::holds_alternative<RapidConfData>(target.configuration);
    if (!configured) return;
    demanded = configured_solution(motion, target, X_WE_end, ik, q_reached);
    named = configuration_text(target.configuration);
  }
  if (demanded && (*demanded - q_reached).cwiseAbs().maxCoeff() <= 1e-6) return;
  throw InputError(motion.file, motion.line,
                   fmt::format("the configuration the line's target names ({}) reached along the "
                               "line from the previous target",
                               named),
                   fmt::format("the line ends at joints {}{}", degrees_text(q_reached),
                               demanded ? ", the target names " + degrees_text(*demanded)
                                        : ", and the named configuration has no solution there"));
}

struct ResolvedLine {
  CpLineSegment segment;
  Eigen::VectorXd q_end;  // empty: the line cannot be followed (the planner reports why)
};

// A linear motion as a certified CP line of E, and the joints its end is reached in.
ResolvedLine resolve_line(const ProgramMotion& motion, ProgramLanguage language,
                          const ProgramFrames& frames, const RobotModel& robot,
                          const kinematics::InverseKinematics& ik, const Eigen::VectorXd& q_now) {
  const KinematicsAccess kinematics = program_kinematics(robot, ik);
  const Eigen::Isometry3d X_WE_start = kinematics.forward(q_now);
  const Eigen::Isometry3d X_WE_end = line_end_X_WE(motion, frames, robot, kinematics);
  ResolvedLine line;
  line.segment.target = line_target(X_WE_start, X_WE_end);
  line.segment.speed = motion.speed.tcp_speed;
  require_line_of_e(motion, language, frames, line.segment.target.angle);
  const CpSampling followed = sample_cp_line(robot, kinematics, CpLine(X_WE_start, line.segment.target),
                                             q_now, kLineFollowSpacing, 1);
  if (followed.error) return line;
  line.q_end = followed.samples.back().q;
  require_reached_configuration(motion, X_WE_end, ik, line.q_end);
  return line;
}

// Per-joint desired speeds: the program's joint speed (URScript movej v) or the default, scaled
// by a KRL $VEL_AXIS percentage where one is given.
Eigen::VectorXd joint_speeds(const ProgramMotion& motion, int joint_count) {
  const double speed = motion.speed.joint_speed.value_or(kDefaultProgramJointSpeed);
  Eigen::VectorXd velocity = Eigen::VectorXd::Constant(joint_count, speed);
  const auto& percent = motion.speed.joint_speed_percent;
  for (int j = 0; j < joint_count && j < static_cast<int>(percent.size()); ++j) {
    const auto& given = percent[static_cast<std::size_t>(j)];
    if (given && *given > 0.0) velocity[j] = speed * *given / 100.0;
  }
  return velocity;
}

std::string file_name_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

Eigen::Isometry3d controller_base_in_root(ProgramLanguage language) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  if (language == ProgramLanguage::kUrScript) {
    X.linear() = Eigen::AngleAxisd(kPi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  }
  return X;
}

const char* to_string(ProgramLanguage language) {
  switch (language) {
    case ProgramLanguage::kUrScript: return "URScript";
    case ProgramLanguage::kKrl: return "KUKA KRL";
    case ProgramLanguage::kRapid: return "ABB RAPID";
  }
  return "program";
}

ProgramPath resolve_program(const RobotProgram& program, const RobotModel& robot,
                            const ProgramFrames& frames, const kinematics::InverseKinematics& ik,
                            const Eigen::VectorXd& q_start) {
  if (program.motions.empty()) {
    throw InputError(program.files.empty() ? "--program" : program.files.front(), 0,
                     "a program with at least one motion statement", "none");
  }
  ProgramPath result;
  result.language = program.language;
  Eigen::VectorXd q_now = q_start;
  for (const ProgramMotion& motion : program.motions) {
    refuse_unmodelled(motion, program.language);
    ResolvedMotion resolved{motion.file, motion.line, false, false, {}};
    resolved.cartesian = std::holds_alternative<CartesianTarget>(motion.target);
    if (motion.kind == MotionKind::kLinear) {
      ResolvedLine line = resolve_line(motion, program.language, frames, robot, ik, q_now);
      resolved.linear = true;
      result.path.segments.push_back({line.segment, motion.line});
      // A line the robot cannot follow ends the run there (the planner's thesis error 3 / 4 / 5):
      // later motions are never reached, so they are not resolved.
      if (line.q_end.size() == 0) break;
      resolved.q = std::move(line.q_end);
    } else {
      resolved.q = resolved.cartesian ? resolve_pose(motion, std::get<CartesianTarget>(motion.target),
                                                     frames, ik, q_now)
                                      : std::get<JointTarget>(motion.target).q;
      check_joint_target(motion, robot, resolved.q);
      result.path.segments.push_back(
          {PtpJointSegment{resolved.q, joint_speeds(motion, robot.joint_count())}, motion.line});
    }
    q_now = resolved.q;
    result.motions.push_back(std::move(resolved));
  }
  return result;
}

std::string describe_program_motion(const ProgramPath& path, const std::string& file_label) {
  int poses = 0;
  int lines = 0;
  for (const ResolvedMotion& motion : path.motions) {
    lines += motion.linear ? 1 : 0;
    poses += motion.cartesian && !motion.linear ? 1 : 0;
  }
  const int count = static_cast<int>(path.motions.size());
  const int joints = count - poses - lines;
  const std::string line_text =
      lines == 0 ? "" : fmt::format(", {} straight TCP line{}", lines, lines == 1 ? "" : "s");
  return fmt::format("program {} ({}), synchronized PTP{}, {} motion{} ({} joint target{}, {} pose{} "
                     "by IK{}), exact stops",
                     file_label, to_string(path.language), lines == 0 ? "" : " and CP lines", count,
                     count == 1 ? "" : "s", joints, joints == 1 ? "" : "s", poses,
                     poses == 1 ? "" : "s", line_text);
}

std::string resolved_targets_text(const ProgramPath& path) {
  std::string text;
  for (const ResolvedMotion& motion : path.motions) {
    if (!text.empty()) text += "; ";
    text += fmt::format("{}:{}", file_name_of(motion.file), motion.line);
    for (Eigen::Index j = 0; j < motion.q.size(); ++j) text += fmt::format(" {:.17g}", motion.q[j]);
  }
  return text;
}

}  // namespace grpvss::motion

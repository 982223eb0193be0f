#pragma once
/// \file
/// \brief A robot program (URScript, KUKA KRL, ABB RAPID: model/robot_program.hpp) as the
/// motion its controller makes, for the verifier and the checker
/// (docs/robot-programs.md#verifying-a-program).
///
/// Each joint motion (movej, PTP, MoveJ, MoveAbsJ) becomes one synchronized PTP segment in
/// joint space (a straight line in joint space, all joints starting and stopping together):
/// a joint target as written, a Cartesian target resolved by inverse kinematics in the
/// configuration the program names. Each linear motion (movel, LIN, MoveL) becomes one certified
/// CP line of the cell's end effector E (CpLineSegment, timed by the motion's own TCP speed):
/// its TCP target re-stated for E, followed from the previous joints; the joints it ends in are
/// the next motion's current joints. Motions whose path this model does not describe are
/// refused, each naming its file and line: circular moves, blending, and a line that turns the
/// orientation under a program TCP other than E (its E path is no straight line).
///
/// Frame chain (docs/conventions.md names): the world W, the cell's robot base R (X_WR), the
/// program's base / work object B (X_RB), its TCP T (X_BT: the target; X_FT: the tool), the
/// flange F (the URDF tip link), the model's end effector E (X_FE: the cell's tool):
/// `X_WE = X_WR * X_RB * X_BT * X_FT^-1 * X_FE`.

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/model/robot_program.hpp"

namespace grpvss::motion {

/// \brief Where the program's robot stands in the cell: the cell's `base` and `tool`.
struct ProgramFrames {
  Eigen::Isometry3d X_WR = Eigen::Isometry3d::Identity();  ///< robot base R in the world, m
  Eigen::Isometry3d X_FE = Eigen::Isometry3d::Identity();  ///< model end effector E in the flange, m
};

/// \brief One program motion as the joint target the controller moves to.
struct ResolvedMotion {
  std::string file;
  int line = 0;
  bool cartesian = false;  ///< the target was a pose (resolved by IK)
  bool linear = false;     ///< a straight TCP line (movel, LIN, MoveL): a CP line of E
  Eigen::VectorXd q;       ///< the joint target (a line: the joints it ends in), rad
};

/// \brief The program as a path of synchronized PTP segments and CP lines, one per motion, in order.
struct ProgramPath {
  ProgramLanguage language = ProgramLanguage::kUrScript;
  PathProgram path;                    ///< PtpJointSegment or CpLineSegment per motion, source_line = its line
  std::vector<ResolvedMotion> motions;
};

/// Joint speed (rad/s) a PTP segment asks of every joint when the program gives none: URScript's
/// documented movej default, used for every language (the robot model has no speed limits). The
/// verdict does not depend on it: it sets the step times, not the joint-space path.
inline constexpr double kDefaultProgramJointSpeed = 1.05;

/// \brief The controller's base frame R in the URDF's root link (the frame a cell's `base`
/// places): for URScript, ur_description's `base` link, the root `base_link` turned by pi about
/// z; for KRL and RAPID the root itself (ROS-Industrial's `base` = `base_link`).
Eigen::Isometry3d controller_base_in_root(ProgramLanguage language);

/// "URScript", "KUKA KRL", "ABB RAPID".
const char* to_string(ProgramLanguage language);

/// \brief Resolves every motion of `program` against `robot`, starting at joints `q_start`.
/// Cartesian targets: `ik` solves for X_WE; a KRL Status/Turn or a RAPID confdata needs the OPW
/// closed form (kinematics::AnalyticIk) and selects the solution with it; a URScript qnear, or
/// no configuration, selects the solution nearest qnear or the joints the robot then has.
/// A line the robot cannot follow within its limits, or of zero length, ends the path there: the
/// planner reports it as thesis error 3, 4 or 5, and the motions after it are not resolved.
/// \throws InputError(motion's file, line, expected, found) for a refused motion (circular,
/// blended, a turning line under another TCP than E), a line whose target names a configuration
/// (KRL S/T, RAPID confdata, movel's joints) other than the one reached along it, a joint target of the wrong size or outside a joint limit (naming the
/// joint, the value and the limit), an unreachable target or configuration, or a program
/// without motions.
ProgramPath resolve_program(const RobotProgram& program, const RobotModel& robot,
                            const ProgramFrames& frames, const kinematics::InverseKinematics& ik,
                            const Eigen::VectorXd& q_start);

/// "program P (URScript), synchronized PTP, 4 motions (2 joint targets, 2 poses by IK)".
std::string describe_program_motion(const ProgramPath& path, const std::string& file_label);

/// The resolved joint targets as the certificate records them: one "file:line q1 ... qn" (rad,
/// 17 significant digits) per motion, separated by "; ".
std::string resolved_targets_text(const ProgramPath& path);

}  // namespace grpvss::motion

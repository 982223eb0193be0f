#pragma once
/// \file
/// \brief An industrial robot program (URScript, KUKA KRL, ABB RAPID) as the motions it
/// commands, in one neutral, fully typed form. Plain data in SI units: metres, radians,
/// seconds. Readers: io/robot_program_file.hpp; format subsets and conversions:
/// docs/robot-programs.md.
///
/// Frames (docs/conventions.md naming):
/// - `R`: the robot base frame (UR `base`, KUKA `$ROBROOT`, ABB base frame). The readers take
///   it to coincide with the controller's world frame (KUKA `$WORLD`, ABB `world`).
/// - `F`: the flange (UR tool flange, KUKA `$NULLFRAME` tool, ABB `tool0`).
/// - `T`: the tool centre point (TCP) in effect for the motion.
/// - `B`: the frame Cartesian targets are expressed in: UR `base` (= R), KUKA `$BASE`,
///   ABB work object (user frame * object frame).
/// A Cartesian target is `X_BT`; the flange pose it commands is
/// `X_RF = X_RB * X_BT * X_FT.inverse()`.

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace grpvss {

/// The language a program was written in.
enum class ProgramLanguage { kUrScript, kKrl, kRapid };

/// How the controller interpolates the motion.
enum class MotionKind {
  kJoint,     ///< all joints start and stop together: UR movej, KUKA PTP, ABB MoveJ/MoveAbsJ
  kLinear,    ///< straight TCP line: UR movel, KUKA LIN, ABB MoveL
  kCircular,  ///< TCP arc through a via point: UR movec, KUKA CIRC, ABB MoveC
};

/// \brief A target given as joint values, in the program's axis order (UR base..wrist 3,
/// KUKA A1..A6, ABB rax_1..rax_6): radians for revolute axes (metres for linear ones).
struct JointTarget {
  Eigen::VectorXd q;
};

/// KUKA `S` (status) and `T` (turn) bits of a POS/E6POS, as written (unset if omitted).
struct KrlStatusTurn {
  std::optional<int> status;
  std::optional<int> turn;
};

/// ABB `confdata` [cf1, cf4, cf6, cfx], as written.
struct RapidConfData {
  int cf1 = 0;
  int cf4 = 0;
  int cf6 = 0;
  int cfx = 0;
};

/// URScript `get_inverse_kin(x, qnear)`: the controller takes the inverse-kinematics solution
/// nearest `qnear` (rad). Empty `qnear` (none given): nearest the joints the robot has then,
/// i.e. at the end of the previous motion.
struct UrNearestJoints {
  Eigen::VectorXd qnear;
};

/// The arm configuration a Cartesian target names, as the program gives it (monostate: none).
using ArmConfiguration = std::variant<std::monostate, KrlStatusTurn, RapidConfData, UrNearestJoints>;

/// \brief A target given as a TCP pose in the motion's base/work-object frame B.
struct CartesianTarget {
  Eigen::Vector3d p_BT = Eigen::Vector3d::Zero();                 ///< metres
  Eigen::Quaterniond R_BT = Eigen::Quaterniond::Identity();       ///< unit quaternion
  ArmConfiguration configuration;                                 ///< as the program gives it

  /// The pose X_BT.
  Eigen::Isometry3d X_BT() const {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = R_BT.toRotationMatrix();
    pose.translation() = p_BT;
    return pose;
  }
};

/// Either kind of target.
using ProgramTarget = std::variant<JointTarget, CartesianTarget>;

/// \brief The speed settings in effect for one motion, as the program gives them, in SI.
/// Unset means the program does not say (the controller's own default applies); which
/// fields a language fills is listed in docs/robot-programs.md.
struct MotionSpeed {
  std::optional<double> tcp_speed;                 ///< m/s: UR movel/movec v, KUKA $VEL.CP, ABB v_tcp
  std::optional<double> tcp_acceleration;          ///< m/s^2: UR movel/movec a, KUKA $ACC.CP
  std::optional<double> orientation_speed;         ///< rad/s: KUKA $VEL.ORI1, ABB v_ori
  std::optional<double> orientation_speed_2;       ///< rad/s: KUKA $VEL.ORI2 (about the tool axis)
  std::optional<double> orientation_acceleration;  ///< rad/s^2: KUKA $ACC.ORI1
  std::optional<double> joint_speed;               ///< rad/s: UR movej v (the leading joint)
  std::optional<double> joint_acceleration;        ///< rad/s^2: UR movej a
  /// KUKA $VEL_AXIS[1..6]: percent of each axis's maximum speed (index 0 = A1); empty or
  /// unset entries when the program does not say.
  std::vector<std::optional<double>> joint_speed_percent;
  /// KUKA $ACC_AXIS[1..6]: percent of each axis's maximum acceleration.
  std::vector<std::optional<double>> joint_acceleration_percent;
  std::optional<double> external_linear_speed;     ///< m/s: ABB v_leax
  std::optional<double> external_rotation_speed;   ///< rad/s: ABB v_reax
  std::optional<double> duration;                  ///< s: UR t > 0, ABB \T (overrides speeds)
  std::string name;                                ///< ABB speeddata name ("v100", "vmax"); "" otherwise
};

/// How a motion ends.
enum class BlendKind {
  kExactStop,         ///< UR r = 0, KUKA without approximation, ABB fine
  kDistance,          ///< radius: UR r > 0, KUKA C_DIS ($APO.CDIS), ABB zone (pzone_tcp or \Z)
  kPtpPercent,        ///< KUKA C_PTP: $APO.CPTP percent
  kVelocityPercent,   ///< KUKA C_VEL: $APO.CVEL percent
  kOrientationAngle,  ///< KUKA C_ORI: $APO.CORI
};

/// \brief Blending into the next motion: the corner is replaced by a curve inside the zone.
struct MotionBlend {
  BlendKind kind = BlendKind::kExactStop;
  std::optional<double> radius;              ///< m (kDistance); unset if the program never set it
  std::optional<double> ptp_percent;         ///< percent (kPtpPercent)
  std::optional<double> velocity_percent;    ///< percent (kVelocityPercent)
  std::optional<double> orientation_angle;   ///< rad (kOrientationAngle; ABB zone_ori)
  std::optional<double> orientation_radius;  ///< m (ABB pzone_ori)
  std::string name;                          ///< "fine", "z10", "C_DIS", ... ; "" for UR
};

/// \brief One motion statement, with everything in effect when the controller runs it.
struct ProgramMotion {
  MotionKind kind = MotionKind::kJoint;
  ProgramTarget target;
  std::string target_name;            ///< the symbol the program names; "" for a literal
  /// Circular motions only: the via (auxiliary) point as written. The arc passes through its
  /// position; UR and KUKA document that its orientation is not used.
  std::optional<ProgramTarget> via;
  std::string via_name;
  std::optional<double> circular_angle;  ///< rad, KUKA CIRC ... CA (unset: to the target)
  Eigen::Isometry3d X_FT = Eigen::Isometry3d::Identity();  ///< tool: TCP in the flange, m
  std::string tool_name;
  Eigen::Isometry3d X_RB = Eigen::Isometry3d::Identity();  ///< base / work object in R, m
  std::string base_name;
  MotionSpeed speed;
  MotionBlend blend;
  std::string file;  ///< the file of the motion statement
  int line = 0;      ///< its 1-based line
};

/// \brief A statement or line the reader did not turn into motion data, and why.
struct ProgramWarning {
  std::string file;
  int line = 0;
  std::string text;
};

/// \brief A program as the motions it commands, in execution order as read
/// (docs/robot-programs.md: control flow is not evaluated).
struct RobotProgram {
  ProgramLanguage language = ProgramLanguage::kUrScript;
  std::string name;                      ///< the program's routine (def / DEF / PROC main)
  std::vector<ProgramMotion> motions;
  std::vector<ProgramWarning> warnings;  ///< in the order met
  std::vector<std::string> files;        ///< every file read, the program first
};

}  // namespace grpvss

#pragma once
/// \file
/// \brief The orientation and pose conventions of the three robot languages, converted to
/// Eigen rotations in SI units (docs/robot-programs.md#orientation-conventions).

#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace grpvss::io {

/// \brief KUKA A, B, C (radians): rotation about Z by A, then about the new Y by B, then about
/// the new X by C: \f$R = R_z(A)\,R_y(B)\,R_x(C)\f$.
Eigen::Quaterniond krl_abc_rotation(double a, double b, double c);

/// \brief KUKA FRAME/POS {X, Y, Z (mm), A, B, C (degrees)} as a pose in metres.
Eigen::Isometry3d krl_frame_pose(double x_mm, double y_mm, double z_mm, double a_degrees,
                                 double b_degrees, double c_degrees);

/// \brief URScript rotation vector (rx, ry, rz): axis times angle in radians.
Eigen::Quaterniond rotation_vector_rotation(const Eigen::Vector3d& rotation_vector);

/// \brief URScript pose p[x, y, z, rx, ry, rz] (metres, rotation vector) as a pose.
Eigen::Isometry3d urscript_pose(const Eigen::Matrix<double, 6, 1>& p);

/// \brief A pose as URScript writes it: position and rotation vector (angle in [0, pi]).
Eigen::Matrix<double, 6, 1> urscript_pose_vector(const Eigen::Isometry3d& pose);

/// Largest accepted deviation of a RAPID quaternion's norm from 1 (it is then normalised).
inline constexpr double kRapidQuaternionNormTolerance = 1e-3;

/// \brief RAPID orient [q1, q2, q3, q4] = (w, x, y, z), normalised; std::nullopt when its
/// norm differs from 1 by more than kRapidQuaternionNormTolerance.
std::optional<Eigen::Quaterniond> rapid_quaternion(double q1, double q2, double q3, double q4);

/// \brief RAPID pose [[x, y, z] (mm), [q1..q4]] in metres (quaternion already unit).
Eigen::Isometry3d rapid_pose(const Eigen::Vector3d& position_mm, const Eigen::Quaterniond& q);

/// Millimetres to metres: one rounded division.
constexpr double millimetres_to_metres(double millimetres) { return millimetres / 1000.0; }

}  // namespace grpvss::io

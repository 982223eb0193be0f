#pragma once
/// \file
/// \brief Closed-form kinematics of the UR family (Universal Robots UR3/5/10/16 and e-series):
/// K. P. Hawkins, "Analytic inverse kinematics for the Universal Robots UR-5/UR-10 arms"
/// (Georgia Tech, 2013), derived again here with atan2 throughout. Model coordinates only: base
/// B, flange F, model angles theta (rad); the chain mapping is in model_placement.hpp.
///
/// The model is UR's own standard DH table, A_i = Rot_z(theta_i) Trans_z(d_i) Trans_x(a_i)
/// Rot_x(alpha_i), with alpha = (pi/2, 0, 0, pi/2, -pi/2, 0), a = (0, a2, a3, 0, 0, 0),
/// d = (d1, 0, 0, d4, d5, d6); X_BF = A_1 ... A_6. Axes 2, 3, 4 are parallel; axis 5 meets
/// axis 4 and axis 6 meets axis 5 at right angles. UR publishes a2, a3 < 0 (e.g. UR5e:
/// d1 0.1625, a2 -0.425, a3 -0.3922, d4 0.1333, d5 0.0997, d6 0.0996 m).

#include <array>

#include <Eigen/Geometry>

#include "grpvss/kinematics/opw_kinematics.hpp"

namespace grpvss::kinematics {

/// \brief The six lengths of UR's DH table (any length unit).
struct UrParameters {
  double d1 = 0.0;  ///< height of axis 2 above B
  double a2 = 0.0;  ///< axis 2 to axis 3 (upper arm), UR: negative
  double a3 = 0.0;  ///< axis 3 to axis 4 (forearm), UR: negative
  double d4 = 0.0;  ///< sideways offset of the wrist along the parallel axes
  double d5 = 0.0;  ///< axis 4 to axis 6, along axis 5
  double d6 = 0.0;  ///< axis 5 to the flange, along axis 6
};

/// \brief X_BF: the flange in the base for model angles theta.
Eigen::Isometry3d ur_forward(const UrParameters& p, const ModelAngles& theta);

/// \brief The signed quantities that tell the UR configurations apart.
struct UrArmSides {
  /// x of the wrist point P5 (origin of DH frame 5, on axis 6 at d6 before the flange) in the
  /// axis-1 frame: a2 cos t2 + a3 cos(t2 + t3) + d5 sin(t2 + t3 + t4).
  double wrist_ahead_of_axis1 = 0.0;
  /// Height of the elbow (axis 3) over the line from axis 2 to axis 4 in the arm plane, taken
  /// with x of the axis-1 frame pointing right (the 2-D cross product chord x elbow):
  /// -a2 a3 sin(theta_3).
  double elbow_over_chord = 0.0;
};

/// \brief The arm sides at model angles theta.
UrArmSides ur_arm_sides(const UrParameters& p, const ModelAngles& theta);

/// \brief All eight branches for the flange pose X_BF, index 4 s + 2 e + w with
/// s = 1: wrist point P5 at negative x of the axis-1 frame, e = 1: sin(theta_3) < 0,
/// w = 1: sin(theta_5) < 0. Angles wrapped to (-pi, pi]. No NaN for any finite pose: an
/// unreachable branch is invalid; when axes 2-4 and 6 line up (sin theta_5 = 0) theta_6 is
/// free and taken from `theta6_free`, the rest solved so that ur_forward reproduces X_BF.
std::array<ModelBranch, 8> ur_inverse(const UrParameters& p, const Eigen::Isometry3d& X_BF,
                                      double theta6_free = 0.0);

}  // namespace grpvss::kinematics

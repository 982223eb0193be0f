#pragma once
/// \file
/// \brief Closed-form kinematics of the OPW family: an ortho-parallel arm with a spherical wrist
/// (M. Brandstötter, A. Angerer, M. Hofbaur, "An analytical solution of the inverse kinematics
/// problem of industrial serial manipulators with an ortho-parallel basis and a spherical
/// wrist", Austrian Robotics Workshop 2014). Model coordinates only: base frame B, flange F,
/// model angles theta (rad). How a chain's joints map onto theta: model_placement.hpp.
///
/// The model (all theta = 0): axis 1 is the z axis of B; axes 2 and 3 are parallel to y, axis 2
/// through (a1, *, c1), axis 3 a distance c2 above it; the wrist centre C = (a1 + a2, b,
/// c1 + c2 + c3); axis 4 is vertical through C, axis 5 along y, axis 6 vertical; the flange F
/// sits c4 above C with the orientation of B. Joints 2, 3, 5 turn about y, joints 1, 4, 6 about
/// z:  R_BF = Rz(t1) Ry(t2 + t3) Rz(t4) Ry(t5) Rz(t6).

#include <array>

#include <Eigen/Geometry>

namespace grpvss::kinematics {

/// \brief Model angles theta_1..theta_6 (rad) at index 0..5.
using ModelAngles = std::array<double, 6>;

/// \brief The seven lengths of the OPW model (paper's notation; any length unit).
struct OpwParameters {
  double a1 = 0.0;  ///< axis 1 to axis 2, along x
  double a2 = 0.0;  ///< axis 3 to axis 4 (the elbow offset), perpendicular to the forearm
  double b = 0.0;   ///< sideways offset of the arm plane from axis 1, along y
  double c1 = 0.0;  ///< height of axis 2 above B
  double c2 = 0.0;  ///< axis 2 to axis 3 (the lower arm), > 0
  double c3 = 0.0;  ///< axis 3 to the wrist centre, along the forearm
  double c4 = 0.0;  ///< wrist centre to the flange, along axis 6
};

/// \brief X_BF: the flange in the base for model angles theta.
Eigen::Isometry3d opw_forward(const OpwParameters& p, const ModelAngles& theta);

/// \brief The two signed distances that tell the arm's configuration apart.
struct OpwArmSides {
  /// x of the wrist centre in the axis-1 frame (B turned by theta_1): >= 0 in front of axis 1.
  double wrist_ahead_of_axis1 = 0.0;
  /// Distance of the wrist centre in front of the line through axes 2 and 3 (the lower arm),
  /// "front" being +x of the axis-1 frame when the lower arm points up:
  /// a2 cos(theta_3) + c3 sin(theta_3).
  double wrist_ahead_of_lower_arm = 0.0;
};

/// \brief The arm sides at model angles theta.
OpwArmSides opw_arm_sides(const OpwParameters& p, const ModelAngles& theta);

/// \brief One closed-form branch; `valid` is false when the pose is out of this branch's reach.
struct ModelBranch {
  ModelAngles theta{};
  bool valid = false;
};

/// \brief The angles that are free at a singular pose, used only there: theta_1 when the wrist
/// centre lies on axis 1 (b = 0), theta_4 when axes 4 and 6 line up (theta_5 = 0 or pi).
struct OpwSingularChoice {
  double theta1 = 0.0;
  double theta4 = 0.0;
};

/// \brief All eight branches for the flange pose X_BF, index 4 s + 2 e + w with
/// s = 1: wrist centre behind axis 1, e = 1: the second elbow solution (wrist centre behind the
/// lower arm when s = 0), w = 1: the flipped wrist (theta_4 + pi, -theta_5, theta_6 + pi).
/// Angles are wrapped to (-pi, pi]. No NaN for any finite pose: an unreachable branch is
/// marked invalid; a singular one takes the free angle from `choice` and solves the rest so that
/// opw_forward reproduces X_BF.
std::array<ModelBranch, 8> opw_inverse(const OpwParameters& p, const Eigen::Isometry3d& X_BF,
                                       const OpwSingularChoice& choice = {});

}  // namespace grpvss::kinematics

#pragma once
/// \file
/// \brief The general kinematic description: per joint a fixed transform, a motion along or
/// about the z axis of a joint frame, and a second fixed transform. make_chain() builds it from
/// the model's DH parameters. Forward kinematics and its rounding bound work on any chain of
/// this form; the motion-bound radii (certify/motion_bound.hpp) and the checker's exact ones
/// still read the DH parameters of the RobotModel.
///
/// Frame i (link i) is placed in frame i-1 by
/// \f[ X_{i-1,i}(q_i) = X_{PJ,i}\; M_i(q_i)\; X_{JC,i}, \f]
/// with \f$M_i = \mathrm{Rot}_z(q_i)\f$ (revolute) or \f$\mathrm{Trans}_z(q_i)\f$ (prismatic).
/// For standard DH (thesis Eq. 1-2), revolute: \f$X_{PJ} = \mathrm{Rot}_z(\theta)\f$,
/// \f$X_{JC} = \mathrm{Trans}_z(d)\mathrm{Trans}_x(a)\mathrm{Rot}_x(\alpha)\f$; prismatic:
/// \f$X_{PJ} = \mathrm{Rot}_z(\theta)\mathrm{Trans}_z(d)\f$,
/// \f$X_{JC} = \mathrm{Trans}_x(a)\mathrm{Rot}_x(\alpha)\f$. Frame 0 is the world frame W.

#include <vector>

#include <Eigen/Geometry>

#include "grpvss/model/robot_model.hpp"

namespace grpvss::kinematics {

/// \brief How far a stored fixed transform may be from the exact transform it denotes
/// (e.g. cos/sin of a DH angle rounded by libm). Used only by the FK rounding bound.
struct FixedTransformError {
  double rotation = 0.0;     ///< bound on the spectral norm of (stored R - exact R)
  double translation = 0.0;  ///< bound on the Euclidean norm of (stored t - exact t)
};

/// \brief One joint of the chain (joint i moves frame i relative to frame i-1).
struct ChainJoint {
  JointType type = JointType::kRevolute;
  /// Joint frame J_i (its z axis is the joint axis) in the parent frame i-1, at q_i = 0.
  Eigen::Isometry3d X_PJ = Eigen::Isometry3d::Identity();
  /// Child frame i in the moved joint frame.
  Eigen::Isometry3d X_JC = Eigen::Isometry3d::Identity();
  FixedTransformError X_PJ_error;
  FixedTransformError X_JC_error;
  double minimum = 0.0;  ///< lower joint limit (rad or length)
  double maximum = 0.0;  ///< upper joint limit (rad or length)
  double home = 0.0;
};

/// \brief An open chain of joints; frame 0 = world W, frame N = end effector E.
struct KinematicChain {
  std::vector<ChainJoint> joints;  ///< joints 1..N at index 0..N-1

  int joint_count() const { return static_cast<int>(joints.size()); }
  /// Joint values at home.
  Eigen::VectorXd home() const;
  /// True when every q_i lies in [minimum_i - slack, maximum_i + slack].
  bool within_limits(const Eigen::VectorXd& q, double slack = 0.0) const;
};

/// \brief Builds the chain from the standard DH description of the model.
KinematicChain make_chain(const RobotModel& model);

/// \brief The joint motion M_i(q): Rot_z(q) for a revolute joint, Trans_z(q) for a prismatic one.
Eigen::Isometry3d joint_motion(JointType type, double q);

}  // namespace grpvss::kinematics

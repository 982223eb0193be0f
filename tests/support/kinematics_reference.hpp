#pragma once
/// \file
/// \brief An independent forward-kinematics reference for tests: the closed-form standard DH
/// matrix (thesis Eq. 1-2) multiplied out, in any scalar type (double, long double,
/// boost::multiprecision). It shares no code with src/kinematics.

#include <cmath>

#include <Eigen/Core>

#include "grpvss/model/robot_model.hpp"

namespace grpvss::test {

/// A_i = Rot_z(theta) Trans_z(d) Trans_x(a) Rot_x(alpha) written out entry by entry.
template <typename Scalar>
Eigen::Matrix<Scalar, 4, 4> dh_matrix(const Joint& joint, double q) {
  using std::cos;
  using std::sin;
  Scalar theta = Scalar(joint.dh.theta);
  Scalar d = Scalar(joint.dh.d);
  if (joint.type == JointType::kRevolute) {
    theta += Scalar(q);
  } else {
    d += Scalar(q);
  }
  const Scalar a = Scalar(joint.dh.a);
  const Scalar alpha = Scalar(joint.dh.alpha);
  const Scalar ct = cos(theta), st = sin(theta), ca = cos(alpha), sa = sin(alpha);
  Eigen::Matrix<Scalar, 4, 4> A;
  A << ct, -st * ca, st * sa, a * ct,  //
      st, ct * ca, -ct * sa, a * st,   //
      Scalar(0), sa, ca, d,            //
      Scalar(0), Scalar(0), Scalar(0), Scalar(1);
  return A;
}

/// Homogeneous pose of link frame `link` (0..N) in W.
template <typename Scalar>
Eigen::Matrix<Scalar, 4, 4> reference_link_pose(const RobotModel& model, const Eigen::VectorXd& q,
                                               int link) {
  Eigen::Matrix<Scalar, 4, 4> X = Eigen::Matrix<Scalar, 4, 4>::Identity();
  for (int i = 0; i < link; ++i) {
    X = (X * dh_matrix<Scalar>(model.joints[static_cast<std::size_t>(i)], q[i])).eval();
  }
  return X;
}

}  // namespace grpvss::test

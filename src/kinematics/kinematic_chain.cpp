#include "grpvss/kinematics/kinematic_chain.hpp"

#include <cmath>
#include <limits>

#include "grpvss/common/unit_roundoff.hpp"

namespace grpvss::kinematics {
namespace {

// libm sin/cos are assumed within 2 ulp; for |value| <= 1 one ulp is at most 2u, so each
// entry is off by at most 4u, and a planar rotation block [[c,-s],[s,c]] perturbed by
// (ec, es) has spectral-norm error sqrt(ec^2 + es^2) <= sqrt(2) * 4u.
// proof: proofs/fk-rounding.md#trig-rounding
const double kPlanarRotationError = std::sqrt(2.0) * 4 * kUnitRoundoff;

// Rotation about z (axis 2) or x (axis 0) built entry by entry (no products, so the only
// rounding is in cos/sin). Angle 0 gives the exact identity.
Eigen::Matrix3d axis_rotation(int axis, double angle, double& error) {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  if (angle == 0.0) {
    error = 0.0;
    return R;
  }
  // A quarter-turn multiple read in degrees becomes the double nearest k pi/2, whose cosine or
  // sine is a residue (sin(fl(pi)) = 1.2e-16, sin(fl(2 pi)) = -2.4e-16). At most 3u, it is
  // within 3u + 2 ulp < 4u of the exact value, so 0 meets Lemma 0 (proofs/fk-rounding.md), and
  // the frame keeps its axes exactly: a 180 deg twist would otherwise tilt every placed
  // horizontal face by 1e-16 and bend it.
  const auto without_residue = [](double x) { return std::abs(x) <= 3 * kUnitRoundoff ? 0.0 : x; };
  const double c = without_residue(std::cos(angle));
  const double s = without_residue(std::sin(angle));
  const int i = (axis + 1) % 3;
  const int j = (axis + 2) % 3;
  R(i, i) = c;
  R(i, j) = -s;
  R(j, i) = s;
  R(j, j) = c;
  error = kPlanarRotationError;
  return R;
}

}  // namespace

Eigen::VectorXd KinematicChain::home() const {
  Eigen::VectorXd q(joint_count());
  for (int i = 0; i < joint_count(); ++i) q[i] = joints[static_cast<std::size_t>(i)].home;
  return q;
}

bool KinematicChain::within_limits(const Eigen::VectorXd& q, double slack) const {
  if (q.size() != joint_count()) return false;
  for (int i = 0; i < joint_count(); ++i) {
    const ChainJoint& joint = joints[static_cast<std::size_t>(i)];
    if (!(q[i] >= joint.minimum - slack && q[i] <= joint.maximum + slack)) return false;
  }
  return true;
}

KinematicChain make_chain(const RobotModel& model) {
  KinematicChain chain;
  chain.joints.reserve(model.joints.size());
  for (const Joint& joint : model.joints) {
    ChainJoint link;
    link.type = joint.type;
    link.minimum = joint.minimum;
    link.maximum = joint.maximum;
    link.home = joint.home;
    if (joint.frames) {
      link.X_PJ = joint.frames->X_PJ;
      link.X_JC = joint.frames->X_JC;
      link.X_PJ_error = {joint.frames->X_PJ_rotation_error, joint.frames->X_PJ_translation_error};
      link.X_JC_error = {joint.frames->X_JC_rotation_error, joint.frames->X_JC_translation_error};
      chain.joints.push_back(link);
      continue;
    }
    const DhParameters& dh = joint.dh;
    // Standard DH: A = Rot_z(theta) Trans_z(d) Trans_x(a) Rot_x(alpha). The variable sits in
    // Rot_z (revolute) or Trans_z (prismatic); whatever precedes it is X_PJ, the rest X_JC.
    // Translations are set directly, so they are exact (error 0).
    link.X_PJ.setIdentity();
    link.X_PJ.linear() = axis_rotation(2, dh.theta, link.X_PJ_error.rotation);
    link.X_JC.setIdentity();
    link.X_JC.linear() = axis_rotation(0, dh.alpha, link.X_JC_error.rotation);
    if (joint.type == JointType::kRevolute) {
      link.X_JC.translation() = Eigen::Vector3d(dh.a, 0.0, dh.d);
    } else {
      link.X_PJ.translation() = Eigen::Vector3d(0.0, 0.0, dh.d);
      link.X_JC.translation() = Eigen::Vector3d(dh.a, 0.0, 0.0);
    }
    chain.joints.push_back(link);
  }
  return chain;
}

Eigen::Isometry3d joint_motion(JointType type, double q) {
  Eigen::Isometry3d M = Eigen::Isometry3d::Identity();
  if (type == JointType::kRevolute) {
    const double c = std::cos(q);
    const double s = std::sin(q);
    M(0, 0) = c;
    M(0, 1) = -s;
    M(1, 0) = s;
    M(1, 1) = c;
  } else {
    M(2, 3) = q;
  }
  return M;
}

}  // namespace grpvss::kinematics

#include "chain_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "elementary_rotations.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"

namespace grpvss::kinematics::detail {

std::optional<std::string> six_revolute_joints(const KinematicChain& chain) {
  if (chain.joint_count() != 6) {
    return "the chain has " + std::to_string(chain.joint_count()) + " joints, not 6";
  }
  for (int i = 0; i < 6; ++i) {
    if (chain.joints[static_cast<std::size_t>(i)].type != JointType::kRevolute) {
      return "joint " + std::to_string(i + 1) + " is not revolute";
    }
  }
  return std::nullopt;
}

ChainGeometry chain_geometry_at_zero(const KinematicChain& chain, const Eigen::Isometry3d& X_ET) {
  ChainGeometry geometry;
  Workspace ws = Workspace::frames_only(chain.joints.size());
  forward_kinematics(chain, Eigen::VectorXd::Zero(chain.joint_count()), ws);
  for (const Eigen::Isometry3d& X_WJ : ws.X_WJ) {
    geometry.axes.push_back({X_WJ.translation(), X_WJ.linear().col(2).normalized()});
  }
  geometry.X_WT = ws.X_WL.back() * X_ET;
  for (const ChainJoint& joint : chain.joints) {
    geometry.length_scale += joint.X_PJ.translation().norm() + joint.X_JC.translation().norm();
  }
  geometry.length_scale += X_ET.translation().norm();
  if (!(geometry.length_scale > 0)) geometry.length_scale = 1.0;
  return geometry;
}

Eigen::Vector3d closest_point(const AxisLine& a, const AxisLine& b) {
  // Minimise |a.p + s a.u - b.p - t b.u|: the normal equations solved for s.
  const Eigen::Vector3d w = a.point - b.point;
  const double uv = a.direction.dot(b.direction);
  const double denominator = 1 - uv * uv;
  const double s = (uv * b.direction.dot(w) - a.direction.dot(w)) / denominator;
  return a.point + s * a.direction;
}

double line_distance(const AxisLine& a, const AxisLine& b) {
  const Eigen::Vector3d normal = a.direction.cross(b.direction);
  const Eigen::Vector3d w = b.point - a.point;
  if (normal.norm() < 1e-12) return (w - w.dot(a.direction) * a.direction).norm();
  return std::abs(w.dot(normal.normalized()));
}

Eigen::Vector3d foot(const AxisLine& a, const Eigen::Vector3d& point) {
  return a.point + a.direction * a.direction.dot(point - a.point);
}

double model_fk_deviation(const KinematicChain& chain, const Eigen::Isometry3d& X_ET,
                          double length_scale, const ModelPlacement& placement,
                          const std::function<Eigen::Isometry3d(const ModelAngles&)>& model_fk) {
  std::mt19937_64 generator(20140101);
  std::uniform_real_distribution<double> uniform(-kPi, kPi);
  double deviation = 0.0;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6);
  for (int sample = 0; sample <= 256; ++sample) {
    const Eigen::Isometry3d X_chain = end_effector_pose(chain, q) * X_ET;
    const Eigen::Isometry3d X_model =
        placement.X_WB * model_fk(placement.to_model(q)) * placement.X_FT;
    const double position = (X_chain.translation() - X_model.translation()).norm() / length_scale;
    const double rotation = rotation_distance(X_chain.linear(), X_model.linear());
    // NaN must fail the check, so compare with ! (x <= d).
    if (!(position <= deviation)) deviation = std::isnan(position) ? INFINITY : position;
    if (!(rotation <= deviation)) deviation = std::isnan(rotation) ? INFINITY : rotation;
    for (int i = 0; i < 6; ++i) q[i] = uniform(generator);
  }
  return deviation;
}

}  // namespace grpvss::kinematics::detail

namespace grpvss::kinematics::detail {

Eigen::Vector3d base_origin(const AxisLine& axis1) { return foot(axis1, Eigen::Vector3d::Zero()); }

Eigen::Vector3d base_up(const AxisLine& axis1, const Eigen::Vector3d& origin,
                        const Eigen::Vector3d& shoulder, double length_tol) {
  const double height = axis1.direction.dot(shoulder - origin);
  const double up = std::abs(height) > length_tol ? height : axis1.direction.z();
  return sign_of(up) * axis1.direction;
}

Eigen::Isometry3d frame_from(const Eigen::Vector3d& origin, const Eigen::Vector3d& z_B,
                             const Eigen::Vector3d& x_hint) {
  const Eigen::Vector3d z = z_B.normalized();
  const Eigen::Vector3d x = (x_hint - x_hint.dot(z) * z).normalized();
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear().col(0) = x;
  X.linear().col(1) = z.cross(x);
  X.linear().col(2) = z;
  X.translation() = origin;
  return X;
}

double tool_roll(const Eigen::Matrix3d& R_BM, const Eigen::Matrix3d& R_BT) {
  const Eigen::Matrix3d R_MT = R_BM.transpose() * R_BT;
  if ((R_MT.col(2) - Eigen::Vector3d::UnitZ()).norm() > kStructureTolerance) return 0.0;
  return std::atan2(R_MT(1, 0), R_MT(0, 0));
}

}  // namespace grpvss::kinematics::detail

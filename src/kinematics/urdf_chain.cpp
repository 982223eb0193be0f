#include "grpvss/kinematics/urdf_chain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "grpvss/common/unit_roundoff.hpp"

namespace grpvss::kinematics {
namespace {

// Multiplies by the rotation factor R unless it is an exact identity (a z axis), which would
// only add rounding terms to the bound.
void multiply_rotation(BoundedProduct& product, const Eigen::Matrix3d& R, double error) {
  if (R == Eigen::Matrix3d::Identity() && error == 0.0) return;
  BoundedFactor factor;
  factor.X.linear() = R;
  factor.delta = error;
  product.multiply(factor);
}

// X_PJ = (path from chain link i-1 to the joint frame at q = 0) R_a.
// proof: proofs/urdf-frames.md#chain-joints
BoundedProduct joint_frame(const ChainJointDescription& joint, const AxisFrame& axis) {
  BoundedProduct product = compose_frame_path(joint.parent_to_joint);
  multiply_rotation(product, axis.R, axis.error);
  return product;
}

// X_JC = R_a^T, then the fixed joints to the tip for the last joint.
BoundedProduct child_frame(const AxisFrame& axis, const FramePath* to_tip) {
  BoundedProduct product;
  multiply_rotation(product, axis.R.transpose(), axis.error);
  if (to_tip != nullptr) {
    for (const FrameStep& step : *to_tip) {
      for (const BoundedFactor& factor : step_factors(step)) product.multiply(factor);
    }
  }
  return product;
}

}  // namespace

KinematicChain make_chain(const RobotDescription& description) {
  KinematicChain chain;
  const std::size_t n = description.joints.size();
  for (std::size_t i = 0; i < n; ++i) {
    const ChainJointDescription& joint = description.joints[i];
    const AxisFrame axis = axis_frame(joint.axis);
    const BoundedProduct parent = joint_frame(joint, axis);
    const BoundedProduct child = child_frame(axis, i + 1 == n ? &description.last_child_to_tip : nullptr);
    ChainJoint link;
    link.type = joint.type;
    link.X_PJ = parent.X();
    link.X_PJ_error = parent.error();
    link.X_JC = child.X();
    link.X_JC_error = child.error();
    link.minimum = joint.minimum;
    link.maximum = joint.maximum;
    link.home = joint.home;
    chain.joints.push_back(link);
  }
  return chain;
}

BoundedPoints collision_frame_points(const CollisionDescription& collision) {
  BoundedPoints points;
  if (collision.shape == CollisionShape::kBox) {
    // Corners +-size/2: halving is exact, the size is the double nearest to its decimals
    // (|c^_i - c_i| <= gamma_1 |c^_i|). proof: proofs/urdf-frames.md#collision-points
    const Eigen::Vector3d half = collision.box_size / 2;
    for (int corner = 0; corner < 8; ++corner) {
      points.points.emplace_back((corner & 1) ? half.x() : -half.x(),
                                 (corner & 2) ? half.y() : -half.y(),
                                 (corner & 4) ? half.z() : -half.z());
    }
    points.error = 2 * gamma(1) * half.norm();
    return points;
  }
  if (collision.shape == CollisionShape::kMesh) {
    if (collision.mesh.vertices.empty()) {
      throw std::invalid_argument("collision_frame_points: mesh of link " + collision.link +
                                  " was not loaded");
    }
    points.points = collision.mesh.vertices;
    points.error = collision.mesh_vertex_error;
    return points;
  }
  throw std::invalid_argument("collision_frame_points: <collision> " +
                              std::to_string(collision.index) + " of link " + collision.link +
                              " is a cylinder or sphere, not a polytope");
}

BoundedPoints place_in_link_frame(const CollisionDescription& collision,
                                  const BoundedPoints& points_C) {
  return transform_points(collision.link_to_collision, points_C);
}

BoundedPoints transform_points(const FramePath& path, const BoundedPoints& points_C) {
  return transform_points(compose_frame_path(path), points_C);
}

BoundedPoints transform_points(const BoundedProduct& X_LC, const BoundedPoints& points_C) {
  BoundedPoints points_L;
  points_L.points.reserve(points_C.points.size());
  double largest = 0.0;
  for (const Eigen::Vector3d& p_C : points_C.points) {
    points_L.points.push_back(X_LC.X() * p_C);
    largest = std::max(largest, p_C.cwiseAbs().sum());  // >= |p_C|_2
  }
  // (P) for the stored points, plus the points' own error (an exact rotation keeps lengths).
  points_L.error = X_LC.point_bound(largest) + points_C.error;
  return points_L;
}

BoundedPoints collision_points_in_link_frame(const CollisionDescription& collision) {
  return place_in_link_frame(collision, collision_frame_points(collision));
}

}  // namespace grpvss::kinematics

#pragma once
// Private helpers of the family recognisers: the chain's joint axes at q = 0 as lines in W,
// line geometry, and the FK comparison of a fitted model against the chain.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/kinematics/model_placement.hpp"

namespace grpvss::kinematics::detail {

struct AxisLine {
  Eigen::Vector3d point;      // any point of the axis, W
  Eigen::Vector3d direction;  // unit, the positive turning direction of the joint
};

struct ChainGeometry {
  std::vector<AxisLine> axes;  // joint axes at q = 0, joint i at index i-1
  Eigen::Isometry3d X_WT;      // the tool at q = 0
  double length_scale = 0.0;   // sum of the lengths of all fixed translations (> 0)
};

/// Why `chain` cannot be a 6R family member, or nothing.
std::optional<std::string> six_revolute_joints(const KinematicChain& chain);

ChainGeometry chain_geometry_at_zero(const KinematicChain& chain, const Eigen::Isometry3d& X_ET);

/// Point of line a nearest to line b (lines not parallel).
Eigen::Vector3d closest_point(const AxisLine& a, const AxisLine& b);
/// Distance between two lines (parallel or not).
double line_distance(const AxisLine& a, const AxisLine& b);
/// Foot of `point` on line a.
Eigen::Vector3d foot(const AxisLine& a, const Eigen::Vector3d& point);

inline double sign_of(double x) { return x < 0 ? -1.0 : 1.0; }

/// Largest difference between X_WB * X_BF(theta(q)) * X_FT and chain FK(q) * X_ET over q = 0
/// and 256 fixed pseudo-random q: max(position error / length_scale, rotation angle).
double model_fk_deviation(const KinematicChain& chain, const Eigen::Isometry3d& X_ET,
                          double length_scale, const ModelPlacement& placement,
                          const std::function<Eigen::Isometry3d(const ModelAngles&)>& model_fk);

}  // namespace grpvss::kinematics::detail

namespace grpvss::kinematics::detail {

/// Angle tolerance (rad) and relative length tolerance of the structural checks; the FK check
/// (kFamilyFkTolerance) decides in the end.
constexpr double kStructureTolerance = 1e-7;

/// Foot of W's origin on axis 1: the model base's origin.
Eigen::Vector3d base_origin(const AxisLine& axis1);

/// The model base's z axis: +-axis 1, pointing from `origin` toward `shoulder` (a point of
/// axis 2); toward W's +z when the shoulder is level with the origin (within `length_tol`).
Eigen::Vector3d base_up(const AxisLine& axis1, const Eigen::Vector3d& origin,
                        const Eigen::Vector3d& shoulder, double length_tol);

/// Frame with origin `origin`, z = z_B and x = the unit part of x_hint perpendicular to z_B.
Eigen::Isometry3d frame_from(const Eigen::Vector3d& origin, const Eigen::Vector3d& z_B,
                             const Eigen::Vector3d& x_hint);

/// Rotation about z of the tool's frame against the model frame R_BM (the flange before the
/// last joint's offset) when the tool's z axis is that frame's z axis; 0 otherwise. Chosen as
/// joint 6's offset, it makes the tool's rotation on the flange the identity.
double tool_roll(const Eigen::Matrix3d& R_BM, const Eigen::Matrix3d& R_BT);

}  // namespace grpvss::kinematics::detail

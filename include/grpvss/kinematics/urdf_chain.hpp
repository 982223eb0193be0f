#pragma once
/// \file
/// \brief The kinematic chain of a RobotDescription (URDF), and its collision geometry placed
/// in the chain's link frames, each with a proven bound on the rounding of the arithmetic
/// (proofs/urdf-frames.md).
///
/// Joint i of the URDF moves its child by Trans(xyz) RPY(rpy) Rot(axis, q) (revolute,
/// continuous) or ... Trans(q axis/|axis|) (prismatic). With R_a a rotation taking z onto
/// axis/|axis| (Rot(axis, q) = R_a Rot_z(q) R_a^T) the chain stores
///   X_PJ = (fixed joints merged since chain link i-1) Trans(xyz) RPY(rpy) R_a,
///   M    = Rot_z(q) or Trans_z(q),
///   X_JC = R_a^T (for the last joint followed by the fixed joints to the tip),
/// so frame i of the chain is the URDF frame of joint i's child link (the tip for i = N) and
/// forward_kinematics() / forward_kinematics_error_bound() apply unchanged.

#include <vector>

#include <Eigen/Geometry>

#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/kinematics/rigid_product_bound.hpp"
#include "grpvss/model/robot_description.hpp"

namespace grpvss::kinematics {

/// \brief R_a: a rotation whose z column is the unit joint axis.
struct AxisFrame {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  /// Bound delta_a: some exact rotation R_a with R_a e_z = axis/|axis| (the exact decimal
  /// axis) has |R - R_a|_2 <= error. 0 for axes along a coordinate axis (R then exact).
  /// proof: proofs/urdf-frames.md#axis-frame
  double error = 0.0;
};

/// \brief The axis frame of a nonzero, finite `axis` (as written in the file).
/// \throws std::invalid_argument for a zero or non-finite axis.
AxisFrame axis_frame(const Eigen::Vector3d& axis);

/// \brief The stored factors of one frame step with their errors (proofs/urdf-frames.md
/// #frame-steps): an origin is Trans(xyz), Rot_z(yaw), Rot_y(pitch), Rot_x(roll) (identity
/// factors left out), an inverse origin the inverses in reverse order, a side-joint motion
/// R_a, Rot_z(value) or Trans_z(value), R_a^T.
std::vector<BoundedFactor> step_factors(const FrameStep& step);

/// \brief The product of a frame path, left to right, with its bounds.
BoundedProduct compose_frame_path(const FramePath& path);

/// \brief The chain of a description (see the file comment). Limits, home and type are the
/// description's (continuous joints keep -inf/+inf limits).
KinematicChain make_chain(const RobotDescription& description);

/// \brief Points with a bound on |stored - exact| shared by all of them (metres).
struct BoundedPoints {
  std::vector<Eigen::Vector3d> points;
  double error = 0.0;
};

/// \brief The points of a mesh (its vertices) or box (its 8 corners) collision, in the
/// collision frame C. \throws std::invalid_argument for a cylinder or sphere (not polytopes:
/// geometry/ builds polytopes around them) and for a mesh that was not loaded.
BoundedPoints collision_frame_points(const CollisionDescription& collision);

/// \brief Places points of the collision frame C (each within points_C.error of its exact
/// position) in the chain link frame: p_L = X_LC p_C with X_LC = compose_frame_path(
/// collision.link_to_collision). The error bounds |p^_L - p_L| for the exact X_LC and exact
/// points. proof: proofs/urdf-frames.md#collision-points
BoundedPoints place_in_link_frame(const CollisionDescription& collision,
                                  const BoundedPoints& points_C);

/// \brief Points of frame C (each within points_C.error of its exact position) carried to
/// frame L by X_LC = compose_frame_path(path_LC), with the same bound as
/// place_in_link_frame(). proof: proofs/urdf-frames.md#collision-points
BoundedPoints transform_points(const FramePath& path_LC, const BoundedPoints& points_C);

/// \brief As above, with the product X_LC already composed.
BoundedPoints transform_points(const BoundedProduct& X_LC, const BoundedPoints& points_C);

/// \brief collision_frame_points() placed by place_in_link_frame().
BoundedPoints collision_points_in_link_frame(const CollisionDescription& collision);

}  // namespace grpvss::kinematics

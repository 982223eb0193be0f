#pragma once
/// \file
/// \brief Forward kinematics into a reusable per-query Workspace (model/workspace split:
/// the chain and the model stay immutable, buffers live here so the hot loop never allocates).

#include <vector>

#include <Eigen/Geometry>

#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::kinematics {

/// \brief Per-query buffers, sized once for one robot model.
struct Workspace {
  Workspace() = default;
  /// Sizes every buffer for `model` (frames 0..N, joint frames 1..N, every hull vertex).
  explicit Workspace(const RobotModel& model);
  /// Frames only (for forward_kinematics and Jacobians), no hull vertices: two allocations
  /// instead of one per hull.
  static Workspace frames_only(std::size_t joint_count);

  /// X_WL[i]: pose of link frame i in the world, i = 0..N (X_WL[0] = identity, X_WL[N] = X_WE).
  std::vector<Eigen::Isometry3d> X_WL;
  /// X_WJ[i-1]: pose of joint frame J_i (z axis = joint axis i) in the world, i = 1..N,
  /// already moved by the joints before i (not by joint i: its axis does not move with it).
  std::vector<Eigen::Isometry3d> X_WJ;
  /// hull_points_W[link][hull][vertex]: every hull vertex of the model in world coordinates.
  std::vector<std::vector<std::vector<Eigen::Vector3d>>> hull_points_W;
};

/// \brief Fills ws.X_WL and ws.X_WJ for joint values q (rad / length). No allocation.
/// Throws std::logic_error when q or ws do not match the chain's size.
///
/// Evaluation order (the FK rounding bound depends on it,
/// proof: proofs/fk-rounding.md#fk-rounding): X <- X * X_PJ; X_WJ = X; X <- X * M(q);
/// X <- X * X_JC; X_WL[i] = X.
void forward_kinematics(const KinematicChain& chain, const Eigen::VectorXd& q, Workspace& ws);

/// \brief Fills ws.hull_points_W from ws.X_WL (call forward_kinematics first). No allocation.
void place_hull_points(const RobotModel& model, Workspace& ws);

/// Link-frame points placed at one configuration, with the frame of the link's own joint there
/// (its z axis is that joint's axis).
struct PlacedAtOwnJoint {
  std::vector<Eigen::Vector3d> points_W;
  Eigen::Isometry3d X_WJ = Eigen::Isometry3d::Identity();
};

/// \brief `points_L` of link `link` (1..N) placed by place_points at the middle of every joint's
/// limits, and joint `link`'s frame there. A point's distance from its own link's joint axis is
/// the same at every configuration (that joint turns the link about it), so one configuration
/// within the limits serves every step (proofs/motion-bound.md#axis-distance-evaluation).
PlacedAtOwnJoint place_at_middle_of_limits(const KinematicChain& chain, const RobotModel& robot, int link,
                                           const std::vector<Eigen::Vector3d>& points_L);

/// \brief Places link-frame points with the pose X_WL exactly as place_hull_points places hull
/// vertices: the expression the FK rounding bound covers (proofs/fk-rounding.md#fk-rounding).
/// The verifier's probe and the certificate checker both place points with it.
void place_points(const Eigen::Isometry3d& X_WL, const std::vector<Eigen::Vector3d>& points_L,
                  std::vector<Eigen::Vector3d>& points_W);

/// \brief X_WE: pose of the end-effector frame (frame N) in the world for joint values q.
Eigen::Isometry3d end_effector_pose(const KinematicChain& chain, const Eigen::VectorXd& q);

}  // namespace grpvss::kinematics

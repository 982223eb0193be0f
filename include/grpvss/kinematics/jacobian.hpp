#pragma once
/// \file
/// \brief Jacobians of points and of the end-effector pose, world coordinates.

#include <Eigen/Core>

#include "grpvss/kinematics/forward_kinematics.hpp"

namespace grpvss::kinematics {

/// \brief Linear-velocity Jacobian \f$\partial p_W / \partial q\f$ (3 x N) of the point with
/// link-frame coordinates p_L fixed in link `link` (0..N), at the configuration last given to
/// forward_kinematics(chain, q, ws). Columns of joints j > link are zero.
/// Revolute j: \f$z_j \times (p_W - o_j)\f$; prismatic j: \f$z_j\f$ (z_j, o_j: axis and origin
/// of joint frame J_j in W).
Eigen::Matrix<double, 3, Eigen::Dynamic> point_jacobian(const KinematicChain& chain,
                                                        const Workspace& ws, int link,
                                                        const Eigen::Vector3d& p_L);

/// \brief Geometric Jacobian (6 x N) of the end-effector frame: rows 0..2 linear velocity of
/// the origin of frame N, rows 3..5 angular velocity, both in W.
Eigen::Matrix<double, 6, Eigen::Dynamic> end_effector_jacobian(const KinematicChain& chain,
                                                               const Workspace& ws);

}  // namespace grpvss::kinematics

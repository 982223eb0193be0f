#pragma once
/// \file
/// \brief Real 6-axis arms as kinematic chains for the closed-form IK tests: built the URDF way
/// (per joint an origin xyz/rpy in the parent link and an axis), not from DH.

#include <random>
#include <string>

#include <Eigen/Geometry>

#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::test {

/// URDF origin: Trans(xyz) Rz(yaw) Ry(pitch) Rx(roll), rpy = (roll, pitch, yaw).
Eigen::Isometry3d urdf_origin(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy);

/// A revolute joint the URDF way: X_PJ = origin * R, X_JC = R^-1 with R turning z onto `axis`,
/// so X_PJ Rz(q) X_JC = origin * Rot(axis, q). Limits in rad.
kinematics::ChainJoint urdf_revolute(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy,
                                     const Eigen::Vector3d& axis, double lower, double upper);

/// The UR5e of /work/shared/robots/ur5e/ur5e.urdf from base_link to tool0, read by a trivial
/// reader of its <joint> elements (fixed joints folded into the neighbouring revolute ones).
kinematics::KinematicChain ur5e_chain_from_urdf();

/// KUKA KR 6 R700 sixx: the ROS-Industrial kr6r700sixx joint origins (A1 axis pointing down,
/// A4 and A6 along -x), tool0 rpy (0, pi/2, 0); the OPW parameters of opw_kinematics'
/// makeKukaKR6_R700_sixx (a1 25, a2 -35, c1 400, c2 315, c3 365, c4 80 mm); KUKA's limits
/// (deg): A1 +-170, A2 -190/45, A3 -120/156, A4 +-185, A5 +-120, A6 +-350. Metres.
kinematics::KinematicChain kr6_r700_chain();

/// ABB IRB 2400/10: joint origins from the OPW paper's parameters (a1 100, a2 -135, c1 615,
/// c2 705, c3 755, c4 85 mm; axes 4, 6 along x, tool0 rpy (0, pi/2, 0)), ABB's limits (deg):
/// +-180, -100/110, -60/65, +-200, +-120, +-400. Metres.
kinematics::KinematicChain irb2400_chain();

/// The UR5e as a DH robot file would describe it (UR's DH table, the URDF's numbers), limits
/// +-2 pi (elbow +-pi), seven links without hulls.
RobotModel ur5e_dh_model();

/// Uniform within each joint's limits.
Eigen::VectorXd random_chain_configuration(const kinematics::KinematicChain& chain,
                                           std::mt19937_64& generator);

/// The chain's tool pose: FK(q) * X_ET.
Eigen::Isometry3d chain_tool_pose(const kinematics::KinematicChain& chain, const Eigen::VectorXd& q,
                                  const Eigen::Isometry3d& X_ET = Eigen::Isometry3d::Identity());

}  // namespace grpvss::test

#include "grpvss/kinematics/forward_kinematics.hpp"

#include <stdexcept>
#include <string>

namespace grpvss::kinematics {

Workspace::Workspace(const RobotModel& model) : Workspace(frames_only(model.joints.size())) {
  hull_points_W.resize(model.links.size());
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const auto& hulls = model.links[i].hulls;
    hull_points_W[i].resize(hulls.size());
    for (std::size_t h = 0; h < hulls.size(); ++h) {
      hull_points_W[i][h].assign(hulls[h].points.size(), Eigen::Vector3d::Zero());
    }
  }
}

Workspace Workspace::frames_only(std::size_t joint_count) {
  Workspace ws;
  ws.X_WL.assign(joint_count + 1, Eigen::Isometry3d::Identity());
  ws.X_WJ.assign(joint_count, Eigen::Isometry3d::Identity());
  return ws;
}

void forward_kinematics(const KinematicChain& chain, const Eigen::VectorXd& q, Workspace& ws) {
  const std::size_t n = chain.joints.size();
  if (static_cast<std::size_t>(q.size()) != n || ws.X_WL.size() != n + 1 || ws.X_WJ.size() != n) {
    throw std::logic_error("forward_kinematics: chain has " + std::to_string(n) +
                           " joints, q has " + std::to_string(q.size()) + ", workspace has " +
                           std::to_string(ws.X_WL.size()) + " frames");
  }
  // Strict left-to-right accumulation, one isometry product per factor: the rounding bound
  // is proved for exactly this order. proof: proofs/fk-rounding.md#fk-rounding
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  ws.X_WL[0] = X;
  for (std::size_t i = 0; i < n; ++i) {
    const ChainJoint& joint = chain.joints[i];
    X = X * joint.X_PJ;
    ws.X_WJ[i] = X;
    X = X * joint_motion(joint.type, q[static_cast<Eigen::Index>(i)]);
    X = X * joint.X_JC;
    ws.X_WL[i + 1] = X;
  }
}

void place_hull_points(const RobotModel& model, Workspace& ws) {
  if (ws.hull_points_W.size() != model.links.size() || ws.X_WL.size() != model.links.size()) {
    throw std::logic_error("place_hull_points: workspace not sized for this model");
  }
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const Eigen::Isometry3d& X_WL = ws.X_WL[i];
    const auto& hulls = model.links[i].hulls;
    for (std::size_t h = 0; h < hulls.size(); ++h) {
      const auto& points_L = hulls[h].points;
      auto& points_W = ws.hull_points_W[i][h];
      if (points_W.size() != points_L.size()) {
        throw std::logic_error("place_hull_points: workspace not sized for this model");
      }
      for (std::size_t k = 0; k < points_L.size(); ++k) points_W[k] = X_WL * points_L[k];
    }
  }
}

Eigen::Isometry3d end_effector_pose(const KinematicChain& chain, const Eigen::VectorXd& q) {
  if (static_cast<std::size_t>(q.size()) != chain.joints.size()) {
    throw std::logic_error("end_effector_pose: q has " + std::to_string(q.size()) +
                           " values for " + std::to_string(chain.joints.size()) + " joints");
  }
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < chain.joints.size(); ++i) {
    const ChainJoint& joint = chain.joints[i];
    X = X * joint.X_PJ;
    X = X * joint_motion(joint.type, q[static_cast<Eigen::Index>(i)]);
    X = X * joint.X_JC;
  }
  return X;
}

void place_points(const Eigen::Isometry3d& X_WL, const std::vector<Eigen::Vector3d>& points_L,
                  std::vector<Eigen::Vector3d>& points_W) {
  points_W.resize(points_L.size());
  for (std::size_t i = 0; i < points_L.size(); ++i) points_W[i] = X_WL * points_L[i];
}

PlacedAtOwnJoint place_at_middle_of_limits(const KinematicChain& chain, const RobotModel& robot, int link,
                                           const std::vector<Eigen::Vector3d>& points_L) {
  Eigen::VectorXd middle(chain.joint_count());
  for (int j = 0; j < chain.joint_count(); ++j) {
    const ChainJoint& joint = chain.joints[static_cast<std::size_t>(j)];
    middle[j] = 0.5 * joint.minimum + 0.5 * joint.maximum;
  }
  Workspace frames(robot);
  forward_kinematics(chain, middle, frames);
  PlacedAtOwnJoint placed;
  place_points(frames.X_WL[static_cast<std::size_t>(link)], points_L, placed.points_W);
  placed.X_WJ = frames.X_WJ[static_cast<std::size_t>(link - 1)];
  return placed;
}

}  // namespace grpvss::kinematics

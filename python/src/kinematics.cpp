// Kinematics: Robot.forward_kinematics(q) (the pose X_WL of every link frame 0..N) and
// Robot.tcp_pose(q) (X_WE, frame N), computed by the kinematics stage exactly as the
// verifier computes them.
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"

namespace py = pybind11;

namespace grpvss::python {
namespace {

void require_joint_count(const LoadedRobot& robot, const Eigen::VectorXd& q) {
  if (q.size() == robot.model.joint_count()) return;
  throw std::invalid_argument("expected " + std::to_string(robot.model.joint_count()) +
                              " joint values, found " + std::to_string(q.size()));
}

std::vector<Eigen::Matrix4d> link_poses(const LoadedRobot& robot, const Eigen::VectorXd& q) {
  require_joint_count(robot, q);
  const kinematics::KinematicChain chain = kinematics::make_chain(robot.model);
  kinematics::Workspace workspace(robot.model);
  kinematics::forward_kinematics(chain, q, workspace);
  std::vector<Eigen::Matrix4d> poses;
  for (const Eigen::Isometry3d& X_WL : workspace.X_WL) poses.push_back(X_WL.matrix());
  return poses;
}

Eigen::Matrix4d tcp_pose(const LoadedRobot& robot, const Eigen::VectorXd& q) {
  require_joint_count(robot, q);
  return kinematics::end_effector_pose(kinematics::make_chain(robot.model), q).matrix();
}

}  // namespace

void bind_kinematics(RobotClass& robot_class) {
  robot_class.def("forward_kinematics", &link_poses, py::arg("q"),
                  "4x4 poses X_WL of link frames 0..N for joint values q (rad / length)");
  robot_class.def("tcp_pose", &tcp_pose, py::arg("q"),
                  "4x4 pose X_WE of the end-effector frame N for joint values q");
}

}  // namespace grpvss::python

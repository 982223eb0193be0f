#include "thesis_rule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "grpvss/geometry/gjk.hpp"
#include "grpvss/kinematics/jacobian.hpp"

namespace grpvss::certify {
namespace {

constexpr double kNoBound = std::numeric_limits<double>::infinity();

}  // namespace

ThesisStepRule::ThesisStepRule(const RobotCell& cell, double min_step_fraction)
    : cell_(&cell), min_step_fraction_(min_step_fraction), workspace_(cell.robot()) {}

std::vector<double> ThesisStepRule::allowed_displacements(const Eigen::VectorXd& q) {
  // Eq. 3-3: delta_l_i = max{min[2D/cos(theta/2), 2D + L], Dmin_i} at the origin of frame i.
  const RobotModel& robot = cell_->robot();
  const Environment& environment = cell_->environment();
  const double delta = cell_->tolerance();
  const double base = std::min(2.0 * delta / std::cos(environment.smallest_angle / 2.0),
                               2.0 * delta + environment.smallest_thickness);
  kinematics::forward_kinematics(cell_->chain(), q, workspace_);
  kinematics::place_hull_points(robot, workspace_);
  std::vector<double> allowed(robot.joint_count() + 1, base);
  for (int link = 1; link <= robot.joint_count(); ++link) {
    double nearest = kNoBound;
    for (const auto& hull_W : workspace_.hull_points_W[link]) {
      for (int o = 0; o < cell_->obstacles().size(); ++o) {
        nearest = std::min(nearest, geometry::gjk(hull_W, cell_->obstacles().vertices_W(o)).distance);
      }
    }
    if (robot.links[link].hulls.empty() || cell_->obstacles().size() == 0) nearest = 0.0;
    allowed[link] = std::max(base, nearest);
  }
  return allowed;
}

double ThesisStepRule::next_parameter(const SegmentPath& path, double s, const Eigen::VectorXd& q,
                                      double previous_step) {
  const std::vector<double> allowed = allowed_displacements(q);
  return path.is_cp() ? next_cp_parameter(path, s, q, allowed)
                      : next_ptp_parameter(path, s, q, previous_step, allowed);
}

// Eq. 4-13..4-16: delta_t_i <= delta_l_i / v_i, with v_i the speed of origin i.
double ThesisStepRule::next_ptp_parameter(const SegmentPath& path, double s,
                                          const Eigen::VectorXd& q, double previous_step,
                                          const std::vector<double>& allowed) {
  const double end = path.parameter_end();
  const int joints = cell_->robot().joint_count();
  double step = previous_step > 0.0 ? previous_step : end / 16.0;
  for (int iteration = 0; iteration < 3; ++iteration) {
    const Eigen::VectorXd speed_now = path.joint_velocity_at(s).cwiseAbs();
    const Eigen::VectorXd speed_then = path.joint_velocity_at(std::min(end, s + step)).cwiseAbs();
    const Eigen::VectorXd joint_speed = speed_now.cwiseMax(speed_then);
    kinematics::forward_kinematics(cell_->chain(), q, workspace_);
    double candidate = end - s;
    for (int link = 1; link <= joints; ++link) {
      const Eigen::Vector3d velocity =
          kinematics::point_jacobian(cell_->chain(), workspace_, link, Eigen::Vector3d::Zero()) *
          joint_speed;
      const double speed = velocity.norm();
      if (speed > 0.0) candidate = std::min(candidate, allowed[link] / speed);
    }
    step = candidate;
  }
  return std::min(end, s + std::max(step, end * min_step_fraction_));
}

// Figure 16: a trial increment of the end effector, scaled by the smallest ratio until every
// origin moves at most its allowance.
double ThesisStepRule::next_cp_parameter(const SegmentPath& path, double s,
                                         const Eigen::VectorXd& q,
                                         const std::vector<double>& allowed) {
  const double end = path.parameter_end();
  const int joints = cell_->robot().joint_count();
  double increment = *std::min_element(allowed.begin() + 1, allowed.end());
  kinematics::forward_kinematics(cell_->chain(), q, workspace_);
  std::vector<Eigen::Vector3d> origins_now(joints + 1);
  for (int link = 1; link <= joints; ++link) origins_now[link] = workspace_.X_WL[link].translation();
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double s1 = std::min(end, s + increment);
    const std::optional<Eigen::VectorXd> q1 = path.q_at(s1, q);
    if (!q1) return s1;  // the caller reports the unreachable point (error 5)
    kinematics::forward_kinematics(cell_->chain(), *q1, workspace_);
    double ratio = kNoBound;
    for (int link = 1; link <= joints; ++link) {
      const double moved = (workspace_.X_WL[link].translation() - origins_now[link]).norm();
      if (moved > 0.0) ratio = std::min(ratio, allowed[link] / moved);
    }
    if (ratio >= 1.0) return s1;
    increment = (s1 - s) * ratio * 0.999;
  }
  return std::min(end, s + increment);
}

}  // namespace grpvss::certify

#pragma once
/// \file
/// \brief Text and JSON renderings of a planned trajectory (`grpvss trajectory`;
/// docs/trajectories.md gives both formats). Joint values: degrees for revolute joints,
/// length units for prismatic ones.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/trajectory.hpp"

namespace grpvss::report {

/// \brief What the report shows besides the trajectory and its motion model.
struct TrajectoryReportSettings {
  std::string robot_file;
  std::string path_file;
  std::string ik_name;
  std::vector<double> times;  ///< path times at which to print the joints
};

/// Joint values for display: revolute joints in degrees, prismatic ones unchanged.
std::vector<double> display_joints(const RobotModel& robot, const Eigen::VectorXd& q);

/// The plain-text report (thesis-style upper case, 2 decimals, A.4 error wording).
std::string trajectory_text(const RobotModel& robot, const motion::Trajectory& trajectory,
                            const TrajectoryReportSettings& settings);

/// The JSON report (full precision).
nlohmann::json trajectory_json(const RobotModel& robot, const motion::Trajectory& trajectory,
                               const TrajectoryReportSettings& settings);

}  // namespace grpvss::report

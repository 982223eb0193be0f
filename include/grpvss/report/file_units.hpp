#pragma once
/// \file
/// \brief Library units -> the units of the input files, for reports: revolute joint values,
/// speeds and orientation angles in DEGREES, lengths and prismatic values unchanged.

#include <vector>

#include <Eigen/Core>

#include "grpvss/model/robot_model.hpp"

namespace grpvss::report {

/// Radians -> degrees: `radians / (pi/180)`, the inverse of the readers' conversion.
double degrees(double radians);

/// A joint value (or joint speed) in file units: degrees for revolute joints, unchanged for
/// prismatic joints.
double joint_value_in_file_units(double value, JointType type);

/// Every entry of `q` in file units.
/// \throws std::logic_error when `q` and `joint_types` differ in size.
std::vector<double> joint_values_in_file_units(const Eigen::VectorXd& q,
                                               const std::vector<JointType>& joint_types);

/// The joint types of `robot`, joint 1 first.
std::vector<JointType> joint_types_of(const RobotModel& robot);

}  // namespace grpvss::report

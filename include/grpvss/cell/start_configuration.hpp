#pragma once
/// \file
/// \brief Where a path starts when the caller says so (`--start`, a batch job's `start`):
/// the values in the units of the model's files, checked against the joints and turned into
/// library units once (docs/user-guide.md#start-configuration).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "grpvss/model/robot_model.hpp"

namespace grpvss::cell {

/// \brief `values`, one per joint in `robot`'s joint order, as library-unit joint values.
/// Units (`from_cell`): with a cell those of the cell's `home` (radians; prismatic joints in the robot's
/// length unit, metres for a URDF robot); with thesis files those of thesis path files
/// (degrees; prismatic joints in the robot file's length unit).
/// \throws InputError(source, 0, ...) when the count differs from the robot's joints, or a
///         value is not finite or lies outside its joint's limits; the message names the joint
///         (its URDF name, else "joint N") and its limits in the same units.
Eigen::VectorXd start_configuration(const std::vector<double>& values, const RobotModel& robot,
                                    bool from_cell, const std::string& source = "--start");

/// "0,-1.5708,1.5708" (the text `--start` takes) parsed into numbers.
/// \throws InputError(source, 0, ...) naming the entry that is not a number.
std::vector<double> parse_start_list(const std::string& text, const std::string& source = "--start");

}  // namespace grpvss::cell

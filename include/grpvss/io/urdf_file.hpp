#pragma once
/// \file
/// \brief Reader of URDF robot descriptions (through urdfdom) into the serial-chain
/// RobotDescription GRPVSS verifies, with collision meshes (through assimp). What is read, how
/// the chain and tip are chosen, side branches, mimic joints, package paths, units and every
/// message: docs/urdf.md.

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "grpvss/io/input_warning.hpp"
#include "grpvss/model/robot_description.hpp"

namespace grpvss::io {

/// Acceleration (rad/s^2 for revolute and continuous joints, m/s^2 for prismatic ones) given to
/// every chain joint the caller names no value for: URDF has no accelerations.
inline constexpr double kDefaultUrdfAcceleration = 5.0;

/// \brief Choices the URDF does not make.
struct UrdfReadOptions {
  /// The link that ends the chain; empty: the unique leaf reached through a movable joint.
  std::string tip;
  /// Directories searched for `package://NAME/...`, in order (the command line's
  /// `--package-path` first, then a cell file's `package_paths`), before ROS_PACKAGE_PATH.
  std::vector<std::string> package_paths;
  /// Append the directories of the ROS_PACKAGE_PATH environment variable to package_paths.
  bool use_ros_package_path = true;
  /// Values of movable joints off the chain (rad or m), by joint name; others: their mimic
  /// rule, else 0 clamped into their limits.
  std::map<std::string, double> side_joint_values;
  /// Accelerations of chain joints by joint name; others get default_acceleration.
  std::map<std::string, double> accelerations;
  double default_acceleration = kDefaultUrdfAcceleration;
  /// Read the collision meshes (false leaves CollisionDescription::mesh empty: for tools that
  /// need only the kinematics, and for the fuzzer).
  bool load_meshes = true;
  /// Turn COLLADA meshes' up axis onto +z (MeshReadOptions::apply_collada_up_axis).
  bool apply_collada_up_axis = false;
};

/// \brief The description and what was ignored on the way.
struct UrdfReadResult {
  RobotDescription description;
  std::vector<InputWarning> warnings;  ///< urdfdom's warnings, ignored elements
};

/// \brief Reads a URDF file; mesh paths are resolved against its folder.
/// \throws InputError naming the file, the line of the offending element and what was expected.
UrdfReadResult read_urdf_file(const std::string& path, const UrdfReadOptions& options = {});

/// \brief As read_urdf_file() on text in memory. `file_name` is used in messages and its folder
/// for relative mesh paths.
UrdfReadResult parse_urdf(std::string_view text, const std::string& file_name,
                          const UrdfReadOptions& options = {});

}  // namespace grpvss::io

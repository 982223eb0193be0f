#pragma once
/// \file
/// \brief The immutable robot model: an open chain of joints described by standard DH
/// parameters (thesis Eq. 1-2), joint limits, home, acceleration bounds, and per-link hulls.
///
/// Units inside the library: lengths in the file's unit (inches for the IBM 7545), revolute
/// joint values in RADIANS, prismatic joint values in length units, velocities per second.
/// Degrees exist only at the input/output boundary (io/, report/).

#include <string>
#include <vector>

#include "grpvss/model/hull_points.hpp"

namespace grpvss {

enum class JointType { kRevolute = 0, kPrismatic = 1 };

/// \brief Standard DH parameters of one joint: A_i = Rot_z(theta) Trans_z(d) Trans_x(a) Rot_x(alpha).
/// For a revolute joint `theta` is the variable (this field then holds its constant offset,
/// 0 for files in the thesis format); for a prismatic joint `d` is the variable.
struct DhParameters {
  double theta = 0.0;  ///< radians
  double d = 0.0;
  double a = 0.0;
  double alpha = 0.0;  ///< radians
};

struct Joint {
  JointType type = JointType::kRevolute;
  DhParameters dh;
  double home = 0.0;          ///< joint value at home (rad or length)
  double minimum = 0.0;       ///< lower joint limit
  double maximum = 0.0;       ///< upper joint limit
  double acceleration = 0.0;  ///< maximum admissible acceleration (> 0), per s^2
  double deceleration = 0.0;  ///< maximum admissible deceleration (> 0, a magnitude), per s^2
};

/// \brief Link i is rigidly attached to frame i (link 0 is the base, fixed in the world).
struct Link {
  double thickness = 0.0;         ///< the thesis's D_i (not given for link 0)
  std::vector<HullPoints> hulls;  ///< points in the link frame L_i
};

/// \brief Robot description, never modified by algorithms (Pinocchio's Model/Data split:
/// per-query buffers live in kinematics::Workspace).
struct RobotModel {
  std::string name;
  std::vector<Joint> joints;  ///< joints 1..N stored at index 0..N-1
  std::vector<Link> links;    ///< links 0..N (size N+1)

  int joint_count() const { return static_cast<int>(joints.size()); }
};

}  // namespace grpvss

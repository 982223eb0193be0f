#pragma once
/// \file
/// \brief The path: a sequence of motion segments (thesis A.1.3), in library units.

#include <optional>
#include <variant>
#include <vector>

#include <Eigen/Core>

namespace grpvss {

/// \brief A world-frame target: end-effector position and an orientation Rot(K, theta):
/// either the CHANGE applied to the orientation at the segment's start (Eq. 4-18, thesis path
/// files) or, when `orientation_is_absolute`, the end-effector orientation R_WE itself (YAML
/// paths, docs/input-formats.md#yaml-path).
struct WorldTarget {
  Eigen::Vector3d position_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_W = Eigen::Vector3d::UnitZ();  ///< K, not necessarily unit in the file
  double angle = 0.0;                                 ///< theta, RADIANS
  bool orientation_is_absolute = false;               ///< Rot(K, theta) is R_WE, not a change
};

/// IND = 1: PTP with joint targets (rad / length) and desired joint speeds (> 0).
struct PtpJointSegment {
  Eigen::VectorXd target;
  Eigen::VectorXd velocity;
};

/// IND = 2: PTP to a world pose (solved by IK), desired joint speeds (> 0).
struct PtpWorldSegment {
  WorldTarget target;
  Eigen::VectorXd velocity;
};

/// IND = 3: straight-line CP motion to a world pose.
struct CpLineSegment {
  WorldTarget target;
  /// The line's own TCP speed (length units/s, > 0): a robot program's movel v, KRL $VEL.CP,
  /// RAPID v_tcp. Unset (path files): the run's one CP speed.
  std::optional<double> speed;
};

using SegmentSpec = std::variant<PtpJointSegment, PtpWorldSegment, CpLineSegment>;

struct PathSegment {
  SegmentSpec spec;
  int source_line = 0;  ///< line of the segment's IND in the path file
};

struct PathProgram {
  std::vector<PathSegment> segments;
};

}  // namespace grpvss

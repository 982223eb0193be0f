#pragma once
/// \file
/// \brief A joint trajectory written as the CSV that io::parse_trajectory_csv reads
/// (docs/trajectories.md#planner-trajectories): the canonical text of a trajectory given as
/// numbers rather than a file (the Python module's arrays), so that it has a digest a
/// certificate can bind, and a file `grpvss verify --trajectory` verifies identically.

#include <string>

#include "grpvss/model/joint_trajectory.hpp"

namespace grpvss::io {

/// \brief `time,<joint>...` (then `<joint>.vel...` when the trajectory has velocities), one row
/// per waypoint, every number in the shortest decimal that reads back as the same double;
/// `\n` line ends. Line 1 is the header, line k+2 waypoint k. Not validated here: parsing the
/// text validates it (a non-finite number is written as `nan`/`inf` and refused by the reader).
std::string render_trajectory_csv(const JointTrajectory& trajectory);

}  // namespace grpvss::io

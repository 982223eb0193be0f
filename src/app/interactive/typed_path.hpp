#pragma once
/// \file
/// \brief A path typed at the terminal, kept as the text of a path file (thesis A.1.3), so the
/// typed path is validated by the same reader as a file (io::parse_path_file), can be digested
/// for the report, and can be saved and verified again with `grpvss verify`.

#include <array>
#include <string>
#include <vector>

#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::app::interactive {

/// One typed segment in file units (degrees for revolute joints, as typed).
struct TypedSegment {
  int kind = 1;                       ///< the thesis's IND: 1 PTP JCS, 2 PTP WCS, 3 CP
  std::vector<double> joint_targets;  ///< kind 1
  std::vector<double> velocities;     ///< kinds 1 and 2
  std::array<double, 7> pose{};       ///< kinds 2 and 3: XEND, YEND, ZEND, KX, KY, KZ, KTHETA
};

/// The path-file text of `segments` (NOMS, then each segment); numbers round-trip exactly.
std::string path_file_text(const std::vector<TypedSegment>& segments);

/// The program of `segments` for `robot`, read back through io::parse_path_file.
/// \throws InputError if a segment does not fit the robot (e.g. wrong joint count).
PathProgram typed_program(const std::vector<TypedSegment>& segments, const RobotModel& robot);

}  // namespace grpvss::app::interactive

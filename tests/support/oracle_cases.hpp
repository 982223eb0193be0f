#pragma once
/// \file
/// \brief Random cells and paths for the oracle soundness tests (fixed seeds; the same seed
/// always gives the same case). Two families:
///
/// - `random_ptp_case`: 2-5 joints, revolute and prismatic mixed, random DH; per link a body
///   box along the link and often a TOOL box sticking out 3-8 units beyond the frame origin
///   in a random direction; PTP joint segments; numeric IK (unused by PTP(JCS)).
/// - `random_scara_cp_case`: robots of the IBM 7545 structure (R, R, P, R with random link
///   lengths, offsets, limits and tool hulls), closed-form IK, paths mixing CP lines (with a
///   yaw change) and PTP joint segments; one move in ten is long (half the joint ranges), so
///   some lines leave the workspace or need a joint jump (errors 5, 7, 8).
///
/// Both: tolerance log-uniform from tiny (0.02) to large (2); 1-3 obstacles placed next to a
/// hull vertex at a configuration on the commanded path, with a signed face gap from -0.5 to
/// +3 tolerances (boxes or thin plates), so that a large share of the cases are contacts or
/// near misses; 0-2 far boxes.

#include <cstdint>
#include <string>

#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::test {

struct OracleCase {
  RobotModel robot;
  Environment environment;
  PathProgram program;
  double tolerance = 0.5;
  kinematics::IkChoice ik{kinematics::IkMethod::kNumeric, {}};  ///< for motion::select_ik
};

OracleCase random_ptp_case(std::uint64_t seed);
OracleCase random_scara_cp_case(std::uint64_t seed);

}  // namespace grpvss::test

// Fuzz target: the ROS JointTrajectory JSON reader, then the motion stage on what it accepts
// (interpolation, variation bounds rounded and exact, limit check).
// InputError is the documented outcome of bad input; anything else is a finding.
#include "fuzz_input.hpp"
#include "grpvss/common/input_error.hpp"
#include "trajectory_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  grpvss::JointTrajectory trajectory;
  try {
    trajectory = grpvss::io::parse_trajectory_json(grpvss::fuzz::as_text(data, size), "fuzz.json");
  } catch (const grpvss::InputError&) {
    return 0;
  }
  grpvss::fuzz::check_accepted_trajectory(trajectory);
  return 0;
}

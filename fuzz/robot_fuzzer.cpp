// Fuzz target: the robot-modelling file reader (thesis A.1.1.1). InputError is the documented
// outcome of bad input; anything else escaping, a crash, a leak or UB is a finding.
#include "fuzz_input.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/robot_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)grpvss::io::parse_robot_file(grpvss::fuzz::as_text(data, size), "fuzz-robot.txt");
  } catch (const grpvss::InputError&) {
  }
  return 0;
}

// Fuzz target: the path-input file reader (thesis A.1.3) for the IBM 7545 sample robot.
// InputError is the documented outcome of bad input; anything else is a finding.
#include "fuzz_input.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const grpvss::RobotModel robot =
      grpvss::io::read_robot_file(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/robot.txt");
  try {
    (void)grpvss::io::parse_path_file(grpvss::fuzz::as_text(data, size), "fuzz-path.txt", robot);
  } catch (const grpvss::InputError&) {
  }
  return 0;
}

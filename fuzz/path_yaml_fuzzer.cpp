// Fuzz target: the YAML path reader (docs/input-formats.md#yaml-path) for the IBM 7545 sample
// robot placed in a model in metres, with a turned base for `frame: base` poses.
// InputError is the documented outcome of bad input; anything else is a finding.
#include <Eigen/Geometry>

#include "fuzz_input.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const grpvss::RobotModel robot =
      grpvss::io::read_robot_file(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/robot.txt");
  static const grpvss::io::PathPlacement placement{
      grpvss::LengthUnit::kMetre,
      Eigen::Isometry3d(Eigen::Translation3d(0.1, 0.0, 0.8) *
                        Eigen::AngleAxisd(0.25, Eigen::Vector3d::UnitZ()))};
  try {
    (void)grpvss::io::parse_path_file(grpvss::fuzz::as_text(data, size), "fuzz-path.yaml", robot,
                                      placement);
  } catch (const grpvss::InputError&) {
  }
  return 0;
}

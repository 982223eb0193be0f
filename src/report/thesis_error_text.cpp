#include "grpvss/report/thesis_error_text.hpp"

#include <stdexcept>

#include <fmt/core.h>

namespace grpvss::report {

std::string thesis_error_text(int code, int segment) {
  if (!is_thesis_error_code(code)) {
    throw std::out_of_range(fmt::format("thesis_error_text: no thesis error {} (1-6)", code));
  }
  if (code >= 3 && segment < 1) {
    throw std::out_of_range(
        fmt::format("thesis_error_text: error {} needs a segment number >= 1, got {}", code,
                    segment));
  }
  // Appendix A.4, verbatim except for the segment number in place of I.
  switch (code) {
    case 1:
      return "The movement of the end effector in the CP operation is zero. In CP operations, "
             "the simulation resolution is determined by the increment of the end effector. "
             "Therefore, the simulation can not be performed if movement of the CP "
             "straight-line operation is zero. PTP operation is suggested if this error is not "
             "caused by a mistake.";
    case 2:
      return "Unreachable intermediate point was encountered. Simulation terminated at that "
             "point. This path is out of the workspace.";
    case 3:
      return fmt::format(
          "The final position of the motion segment {} in the path input file is out of "
          "workspace. This motion segment was not simulated. The simulation terminated when "
          "this motion segment was encountered.",
          segment);
    case 4:
      return fmt::format(
          "The movement of the end effector in the CP operation of motion segment {} in the "
          "input path file is zero. PTP operation is suggested if the error is not caused by "
          "a mistake.",
          segment);
    case 5:
      return fmt::format(
          "Unreachable intermediate point was encountered in the motion segment {} in the "
          "input file. Simulation terminated at that point. This motion segment is out of the "
          "workspace.",
          segment);
    default:  // 6
      return fmt::format(
          "Undefined operation type data was encountered in motion segment {} in the input "
          "file. Simulation terminated at that point. Check the path input file.",
          segment);
  }
}

}  // namespace grpvss::report

#include "grpvss/motion/thesis_error.hpp"

#include <stdexcept>
#include <utility>

#include <fmt/core.h>

namespace grpvss::motion {

std::string thesis_error_text(int code, int segment) {
  // Verbatim from thesis Appendix A.4, with I replaced by the segment number.
  switch (code) {
    case 1:
      return "The movement of the end effector in the CP operation is zero. In CP operations, "
             "the simulation resolution is determined by the increment of the end effector. "
             "Therefore, the simulation can not be performed if movement of the CP straight-line "
             "operation is zero. PTP operation is suggested if this error is not caused by a "
             "mistake.";
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
          "input path file is zero. PTP operation is suggested if the error is not caused by a "
          "mistake.",
          segment);
    case 5:
      return fmt::format(
          "Unreachable intermediate point was encountered in the motion segment {} in the input "
          "file. Simulation terminated at that point. This motion segment is out of the "
          "workspace.",
          segment);
    case 6:
      return fmt::format(
          "Undefined operation type data was encountered in motion segment {} in the input "
          "file. Simulation terminated at that point. Check the path input file.",
          segment);
    default:
      throw std::invalid_argument(fmt::format("thesis error code {} is not in 1..6", code));
  }
}

ThesisError make_thesis_error(int code, int segment, std::string detail) {
  return ThesisError{code, segment, thesis_error_text(code, segment), std::move(detail)};
}

}  // namespace grpvss::motion

#pragma once
/// \file
/// \brief The thesis's path errors 1-6 (Appendix A.4): findings about a path, not bad input.
/// A thesis error stops the path at the failing segment (the thesis terminates there).

#include <string>

namespace grpvss::motion {

/// \brief One thesis error. `segment` is the 1-based motion segment (0 when there is no
/// segment context: errors 1 and 2).
struct ThesisError {
  int code = 0;
  int segment = 0;
  std::string message;  ///< the A.4 wording with the segment number filled in
  std::string detail;   ///< what GRPVSS found (e.g. which joint limit), may be empty
};

/// The A.4 wording of error `code` (1..6), the segment number written in place of "I".
/// \throws std::invalid_argument for a code outside 1..6.
std::string thesis_error_text(int code, int segment);

/// Builds a ThesisError with its A.4 message.
ThesisError make_thesis_error(int code, int segment, std::string detail = {});

}  // namespace grpvss::motion

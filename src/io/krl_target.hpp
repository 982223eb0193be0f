#pragma once
// KRL motion targets: AXIS/E6AXIS (A1..A6 degrees) and POS/E6POS/FRAME (X, Y, Z mm;
// A, B, C degrees; S, T) structures as neutral targets in SI.

#include <optional>
#include <string>
#include <vector>

#include "grpvss/io/program_lexer.hpp"
#include "grpvss/model/robot_program.hpp"
#include "krl_value.hpp"

namespace grpvss::io::krl {

/// The last target read, which completes a partial aggregate (KRL takes the missing
/// components from the current position, which after a motion is that motion's target).
struct PreviousTarget {
  Value value;  ///< complete
  bool joint = false;
  std::string tool_name;
  std::string base_name;
};

struct KrlTarget {
  ProgramTarget target;
  Value completed;  ///< the value with every component
  bool joint = false;
  /// Nonzero external axes ("E1 = 300"), which are not read.
  std::vector<std::string> external_axes;
};

/// \brief Converts a target value of motion `what` ("PTP", "the auxiliary point of CIRC").
/// A partial aggregate is completed from `previous` when that is of the same kind (and, for
/// a Cartesian target, was read with the same tool and base names).
/// \throws InputError (at `line`) for an unknown value, a value that is not a target, a
/// component that is not a number (S and T: integers), or a partial target that cannot be
/// completed.
KrlTarget krl_target(const Value& value, const std::string& what,
                     const std::optional<PreviousTarget>& previous, const std::string& tool_name,
                     const std::string& base_name, const TokenCursor& cursor, int line);

}  // namespace grpvss::io::krl

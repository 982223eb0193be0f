#pragma once
// NumberTraits<mpq_class> for TrajectoryPiece: the stored doubles converted exactly.
#include <gmpxx.h>

#include "joint_trajectory_pieces.hpp"

namespace grpvss::motion::detail {

template <>
struct NumberTraits<mpq_class> {
  static mpq_class from(double x) { return mpq_class(x); }
  static mpq_class difference(double a, double b) { return mpq_class(a) - mpq_class(b); }
  static mpq_class unit_ratio(const mpq_class& n, const mpq_class& d) { return n / d; }
};

using ExactPiece = TrajectoryPiece<mpq_class>;

}  // namespace grpvss::motion::detail

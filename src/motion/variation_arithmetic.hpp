#pragma once
// The two number policies of detail::piece_variation (hermite_piece.hpp): enclosing intervals
// for the verifier's rounded bound and GMP rationals for the checker's exact bound.
// proof: proofs/joint-variation.md#lemma-monotone-test, #rounded-evaluation
#include <gmpxx.h>

#include "enclosing_interval.hpp"

namespace grpvss::motion::detail {

/// Interval arithmetic: every result encloses the exact one.
struct IntervalArithmetic {
  using Bound = double;
  static double magnitude(const Interval& x) { return magnitude_up(x); }
  static double sum(double a, double b) { return sum_up(a, b); }
  static Interval third(const Interval& x) { return divided(x, 3.0); }
  static Interval midpoint(const Interval& a, const Interval& b) { return detail::midpoint(a, b); }
  /// The monotonicity test of the lemma, certified for every value in the intervals.
  static bool monotone(const Interval& d0, const Interval& d1, const Interval& d2) {
    const bool rising = d0.lo >= 0.0 && d2.lo >= 0.0 &&
                        (d1.lo >= 0.0 || square_up(d1) <= product_down(d0.lo, d2.lo));
    const bool falling = d0.hi <= 0.0 && d2.hi <= 0.0 &&
                         (d1.hi <= 0.0 || square_up(d1) <= product_down(-d0.hi, -d2.hi));
    return rising || falling;
  }
};

/// Exact rational arithmetic.
struct ExactArithmetic {
  using Bound = mpq_class;
  static mpq_class magnitude(const mpq_class& x) { return abs(x); }
  static mpq_class sum(const mpq_class& a, const mpq_class& b) { return a + b; }
  static mpq_class third(const mpq_class& x) { return x / 3; }
  static mpq_class midpoint(const mpq_class& a, const mpq_class& b) { return (a + b) / 2; }
  static bool monotone(const mpq_class& d0, const mpq_class& d1, const mpq_class& d2) {
    const bool squared_small = d1 * d1 <= d0 * d2;
    const bool rising = d0 >= 0 && d2 >= 0 && (d1 >= 0 || squared_small);
    const bool falling = d0 <= 0 && d2 <= 0 && (d1 <= 0 || squared_small);
    return rising || falling;
  }
};

}  // namespace grpvss::motion::detail

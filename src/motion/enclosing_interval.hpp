#pragma once
// Closed intervals of doubles that enclose exact real values, computed in the default
// round-to-nearest mode (no rounding-mode switch, no dependency on geometry/):
// - a sum or difference is rounded to nearest and its exact error found by Knuth's TwoSum;
//   the interval is [fl, succ(fl)] or [pred(fl), fl] by the error's sign, [fl, fl] when exact;
// - a product or quotient is widened to the neighbouring doubles (a correctly rounded result
//   is one of the two doubles that bracket the exact value), exact when an operand is 0.
// proof: proofs/joint-variation.md#rounded-evaluation
// Requires round-to-nearest (checked by the callers) and no overflow (inputs are bounded by
// 1e9, JointTrajectoryMotion checks it).
#include <algorithm>
#include <cmath>
#include <limits>

#include "grpvss/common/next_double.hpp"

namespace grpvss::motion::detail {

using grpvss::next_down;
using grpvss::next_up;

/// [lo, hi] with lo <= hi.
struct Interval {
  double lo = 0.0;
  double hi = 0.0;

  static Interval point(double x) { return {x, x}; }
  bool is_point(double x) const { return lo == x && hi == x; }
};

/// RD(a + b) and RU(a + b) from the nearest sum and its exact TwoSum error.
inline double sum_down(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  const double error = (a - (s - bb)) + (b - bb);
  return error < 0.0 ? next_down(s) : s;
}
inline double sum_up(double a, double b) { return -sum_down(-a, -b); }

/// A bracket of the exact product a * b: exact when a factor is 0, else the neighbours of the
/// correctly rounded product.
inline Interval product_bracket(double a, double b) {
  if (a == 0.0 || b == 0.0) return {0.0, 0.0};
  const double p = a * b;
  return {next_down(p), next_up(p)};
}

inline Interval operator+(const Interval& a, const Interval& b) {
  return {sum_down(a.lo, b.lo), sum_up(a.hi, b.hi)};
}
inline Interval operator-(const Interval& a, const Interval& b) {
  return {sum_down(a.lo, -b.hi), sum_up(a.hi, -b.lo)};
}
inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }

inline Interval operator*(const Interval& a, const Interval& b) {
  const Interval products[4] = {product_bracket(a.lo, b.lo), product_bracket(a.lo, b.hi),
                                product_bracket(a.hi, b.lo), product_bracket(a.hi, b.hi)};
  Interval result = products[0];
  for (const Interval& p : products) {
    result.lo = std::min(result.lo, p.lo);
    result.hi = std::max(result.hi, p.hi);
  }
  return result;
}

/// x / c for a constant c > 0 (3 for the Bezier thirds): each end's quotient widened
/// outwards unless it is an exact 0.
inline Interval divided(const Interval& x, double c) {
  const auto down = [c](double v) { return v == 0.0 ? 0.0 : next_down(v / c); };
  const auto up = [c](double v) { return v == 0.0 ? 0.0 : next_up(v / c); };
  return {down(x.lo), up(x.hi)};
}

/// The midpoint (a + b) / 2, widened where halving a subnormal end was inexact.
inline Interval midpoint(const Interval& a, const Interval& b) {
  const Interval sum = a + b;
  double lo = sum.lo * 0.5, hi = sum.hi * 0.5;
  if (lo * 2.0 != sum.lo) lo = next_down(lo);
  if (hi * 2.0 != sum.hi) hi = next_up(hi);
  return {lo, hi};
}

/// An upper bound of |x| over the interval.
inline double magnitude_up(const Interval& x) { return std::max(std::fabs(x.lo), std::fabs(x.hi)); }

/// x intersected with [0, 1] (x encloses a value known to lie in [0, 1]).
inline Interval clamped_to_unit(const Interval& x) {
  return {std::clamp(x.lo, 0.0, 1.0), std::clamp(x.hi, 0.0, 1.0)};
}

/// A lower bound of a * b for a, b >= 0.
inline double product_down(double a, double b) {
  if (a == 0.0 || b == 0.0) return 0.0;
  return next_down(a * b);
}
/// An upper bound of x^2 over the interval.
inline double square_up(const Interval& x) {
  const double m = magnitude_up(x);
  return m == 0.0 ? 0.0 : next_up(m * m);
}

}  // namespace grpvss::motion::detail

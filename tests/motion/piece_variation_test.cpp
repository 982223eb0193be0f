// The recursion of proofs/joint-variation.md#theorem-piece-variation with the library's two
// number policies, on its own: without the proposed split points that JointTrajectoryMotion
// adds, so the monotonicity test, the midpoint halving and the control-polygon leaves all
// carry the bound (with the split points most parts are monotone already).
#include <random>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include "motion/hermite_piece.hpp"
#include "motion/variation_arithmetic.hpp"

namespace grpvss::motion::detail {
namespace {

/// q with q' = 3 c3 (s - r1)(s - r2) + slope_shift and q(0) = offset: coefficient doubles.
struct Cubic {
  double c0, c1, c2, c3;
};

Cubic random_cubic(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0, 1), size(-4, 4);
  const double r1 = unit(rng), r2 = unit(rng), c3 = size(rng);
  const double shift = unit(rng) < 0.3 ? 0.0 : 0.3 * size(rng);
  // 3 c3 (s^2 - (r1 + r2) s + r1 r2) + shift = c1 + 2 c2 s + 3 c3 s^2 (rounded: any cubic is fine).
  return {size(rng), 3 * c3 * r1 * r2 + shift, -1.5 * c3 * (r1 + r2), c3};
}

PiecePolynomial<mpq_class> exact_of(const Cubic& c) {
  PiecePolynomial<mpq_class> p;
  p.c0 = c.c0, p.c1 = c.c1, p.c2 = c.c2, p.c3 = c.c3;
  return p;
}
PiecePolynomial<Interval> interval_of(const Cubic& c) {
  PiecePolynomial<Interval> p;
  p.c0 = Interval::point(c.c0), p.c1 = Interval::point(c.c1);
  p.c2 = Interval::point(c.c2), p.c3 = Interval::point(c.c3);
  return p;
}

/// The exact chord sum over `samples` equal steps of [a, b], with a reference evaluation.
mpq_class sampled_variation(const Cubic& c, const mpq_class& a, const mpq_class& b, int samples = 200) {
  const auto q = [&](const mpq_class& s) -> mpq_class {
    return mpq_class(c.c0) + mpq_class(c.c1) * s + mpq_class(c.c2) * s * s + mpq_class(c.c3) * s * s * s;
  };
  mpq_class total = 0, previous = q(a);
  for (int i = 1; i <= samples; ++i) {
    const mpq_class value = q(a + (b - a) * mpq_class(i, samples));
    total += abs(value - previous);
    previous = value;
  }
  return total;
}

TEST(PieceVariation, NeverBelowTheSampledVariationWithoutSplitPoints) {
  int with_two_turns = 0;
  for (unsigned seed : {3u, 11u, 2718u}) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int trial = 0; trial < 60; ++trial) {
      const Cubic cubic = random_cubic(rng);
      double a = unit(rng), b = unit(rng);
      if (a > b) std::swap(a, b);
      if (trial % 3 == 0) a = 0, b = 1;
      const PiecePolynomial<mpq_class> exact_poly = exact_of(cubic);
      const mpq_class exact = piece_variation<ExactArithmetic>(
          exact_poly, evaluate_end(exact_poly, mpq_class(a)), evaluate_end(exact_poly, mpq_class(b)));
      const mpq_class sampled = sampled_variation(cubic, a, b);
      ASSERT_GE(exact, sampled) << "seed " << seed << " trial " << trial;
      const PiecePolynomial<Interval> rounded_poly = interval_of(cubic);
      const double rounded = piece_variation<IntervalArithmetic>(
          rounded_poly, evaluate_end(rounded_poly, Interval::point(a)),
          evaluate_end(rounded_poly, Interval::point(b)));
      ASSERT_GE(mpq_class(rounded), exact) << "seed " << seed << " trial " << trial;
      // Slopes at both ends of one sign but two turns inside: the d1 clause of the test matters.
      const mpq_class slope_a = exact_poly.slope(mpq_class(a)), slope_b = exact_poly.slope(mpq_class(b));
      if (sgn(slope_a) == sgn(slope_b) && sampled > abs(exact_poly.value(mpq_class(b)) - exact_poly.value(mpq_class(a)))) {
        ++with_two_turns;
      }
    }
  }
  EXPECT_GT(with_two_turns, 10);
}

TEST(PieceVariation, EqualsTheIncrementWhenTheCubicIsMonotone) {
  // q' = 3 c3 (s - r)^2 + shift with c3, shift >= 0 is non-negative: q is monotone.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0, 1);
  int checked = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const double r = unit(rng), c3 = 4 * unit(rng), shift = trial % 4 == 0 ? 0.0 : unit(rng);
    const Cubic cubic{unit(rng), 3 * c3 * r * r + shift, -3 * c3 * r, c3};
    const PiecePolynomial<mpq_class> p = exact_of(cubic);
    // The rounded coefficients may not be exactly monotone: check with the exact derivative.
    const mpq_class discriminant = p.c2 * p.c2 - 3 * p.c1 * p.c3;
    if (sgn(discriminant) > 0) continue;
    const mpq_class a(unit(rng) / 2), b(0.5 + unit(rng) / 2);
    EXPECT_EQ(piece_variation<ExactArithmetic>(p, evaluate_end(p, a), evaluate_end(p, b)),
              abs(p.value(b) - p.value(a)));
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

}  // namespace
}  // namespace grpvss::motion::detail

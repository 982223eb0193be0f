// The exact core's rounding of rational points (proofs/interference.md#rounding-the-points,
// #crossing-by-error-bound), checked against a reference written here in GMP rationals: the
// nearest double, ties toward +infinity, found by exact comparisons with the midpoints.
#include "exact/exact_rounding.hpp"
#include "exact/extended_precision.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Mpzf.h>

#include <cfenv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include <Eigen/Geometry>

#include "support/rounding_reference.hpp"

namespace grpvss::geometry {
namespace {

using Gmpq = CGAL::Gmpq;
using CGAL::Mpzf;
using testing::reference_crossing;
using testing::reference_plane_side;
using testing::reference_round;

constexpr double kInf = std::numeric_limits<double>::infinity();

Gmpq to_rational(const Mpzf& x) { return static_cast<Gmpq>(x); }

/// A double with a random significand and an exponent in [-exponent_range, exponent_range].
double random_double(std::mt19937_64& rng, int exponent_range) {
  std::uniform_real_distribution<double> mantissa(0.5, 1.0);
  std::uniform_int_distribution<int> exponent(-exponent_range, exponent_range);
  const double x = std::ldexp(mantissa(rng), exponent(rng));
  return (rng() & 1) ? -x : x;
}

TEST(RoundQuotient, FilteredAndMidpointRoundingsAreTheReferenceRounding) {
  std::mt19937_64 rng(20261125);
  for (int i = 0; i < 20000; ++i) {
    // num and den as exact sums of products of doubles, as the crossing formula makes them.
    const int range = (i % 4 == 0) ? 300 : 20;
    const Mpzf num = Mpzf(random_double(rng, range)) * Mpzf(random_double(rng, range)) -
                     Mpzf(random_double(rng, range)) * Mpzf(random_double(rng, range));
    Mpzf den = Mpzf(random_double(rng, range)) * Mpzf(random_double(rng, range)) +
               Mpzf(random_double(rng, 5));
    if (CGAL::sign(den) == CGAL::ZERO) continue;
    if (CGAL::sign(den) == CGAL::NEGATIVE) den = -den;
    const double expected = reference_round(to_rational(num) / to_rational(den));
    EXPECT_EQ(round_quotient_to_nearest(num, den), expected) << i;
    EXPECT_EQ(round_quotient_by_midpoints(num, den), expected) << i;
  }
}

TEST(RoundQuotient, ExactTiesGoUpAndNearTiesGoToTheirSide) {
  // Midpoints between consecutive doubles, including around powers of two (unequal gaps),
  // negatives and values whose first estimate lands on the wrong side.
  for (const double q : {1.0, 1.5, 0.1, -0.1, 3.0, -4.0, 1024.0, 7.25e-3, -1.0 / 3.0, 1e300}) {
    for (const double neighbour : {std::nextafter(q, kInf), std::nextafter(q, -kInf)}) {
      const double lower = std::min(q, neighbour), upper = std::max(q, neighbour);
      const Mpzf tie = Mpzf(lower) + Mpzf(upper);  // 2 x the midpoint
      const Mpzf two(2.0);
      EXPECT_EQ(round_quotient_to_nearest(tie, two), upper) << q;
      EXPECT_EQ(round_quotient_by_midpoints(tie, two), upper) << q;
      // A tiny nudge either way decides the side (the filter cannot: its enclosure spans it).
      const Mpzf nudge(std::ldexp(std::abs(q), -120));
      EXPECT_EQ(round_quotient_to_nearest(tie - nudge, two), lower) << q;
      EXPECT_EQ(round_quotient_to_nearest(tie + nudge, two), upper) << q;
    }
  }
  // A quotient that is a double is returned unchanged (residual exactly zero).
  EXPECT_EQ(round_quotient_to_nearest(Mpzf(0.75) * Mpzf(3.0), Mpzf(3.0)), 0.75);
  EXPECT_EQ(round_quotient_to_nearest(Mpzf(0.0), Mpzf(3.0)), 0.0);
}

using Vec = Eigen::Vector3d;

struct CrossingCounts {
  int answered = 0;
  int declined = 0;
};

/// Random crossings near a random centre (coordinates up to `offset`), triangle and segment
/// within `scale` of it; `tilt` scales how far the end points are from the plane (small:
/// nearly in the plane, where the bound must give up rather than guess).
CrossingCounts check_random_crossings(std::uint64_t seed, int cases, double scale, double tilt,
                                      double offset = 0.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(-scale, scale);
  std::uniform_real_distribution<double> shift(-offset, offset);
  Vec centre;
  const auto point = [&] {
    return Vec(centre.x() + coordinate(rng), centre.y() + coordinate(rng),
               centre.z() + coordinate(rng));
  };
  CrossingCounts counts;
  for (int i = 0; i < cases; ++i) {
    centre = Vec(shift(rng), shift(rng), shift(rng));
    const Vec f0 = point(), f1 = point(), f2 = point();
    const Vec normal = (f1 - f0).cross(f2 - f0).normalized();
    const Vec on_plane = f0 + 0.3 * (f1 - f0) + 0.3 * (f2 - f0);
    const Vec along = Vec(coordinate(rng), coordinate(rng), coordinate(rng)).cross(normal);
    const auto height = [&] { return tilt * scale * (0.1 + std::abs(coordinate(rng)) / scale); };
    const Vec p = on_plane + along * 0.5 + normal * height();
    const Vec q = on_plane - along * 0.3 - normal * height();
    const auto answer = crossing_rounded_by_error_bound(p, q, f0, f1, f2);
    // The filter is only asked for strict crossings; skip what rounding put on one side.
    if (reference_plane_side(p, f0, f1, f2) * reference_plane_side(q, f0, f1, f2) >= 0) continue;
    if (!answer) {
      ++counts.declined;
      continue;
    }
    ++counts.answered;
    const Vec expected = reference_crossing(p, q, f0, f1, f2);
    EXPECT_EQ(*answer, expected) << "case " << i << " scale " << scale << " tilt " << tilt;
  }
  return counts;
}

TEST(CrossingByErrorBound, EveryAnswerIsTheExactCrossingsRounding) {
  // As the verifier has them (a link-frame hull face and an obstacle edge, a few inches long,
  // up to 30 in. from the origin): the bound answers nearly all. (In the Table 3 operations
  // 96% of the crossings are answered here.)
  const CrossingCounts cell_like = check_random_crossings(6, 4000, 3.0, 0.5, 30.0);
  EXPECT_GT(cell_like.answered, 3600);
  // Large random triangles, far end points: the 11 extra bits answer most, not all.
  const CrossingCounts generic = check_random_crossings(7, 4000, 30.0, 1.0);
  EXPECT_GT(generic.answered, 2400);
  // Across magnitudes.
  const CrossingCounts tiny = check_random_crossings(8, 1000, 1e-30, 1.0);
  const CrossingCounts huge = check_random_crossings(9, 1000, 1e30, 1.0);
  EXPECT_GT(tiny.answered, 600);
  EXPECT_GT(huge.answered, 600);
  // End points within ~1e-16 of the plane: the sides are dominated by their rounding error,
  // so the bound declines every strict crossing (the exact path decides those).
  const CrossingCounts grazing = check_random_crossings(10, 1000, 30.0, 1e-17);
  EXPECT_GT(grazing.declined, 300);
  EXPECT_EQ(grazing.answered, 0);
}

TEST(CrossingByErrorBound, ExactlyRepresentableCrossingsAndTheRoundingModeGuard) {
  // Edge from (0.125, 0.125, -1) to (0.125, 0.125, 2) through x + y + z = 1: z = 0.75 exactly.
  const Vec p(0.125, 0.125, -1), q(0.125, 0.125, 2);
  const Vec f0(1, 0, 0), f1(0, 1, 0), f2(0, 0, 1);
  const auto answer = crossing_rounded_by_error_bound(p, q, f0, f1, f2);
  ASSERT_TRUE(answer.has_value());
  EXPECT_EQ(*answer, Vec(0.125, 0.125, 0.75));
  // The lemma assumes round-to-nearest: under another mode the filter declines.
  std::fesetround(FE_UPWARD);
  const auto upward = crossing_rounded_by_error_bound(p, q, f0, f1, f2);
  std::fesetround(FE_TONEAREST);
  EXPECT_FALSE(upward.has_value());
}

#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)
// The lemma assumes a 64-bit significand: with the x87 precision control set to double (as
// some libraries do), long double results are rounded to 53 bits and the filter declines.
TEST(CrossingByErrorBound, DeclinesWhenTheX87PrecisionControlIsDouble) {
  const Vec p(0.125, 0.125, -1), q(0.125, 0.125, 2);
  const Vec f0(1, 0, 0), f1(0, 1, 0), f2(0, 0, 1);
  ASSERT_TRUE(extended_precision_rounds_to_nearest());
  unsigned short control = 0;
  __asm__ volatile("fnstcw %0" : "=m"(control));
  const unsigned short double_precision = static_cast<unsigned short>((control & ~0x300) | 0x200);
  __asm__ volatile("fldcw %0" : : "m"(double_precision));
  const bool extended = extended_precision_rounds_to_nearest();
  const auto answer = crossing_rounded_by_error_bound(p, q, f0, f1, f2);
  __asm__ volatile("fldcw %0" : : "m"(control));
  EXPECT_FALSE(extended);
  EXPECT_FALSE(answer.has_value());
  EXPECT_TRUE(extended_precision_rounds_to_nearest());
}
#endif

}  // namespace
}  // namespace grpvss::geometry

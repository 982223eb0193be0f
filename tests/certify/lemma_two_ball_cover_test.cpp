// Checks proofs/two-ball-cover.md: a path of length <= r_k + r_k1 stays in the union of the
// closed balls around its end points; slightly longer paths can leave them; touching is possible
// under non-strict inequalities; every path point keeps the motion clearance g from obstacles.

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "certify/lemma_reference.hpp"

namespace {

using lemma_ref::Vec3;

std::vector<Vec3> random_polyline(std::mt19937& rng, int segments) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points{{u(rng), u(rng), u(rng)}};
  for (int s = 0; s < segments; ++s) {
    const double len = 0.05 + std::abs(u(rng));
    Vec3 dir{u(rng), u(rng), u(rng)};
    dir = lemma_ref::scale(dir, len / lemma_ref::norm(dir));
    points.push_back(lemma_ref::add(points.back(), dir));
  }
  return points;
}

// Dense samples along a polyline (the vertices included).
std::vector<Vec3> densify(const std::vector<Vec3>& poly, int per_segment) {
  std::vector<Vec3> out;
  for (std::size_t s = 0; s + 1 < poly.size(); ++s)
    for (int k = 0; k < per_segment; ++k)
      out.push_back(lemma_ref::add(poly[s], lemma_ref::scale(lemma_ref::sub(poly[s + 1], poly[s]),
                                                              static_cast<double>(k) / per_segment)));
  out.push_back(poly.back());
  return out;
}

double length_of(const std::vector<Vec3>& poly) {
  double l = 0.0;
  for (std::size_t s = 0; s + 1 < poly.size(); ++s) l += lemma_ref::norm(lemma_ref::sub(poly[s + 1], poly[s]));
  return l;
}

TEST(LemmaTwoBallCover, ShortPathsStayInTheTwoBalls) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<Vec3> path;
    if (trial % 2 == 0) {
      path = densify(random_polyline(rng, 1 + trial % 7), 50);
    } else {
      // A helix arc: a curved path like a point on a rotating link.
      const double radius = 0.2 + u01(rng), pitch = u01(rng), turns = 0.1 + 2.0 * u01(rng);
      for (int k = 0; k <= 2000; ++k) {
        const double a = 2.0 * M_PI * turns * k / 2000.0;
        path.push_back({radius * std::cos(a), radius * std::sin(a), pitch * a});
      }
    }
    const double ell = length_of(path);
    // Split the length budget at random, sometimes with spare length.
    const double r_k = ell * u01(rng);
    const double r_k1 = (ell - r_k) * (1.0 + 0.1 * (trial % 3));
    ASSERT_LE(ell, r_k + r_k1 + 1e-12 * ell);
    for (const Vec3& p : path) {
      const double d0 = lemma_ref::norm(lemma_ref::sub(p, path.front()));
      const double d1 = lemma_ref::norm(lemma_ref::sub(p, path.back()));
      EXPECT_TRUE(d0 <= r_k * (1.0 + 1e-12) + 1e-12 || d1 <= r_k1 * (1.0 + 1e-12) + 1e-12)
          << "trial " << trial << " d0 " << d0 << " r_k " << r_k << " d1 " << d1 << " r_k1 " << r_k1;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100000);
}

TEST(LemmaTwoBallCover, LongerPathLeavesTheBalls) {
  // Straight path of length 2, radii summing to 1.98: the point at arc length 1 is outside both.
  const Vec3 x0{0.0, 0.0, 0.0}, x1{2.0, 0.0, 0.0};
  const double r_k = 0.99, r_k1 = 0.99;
  bool found_outside = false;
  for (int k = 0; k <= 1000; ++k) {
    const Vec3 p = lemma_ref::scale(x1, k / 1000.0);
    const double d0 = lemma_ref::norm(lemma_ref::sub(p, x0)), d1 = lemma_ref::norm(lemma_ref::sub(p, x1));
    if (d0 > r_k && d1 > r_k1) found_outside = true;
  }
  EXPECT_TRUE(found_outside);
}

TEST(LemmaTwoBallCover, TangentFlatObstacleShowsWhyStrictnessIsNeeded) {
  // proofs/two-ball-cover.md#strictness: distances equal to the radii and length equal to their
  // sum allow contact with the flat square {x = 1, |y| <= 1, |z| <= 1}.
  using lemma_ref::Q;
  const Q r_k = 1, r_k1 = 1;
  const Q x0 = 0, x1 = 2;  // on the x axis
  const Q ell = x1 - x0;
  // Distance of each end to the square is |x - 1| (the square spans the y,z range around 0).
  const Q dist0 = 1 - x0, dist1 = x1 - 1;
  EXPECT_EQ(dist0, r_k);
  EXPECT_EQ(dist1, r_k1);
  EXPECT_EQ(ell, r_k + r_k1);  // closed-ball hypothesis holds...
  const Q midpoint = (x0 + x1) / 2;
  EXPECT_EQ(midpoint, 1);  // ...and the path point (1,0,0) lies on the obstacle.
  // Neither strictness condition S1 (ell < r_k + r_k1) nor S2 (dist > r) holds.
  EXPECT_FALSE(ell < r_k + r_k1);
  EXPECT_FALSE(dist0 > r_k && dist1 > r_k1);
}

// proofs/two-ball-cover.md#corollary-motion-clearance, in exact-enough doubles (the reference
// here is the formula, not the implementation in src/certify/motion_clearance.cpp).
double motion_clearance(double r_k, double r_k1, double bound) {
  return std::max((r_k + r_k1 - bound) / 2.0, std::max(r_k, r_k1) - bound);
}

double distance_to_cloud(const Vec3& p, const std::vector<Vec3>& cloud) {
  double d = std::numeric_limits<double>::infinity();
  for (const Vec3& o : cloud) d = std::min(d, lemma_ref::norm(lemma_ref::sub(p, o)));
  return d;
}

// Random paths (polylines, helix arcs) and obstacle point clouds; the radii are the end points'
// distances shrunk at random, the bound the path length stretched at random: every sampled
// path point is at least g from the cloud.
TEST(LemmaTwoBallCover, EveryPathPointKeepsTheMotionClearanceFromTheObstacles) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  int positive = 0, checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<Vec3> path;
    if (trial % 2 == 0) {
      path = densify(random_polyline(rng, 1 + trial % 5), 60);
    } else {
      const double radius = 0.2 + u01(rng), pitch = u01(rng), turns = 0.1 + u01(rng);
      for (int k = 0; k <= 600; ++k) {
        const double a = 2.0 * M_PI * turns * k / 600.0;
        path.push_back({radius * std::cos(a), radius * std::sin(a), pitch * a});
      }
    }
    std::vector<Vec3> cloud(1 + trial % 9);
    for (Vec3& o : cloud) o = {u(rng), u(rng), u(rng)};
    const double r_k = distance_to_cloud(path.front(), cloud) * (trial % 4 == 0 ? 1.0 : u01(rng));
    const double r_k1 = distance_to_cloud(path.back(), cloud) * (trial % 4 == 1 ? 1.0 : u01(rng));
    const double bound = length_of(path) * (1.0 + (trial % 3 == 0 ? 0.0 : u01(rng)));
    const double g = motion_clearance(r_k, r_k1, bound);
    if (g > 0.0) ++positive;
    for (const Vec3& p : path) {
      ASSERT_GE(distance_to_cloud(p, cloud), g - 1e-12 * (1.0 + bound)) << "trial " << trial;
      ++checked;
    }
  }
  EXPECT_GT(positive, 100);  // the bound says something in many cases
  EXPECT_GT(checked, 100000);
}

// The bound is attained: a point that goes out 1 and comes back (length 2) towards an obstacle
// point 2 away from its start keeps exactly 1, and g = max((2 + 2 - 2)/2, 2 - 2) = 1; the
// one-sided branch: obstacle 3 beyond a straight move of 2, g = max((3 + 1 - 2)/2, 3 - 2) = 1.
TEST(LemmaTwoBallCover, TheMotionClearanceIsAttainedByAStraightPass) {
  std::vector<Vec3> out_and_back;
  for (int k = 0; k <= 200; ++k) out_and_back.push_back({1.0 - std::abs(k - 100) / 100.0, 0.0, 0.0});
  const std::vector<Vec3> obstacle{{2.0, 0.0, 0.0}};
  double closest = std::numeric_limits<double>::infinity();
  for (const Vec3& p : out_and_back) closest = std::min(closest, distance_to_cloud(p, obstacle));
  EXPECT_DOUBLE_EQ(length_of(out_and_back), 2.0);
  EXPECT_EQ(closest, 1.0);
  EXPECT_EQ(motion_clearance(2.0, 2.0, 2.0), 1.0);

  EXPECT_EQ(motion_clearance(3.0, 1.0, 2.0), 1.0);
  EXPECT_EQ(distance_to_cloud({2.0, 0.0, 0.0}, {{3.0, 0.0, 0.0}}), 1.0);
}

// proofs/two-ball-cover.md#lemma-tolerance-along-motion: a rigid point set passing straight
// from A to B (every point's path has length |B - A| = M) with radii r_k, r_k1 at most its
// distances to an obstacle cloud at the ends, and Delta with M <= (r_k - D) + (r_k1 - D) or
// M <= max(r_k, r_k1) - D (the rule (T), here g >= Delta): at every sampled time every point of
// the expanded set (each point plus a sampled offset of length Delta) stays outside the cloud's
// points by a positive distance, and the body itself keeps Delta.
TEST(LemmaTwoBallCover, TheExpandedHullStaysClearWhenTheToleranceRuleHolds) {
  std::mt19937 rng(7545);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  std::vector<Vec3> offsets;  // unit directions (Fibonacci sphere)
  for (int k = 0; k < 64; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / 64.0, rho = std::sqrt(1.0 - z * z);
    const double a = k * M_PI * (3.0 - std::sqrt(5.0));
    offsets.push_back({rho * std::cos(a), rho * std::sin(a), z});
  }
  int held = 0;
  long long checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Vec3> body(1 + trial % 5);
    for (Vec3& p : body) p = {0.3 * u(rng) / 4.0, 0.3 * u(rng) / 4.0, 0.3 * u(rng) / 4.0};
    const Vec3 a{u(rng), u(rng), u(rng)};
    const Vec3 b = lemma_ref::add(a, lemma_ref::scale(Vec3{u(rng), u(rng), u(rng)}, 0.25 * u01(rng)));
    std::vector<Vec3> cloud(1 + trial % 7);
    for (Vec3& o : cloud) o = {u(rng), u(rng), u(rng)};
    const auto body_distance = [&](const Vec3& at) {
      double d = std::numeric_limits<double>::infinity();
      for (const Vec3& p : body) d = std::min(d, distance_to_cloud(lemma_ref::add(at, p), cloud));
      return d;
    };
    const double r_k = body_distance(a) * (trial % 3 == 0 ? 1.0 : 0.5 + 0.5 * u01(rng));
    const double r_k1 = body_distance(b) * (trial % 3 == 1 ? 1.0 : 0.5 + 0.5 * u01(rng));
    const double motion = lemma_ref::norm(lemma_ref::sub(b, a));
    const double g = motion_clearance(r_k, r_k1, motion);
    if (!(g > 0.0)) continue;
    const double delta = g * (trial % 4 == 0 ? 1.0 : u01(rng));  // (T) holds, at times tightly
    ASSERT_TRUE(motion <= (r_k - delta) + (r_k1 - delta) + 1e-12 ||
                motion <= std::max(r_k, r_k1) - delta + 1e-12);
    ++held;
    for (int k = 0; k <= 100; ++k) {
      const Vec3 at = lemma_ref::add(a, lemma_ref::scale(lemma_ref::sub(b, a), k / 100.0));
      ASSERT_GE(body_distance(at), delta - 1e-12) << "trial " << trial;
      for (const Vec3& p : body) {
        for (const Vec3& direction : offsets) {
          const Vec3 expanded = lemma_ref::add(lemma_ref::add(at, p), lemma_ref::scale(direction, delta));
          ASSERT_GE(distance_to_cloud(expanded, cloud), -1e-12) << "trial " << trial;
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(held, 150);
  EXPECT_GT(checked, 1000000);
}

// The rule is tight: a point that goes out 1 towards an obstacle point 2 away and comes back
// (M = 2, r_k = r_k1 = 2, g = 1) keeps exactly 1, so the point expanded by Delta = 1 touches the
// obstacle, and by any Delta > 1 (where (T) fails) it reaches into it.
TEST(LemmaTwoBallCover, TheToleranceRuleIsTightForAStraightPass) {
  const std::vector<Vec3> obstacle{{2.0, 0.0, 0.0}};
  const double r = 2.0, motion = 2.0;
  EXPECT_TRUE(motion <= (r - 1.0) + (r - 1.0));
  EXPECT_FALSE(motion <= (r - 1.0625) + (r - 1.0625) || motion <= r - 1.0625);
  double closest = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= 200; ++k) {
    const Vec3 p{1.0 - std::abs(k - 100) / 100.0, 0.0, 0.0};
    closest = std::min(closest, distance_to_cloud(p, obstacle));
  }
  EXPECT_EQ(closest, 1.0);  // the expanded point (Delta = 1) reaches the obstacle exactly
  EXPECT_LT(closest - 1.0625, 0.0);  // Delta = 1.0625: it reaches into it
}

// proofs/two-ball-cover.md#corollary-self-tolerance-along-motion: two bodies both moving (each
// translated along a random polyline, so every point's path is as long as the polyline), the
// distances d_k, d_k1 at the ends shrunk at random and M the sum of the two path lengths. Where
// (T) holds for Delta (drawn up to g), the bodies stay at least Delta apart at every sample.
TEST(LemmaTwoBallCover, TwoMovingBodiesKeepTheGapWhenTheToleranceRuleHolds) {
  std::mt19937 rng(2014);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int held = 0;
  long long checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<Vec3> body_a(1 + trial % 4), body_b(1 + trial % 5);
    for (Vec3& p : body_a) p = {0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)};
    for (Vec3& p : body_b) p = {3.0 + 0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)};
    const std::vector<Vec3> path_a = densify(random_polyline(rng, 1 + trial % 3), 40);
    const std::vector<Vec3> path_b = densify(random_polyline(rng, 1 + trial % 2), 40);
    const auto gap_at = [&](double t) {  // t in [0, 1] along both densified paths
      const Vec3& shift_a = path_a[static_cast<std::size_t>(std::lround(t * (path_a.size() - 1)))];
      const Vec3& shift_b = path_b[static_cast<std::size_t>(std::lround(t * (path_b.size() - 1)))];
      double d = std::numeric_limits<double>::infinity();
      for (const Vec3& a : body_a) {
        for (const Vec3& b : body_b) {
          d = std::min(d, lemma_ref::norm(lemma_ref::sub(lemma_ref::add(a, lemma_ref::sub(shift_a, path_a.front())),
                                                         lemma_ref::add(b, lemma_ref::sub(shift_b, path_b.front())))));
        }
      }
      return d;
    };
    const double d_k = gap_at(0.0) * (trial % 3 == 0 ? 1.0 : 0.6 + 0.4 * u01(rng));
    const double d_k1 = gap_at(1.0) * (trial % 3 == 1 ? 1.0 : 0.6 + 0.4 * u01(rng));
    const double relative_motion = length_of(path_a) + length_of(path_b);
    const double g = motion_clearance(d_k, d_k1, relative_motion);
    if (!(g > 0.0)) continue;
    const double delta = g * (trial % 4 == 0 ? 1.0 : u01(rng));  // (T) holds, at times tightly
    ASSERT_TRUE(relative_motion <= (d_k - delta) + (d_k1 - delta) + 1e-12 ||
                relative_motion <= std::max(d_k, d_k1) - delta + 1e-12);
    ++held;
    // Samples of one joint motion: both bodies move along their paths as t goes 0 -> 1.
    for (int k = 0; k <= 240; ++k) {
      ASSERT_GE(gap_at(k / 240.0), delta - 1e-12) << "trial " << trial << " k " << k;
      ++checked;
    }
  }
  EXPECT_GT(held, 100);
  EXPECT_GT(checked, 20000);
}

// Tight for two moving bodies too: a (at 0) goes 0.5 towards b (at 2) and back, b 0.5 towards a
// and back: M = 1 + 1 = 2, d_k = d_k1 = 2, g = (2 + 2 - 2) / 2 = 1, and the closest approach is
// exactly 1 at the middle; (T) holds for Delta = 1 and fails for any larger Delta.
TEST(LemmaTwoBallCover, TheSelfToleranceRuleIsTightForTwoPointsApproachingEachOther) {
  const double d = 2.0, relative_motion = 2.0;
  EXPECT_TRUE(relative_motion <= (d - 1.0) + (d - 1.0));
  EXPECT_FALSE(relative_motion <= (d - 1.0625) + (d - 1.0625) || relative_motion <= d - 1.0625);
  double closest = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= 200; ++k) {
    const double out = 0.5 - std::abs(k - 100) / 200.0;  // 0 -> 0.5 -> 0
    const Vec3 a{out, 0.0, 0.0}, b{2.0 - out, 0.0, 0.0};
    closest = std::min(closest, lemma_ref::norm(lemma_ref::sub(b, a)));
  }
  EXPECT_EQ(closest, 1.0);  // a expanded by Delta = 1 reaches b exactly
  EXPECT_LT(closest - 1.0625, 0.0);  // Delta = 1.0625: it reaches past b
}

}  // namespace

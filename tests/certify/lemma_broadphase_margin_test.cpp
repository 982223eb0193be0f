// Checks proofs/fast-path.md#broadphase-margin with an independent implementation: when the
// obstacle's exact box misses the query box inflated (outward) by m, every pair of hull points is
// farther apart than m; and boxes that only touch the inflated box must be kept.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "certify/lemma_reference.hpp"

namespace {

using lemma_ref::Vec3;

struct Box {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
};

Box box_of(const std::vector<Vec3>& pts) {
  Box b;
  for (const Vec3& p : pts)
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = std::min(b.lo[k], p[k]);
      b.hi[k] = std::max(b.hi[k], p[k]);
    }
  return b;
}

// Outward rounding without changing the FPU mode: one step away from the rounded-to-nearest value.
Box inflate(const Box& b, double m) {
  Box out;
  for (int k = 0; k < 3; ++k) {
    out.lo[k] = std::nextafter(b.lo[k] - m, -std::numeric_limits<double>::infinity());
    out.hi[k] = std::nextafter(b.hi[k] + m, std::numeric_limits<double>::infinity());
  }
  return out;
}

bool overlap(const Box& a, const Box& b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

TEST(LemmaBroadphaseMargin, MissedBoxesAreFartherThanMargin) {
  std::mt19937 rng(1111);
  std::uniform_real_distribution<double> u(-1.0, 1.0), u01(0.0, 1.0);
  int missed = 0, kept = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<Vec3> query, obstacle;
    const Vec3 shift{3 * u(rng), 3 * u(rng), 3 * u(rng)};
    for (int k = 0; k < 6; ++k) {
      query.push_back({u(rng), u(rng), u(rng)});
      obstacle.push_back(lemma_ref::add(shift, {u(rng), u(rng), u(rng)}));
    }
    const double m = 1.5 * u01(rng);
    if (overlap(box_of(obstacle), inflate(box_of(query), m))) {
      ++kept;
      continue;
    }
    ++missed;
    // Every point pair (vertices and random hull points) is farther than m; the largest
    // axis separation alone already exceeds m.
    double closest = 1e300;
    for (const Vec3& a : query)
      for (const Vec3& b : obstacle) closest = std::min(closest, lemma_ref::norm(lemma_ref::sub(a, b)));
    EXPECT_GT(closest, m) << "trial " << trial;
    const Box bq = box_of(query), bo = box_of(obstacle);
    double axis_gap = 0.0;
    for (int k = 0; k < 3; ++k) axis_gap = std::max({axis_gap, bo.lo[k] - bq.hi[k], bq.lo[k] - bo.hi[k]});
    EXPECT_GT(axis_gap, m);
  }
  EXPECT_GT(missed, 500);
  EXPECT_GT(kept, 500);
}

TEST(LemmaBroadphaseMargin, TouchingInflatedBoxIsKept) {
  // Query point at the origin, obstacle point at exactly distance m on the x axis: the distance
  // is not > m, so the obstacle must be returned (closed-box overlap).
  const double m = 0.75;
  const Box query = box_of({{0, 0, 0}}), obstacle = box_of({{m, 0, 0}, {m + 1, 1, 1}});
  EXPECT_TRUE(overlap(obstacle, inflate(query, m)));
}

}  // namespace

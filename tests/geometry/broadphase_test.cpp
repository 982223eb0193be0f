#include "grpvss/geometry/broadphase.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "support/random_shapes.hpp"

namespace grpvss::geometry {
namespace {

using Eigen::Vector3d;

// Brute force reference: distance along the best axis between the two exact boxes,
// computed in long double (differences of doubles are exact there for these magnitudes).
long double axis_gap(const Aabb& x, const Aabb& y) {
  long double gap = 0;
  for (int k = 0; k < 3; ++k) {
    gap = std::max(gap, static_cast<long double>(y.lo[k]) - x.hi[k]);
    gap = std::max(gap, static_cast<long double>(x.lo[k]) - y.hi[k]);
  }
  return gap;
}

TEST(Broadphase, NeverDropsAnObstacleWithinTheMargin) {
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> position(-60.0, 60.0);
  std::vector<std::vector<Vector3d>> obstacles;
  for (int k = 0; k < 500; ++k) {
    obstacles.push_back(
        test::random_prism(rng, Vector3d(position(rng), position(rng), position(rng)), 2.0));
  }
  const StaticObstacleIndex index(obstacles);
  ASSERT_EQ(index.size(), 500);
  std::vector<int> found;
  for (int query = 0; query < 300; ++query) {
    const auto hull = test::random_prism(
        rng, Vector3d(position(rng), position(rng), position(rng)), 3.0);
    const double margin = 0.25 * (query % 20);
    const Aabb box = Aabb::of_points(hull);
    index.candidates(box, margin, found);
    std::vector<int> expected;
    for (int k = 0; k < 500; ++k) {
      if (axis_gap(box, Aabb::of_points(obstacles[k])) <= margin) expected.push_back(k);
    }
    EXPECT_EQ(found, expected) << "query " << query;
    // Every dropped obstacle is farther than the margin from every hull point.
    for (int k = 0; k < 500; ++k) {
      if (std::binary_search(found.begin(), found.end(), k)) continue;
      EXPECT_GT(axis_gap(box, index.box(k)), margin);
    }
  }
}

// A probe walks the tree once for a box with room to move, then filters that answer while the
// hull's inflated box stays inside: the filter must give exactly the tree's answer (the same
// obstacles, in the same order), against the brute-force reference too.
TEST(Broadphase, CandidatesAmongAnEnclosingBoxsAnswerAreTheTreesAnswer) {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> position(-30.0, 30.0);
  std::uniform_real_distribution<double> drift(-1.0, 1.0);
  std::vector<std::vector<Vector3d>> obstacles;
  for (int k = 0; k < 300; ++k) {
    obstacles.push_back(test::random_prism(rng, Vector3d(position(rng), position(rng), position(rng)), 2.0));
  }
  const StaticObstacleIndex index(obstacles);
  std::vector<int> enclosing, filtered, walked;
  int filtered_queries = 0;
  for (int walk = 0; walk < 40; ++walk) {
    Vector3d center(position(rng), position(rng), position(rng));
    const double margin = 0.5 + 0.25 * (walk % 8);
    Aabb room;
    for (int step = 0; step < 25; ++step, center += Vector3d(drift(rng), drift(rng), drift(rng))) {
      const Aabb box = Aabb::of_points(test::random_prism(rng, center, 3.0));
      const Aabb inflated = box.inflated(margin);
      if (step == 0 || !room.contains(inflated)) {
        room = inflated.inflated(margin);
        index.candidates(room, 0.0, enclosing);
      } else {
        ++filtered_queries;
      }
      index.candidates_among(enclosing, box, margin, filtered);
      index.candidates(box, margin, walked);
      EXPECT_EQ(filtered, walked) << "walk " << walk << " step " << step;
      std::vector<int> expected;
      for (int k = 0; k < 300; ++k) {
        if (axis_gap(box, Aabb::of_points(obstacles[static_cast<std::size_t>(k)])) <= margin) expected.push_back(k);
      }
      EXPECT_EQ(filtered, expected) << "walk " << walk << " step " << step;
    }
  }
  EXPECT_GT(filtered_queries, 200);  // the filter is exercised, not only fresh walks
}

TEST(Broadphase, ContainsIsExactAndClosed) {
  Aabb outer;
  outer.lo = Vector3d(0, 0, 0);
  outer.hi = Vector3d(1, 1, 1);
  Aabb inner = outer;
  EXPECT_TRUE(outer.contains(inner));  // closed: equal boxes
  inner.hi.z() = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(outer.contains(inner));
  inner.hi.z() = 0.5;
  inner.lo.x() = std::nextafter(0.0, -1.0);
  EXPECT_FALSE(outer.contains(inner));
  EXPECT_FALSE(Aabb{}.contains(outer));  // the empty box contains no box
}

TEST(Broadphase, TouchingBoxesAtExactlyTheMarginAreReturned) {
  const std::vector<std::vector<Vector3d>> obstacles = {test::cube(Vector3d(3, 0, 0), 1.0),
                                                        test::cube(Vector3d(10, 0, 0), 1.0)};
  const StaticObstacleIndex index(obstacles);
  const auto hull = test::cube(Vector3d(0, 0, 0), 1.0);  // gap 2 to the first cube
  EXPECT_EQ(index.candidates(hull, 2.0), std::vector<int>({0}));
  // 1 + 1.9375 is exact, so nothing rounds and the box stops short of the cube.
  EXPECT_EQ(index.candidates(hull, 1.9375), std::vector<int>());
  // Gap 9 to the second cube.
  EXPECT_EQ(index.candidates(hull, 8.9375), std::vector<int>({0}));
  EXPECT_EQ(index.candidates(hull, 9.0), std::vector<int>({0, 1}));
}

TEST(Broadphase, InflationRoundsOutward) {
  Aabb box;
  box.lo = Vector3d(0.1, 0.1, 0.1);
  box.hi = Vector3d(0.7, 0.7, 0.7);
  const Aabb grown = box.inflated(0.2);
  for (int k = 0; k < 3; ++k) {
    EXPECT_GE(static_cast<long double>(grown.hi[k]), static_cast<long double>(0.7) + 0.2);
    EXPECT_LE(static_cast<long double>(grown.lo[k]),
              static_cast<long double>(0.1) - static_cast<long double>(0.2));
  }
  EXPECT_THROW(box.inflated(-1.0), std::invalid_argument);
  const std::vector<std::vector<Vector3d>> with_empty = {test::cube(Vector3d::Zero(), 1.0), {}};
  EXPECT_THROW(StaticObstacleIndex{with_empty}, std::invalid_argument);
}

}  // namespace
}  // namespace grpvss::geometry

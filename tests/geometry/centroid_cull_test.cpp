#include "grpvss/geometry/centroid_cull.hpp"

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/geometry/gjk.hpp"
#include "support/random_shapes.hpp"

namespace grpvss::geometry {
namespace {

using Eigen::Vector3d;

// The two obstacles of thesis Appendix A (data/ibm7545/environment.txt), read simply: three
// header lines, then 16 "x,y,z" lines per obstacle.
std::vector<std::vector<Vector3d>> thesis_obstacles() {
  std::ifstream in(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/environment.txt");
  std::string line;
  for (int k = 0; k < 3; ++k) std::getline(in, line);
  std::vector<std::vector<Vector3d>> obstacles(2);
  for (int k = 0; k < 32 && std::getline(in, line); ++k) {
    for (char& c : line) if (c == ',') c = ' ';
    std::istringstream fields(line);
    Vector3d p;
    fields >> p.x() >> p.y() >> p.z();
    obstacles[k / 16].push_back(p);
  }
  return obstacles;
}

TEST(CentroidCull, ThesisFormulaNumbersOnTheTwoThesisObstacles) {
  const auto obstacles = thesis_obstacles();
  ASSERT_EQ(obstacles[0].size(), 16u);
  ASSERT_EQ(obstacles[1].size(), 16u);
  const CentroidSphere s0 = thesis_centroid_sphere(obstacles[0]);
  const CentroidSphere s1 = thesis_centroid_sphere(obstacles[1]);
  // Eq. 4-19 by hand: coordinate sums 280, 280, 280 and -232, 200, 280 over 16 vertices.
  EXPECT_EQ(s0.centroid, Vector3d(17.5, 17.5, 17.5));
  EXPECT_EQ(s1.centroid, Vector3d(-14.5, 12.5, 17.5));
  // Eq. 4-20: the corner (15,15,15) is (-2.5,-2.5,-2.5) from the centroid; (-12,10,15) is
  // (2.5,-2.5,-2.5) from the other.
  EXPECT_DOUBLE_EQ(s0.radius, std::sqrt(18.75));
  EXPECT_DOUBLE_EQ(s1.radius, std::sqrt(18.75));
  // Eq. 4-21: (32, 5, 0) apart. Eq. 4-22 with the thesis tolerance 0.5.
  const ThesisCullRecord record = thesis_prejudge(s0, s1, 0.5);
  EXPECT_DOUBLE_EQ(record.centroid_distance, std::sqrt(1049.0));
  EXPECT_TRUE(record.culled);
  // Not culled once the tolerance exceeds DIS - D_0 - D_1 = 32.388 - 8.660 = 23.73.
  EXPECT_TRUE(thesis_prejudge(s0, s1, 23.7).culled);
  EXPECT_FALSE(thesis_prejudge(s0, s1, 23.8).culled);
}

TEST(CentroidCull, CertifiedSphereContainsEveryPointAndIsTight) {
  std::mt19937_64 rng(4242);
  for (int trial = 0; trial < 1000; ++trial) {
    const auto points = test::random_prism(rng, Vector3d(1e3, -2e2, 7.0), 3.0);
    const CertifiedSphere certified = certified_sphere(points);
    const CentroidSphere thesis = thesis_centroid_sphere(points);
    EXPECT_EQ(certified.center, thesis.centroid);
    // Containment checked in long double (64-bit mantissa): squares of the 53-bit
    // differences are exact there up to one rounding, far below the margin we test.
    for (const auto& p : points) {
      long double d2 = 0;
      for (int k = 0; k < 3; ++k) {
        const long double d = static_cast<long double>(p[k]) - certified.center[k];
        d2 += d * d;
      }
      const long double r = certified.radius_upper;
      EXPECT_LE(d2, r * r);
    }
    EXPECT_GE(certified.radius_upper, thesis.radius);
    EXPECT_LE(certified.radius_upper, thesis.radius * (1 + 1e-14));
  }
}

TEST(CentroidCull, CertifiedCullIsAProvenLowerBoundOfTheHullDistance) {
  std::mt19937_64 rng(777);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int culled = 0, kept = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const auto a = test::random_prism(rng, Vector3d::Zero(), 1.0);
    const Vector3d c(unit(rng), unit(rng), unit(rng));
    const auto b = test::random_prism(rng, 4.0 * c, 1.0);
    const CertifiedCullRecord record =
        certified_sphere_cull(certified_sphere(a), certified_sphere(b), 0.5);
    if (!record.culled) {
      ++kept;
      EXPECT_LT(record.sphere_gap_lower, 0.5);
      continue;
    }
    ++culled;
    EXPECT_GE(record.sphere_gap_lower, 0.5);
    // GJK's closest points are points of the hulls, so their distance bounds the true
    // distance from above; the cull's bound must not exceed it.
    const GjkResult g = gjk(a, b);
    EXPECT_LE(record.sphere_gap_lower, (g.closest_a - g.closest_b).norm());
  }
  EXPECT_GT(culled, 100);
  EXPECT_GT(kept, 100);
}

TEST(CentroidCull, CertifiedCullNeverCullsOverlapOrZeroGap) {
  const auto a = test::cube(Vector3d::Zero(), 1.0);
  const auto b = test::cube(Vector3d(0.5, 0, 0), 1.0);
  EXPECT_FALSE(certified_sphere_cull(certified_sphere(a), certified_sphere(b), 0.0).culled);
  EXPECT_THROW(certified_sphere({}), std::invalid_argument);
}

}  // namespace
}  // namespace grpvss::geometry

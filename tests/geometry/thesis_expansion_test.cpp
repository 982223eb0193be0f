// The thesis's expansion (Eq. 4-1 .. 4-12) against hand-computed and closed-form references.
#include "grpvss/geometry/thesis_expansion.hpp"
#include "grpvss/io/robot_file.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace grpvss::geometry {
namespace {

/// Rectangle-with-midpoints prism x in [1,5], y in [1,3], z in [1,4] (like most IBM 7545
/// hulls: corners plus edge midpoints, so every other pair of neighbouring edges is collinear).
/// `counter_clockwise` lists the caps counter-clockwise seen from +z.
HullPoints box_prism(double z_a, double z_b, bool counter_clockwise = true) {
  const std::array<Eigen::Vector2d, 8> ring = {
      Eigen::Vector2d(1, 1), Eigen::Vector2d(3, 1), Eigen::Vector2d(5, 1),
      Eigen::Vector2d(5, 2), Eigen::Vector2d(5, 3), Eigen::Vector2d(3, 3),
      Eigen::Vector2d(1, 3), Eigen::Vector2d(1, 2)};
  HullPoints hull;
  for (double z : {z_a, z_b}) {
    for (int i = 0; i < 8; ++i) {
      const Eigen::Vector2d& q = ring[counter_clockwise ? i : (8 - i) % 8];
      hull.points.emplace_back(q.x(), q.y(), z);
    }
  }
  return hull;
}

/// The box expanded by 0.5 by hand: every in-plane coordinate moves 0.5 outward, the caps
/// move 0.5 away from each other, midpoints stay midpoints.
std::array<Eigen::Vector3d, 16> box_prism_expanded_by_half() {
  const std::array<Eigen::Vector2d, 8> ring = {
      Eigen::Vector2d(0.5, 0.5), Eigen::Vector2d(3, 0.5), Eigen::Vector2d(5.5, 0.5),
      Eigen::Vector2d(5.5, 2),   Eigen::Vector2d(5.5, 3.5), Eigen::Vector2d(3, 3.5),
      Eigen::Vector2d(0.5, 3.5), Eigen::Vector2d(0.5, 2)};
  std::array<Eigen::Vector3d, 16> expected;
  for (int i = 0; i < 8; ++i) {
    expected[i] = Eigen::Vector3d(ring[i].x(), ring[i].y(), 0.5);
    expected[i + 8] = Eigen::Vector3d(ring[i].x(), ring[i].y(), 4.5);
  }
  return expected;
}

template <typename Scalar>
void expect_box_expanded_exactly() {
  const auto result = expand_prism_as_thesis<Scalar>(box_prism(1.0, 4.0), 0.5);
  const auto expected = box_prism_expanded_by_half();
  for (int k = 0; k < 16; ++k) {
    // Every number here is dyadic, so both precisions must hit it exactly.
    EXPECT_EQ(result.vertices[k].template cast<double>(), expected[k]) << "vertex " << k;
    EXPECT_EQ(result.midpoint_gaps[k], Scalar(0)) << "vertex " << k;
    // Midpoint vertices (odd indices) join collinear edges: DENO == 0.
    EXPECT_EQ(result.parallel_lines[k], k % 2 == 1) << "vertex " << k;
  }
  EXPECT_EQ(result.max_midpoint_gap, Scalar(0));
  EXPECT_EQ(result.origin_on_cap_plane, 0);
  EXPECT_EQ(result.degenerate_in_plane_sign, 0);
  EXPECT_EQ(result.in_plane_minus, 0);
}

TEST(ThesisExpansion, BoxPrismExpandsToHandComputedVerticesInDouble) {
  expect_box_expanded_exactly<double>();
}

TEST(ThesisExpansion, BoxPrismExpandsToHandComputedVerticesInFloat) {
  expect_box_expanded_exactly<float>();
}

TEST(ThesisExpansion, ClockwiseCapsGiveTheSameBox) {
  // The Newell normal flips with the vertex order; the Eq. 4-2 sign rule compensates.
  const auto result = expand_prism_as_thesis<double>(box_prism(1.0, 4.0, false), 0.5);
  const auto expected = box_prism_expanded_by_half();
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(result.vertices[i], expected[(8 - i) % 8]) << "vertex " << i;
    EXPECT_EQ(result.vertices[i + 8], expected[8 + (8 - i) % 8]) << "vertex " << i + 8;
  }
}

TEST(ThesisExpansion, OriginOnCapPlaneFallsThroughToMinusAsTheTextSays) {
  // Cap A at z = 0 contains the origin: the Eq. 4-2 rule's "otherwise" picks "-". With a
  // counter-clockwise cap (N = +z) "-" happens to step away from the hull (z = -0.5) ...
  const auto ccw = expand_prism_as_thesis<double>(box_prism(0.0, 3.0, true), 0.5);
  EXPECT_EQ(ccw.origin_on_cap_plane, 8);
  for (int k = 0; k < 8; ++k) EXPECT_EQ(ccw.vertices[k].z(), -0.5) << "vertex " << k;
  for (int k = 8; k < 16; ++k) EXPECT_EQ(ccw.vertices[k].z(), 3.5) << "vertex " << k;
  // ... with a clockwise cap (N = -z) the same rule steps INTO the hull (z = +0.5).
  const auto cw = expand_prism_as_thesis<double>(box_prism(0.0, 3.0, false), 0.5);
  EXPECT_EQ(cw.origin_on_cap_plane, 8);
  for (int k = 0; k < 8; ++k) EXPECT_EQ(cw.vertices[k].z(), 0.5) << "vertex " << k;
  for (int k = 8; k < 16; ++k) EXPECT_EQ(cw.vertices[k].z(), 3.5) << "vertex " << k;
}

/// A strictly convex octagon prism (right prism), rotated into a general orientation.
struct RotatedOctagon {
  HullPoints hull;
  Eigen::Matrix3d rotation;
  Eigen::Vector3d translation;
  std::array<Eigen::Vector2d, 8> ring;
  double height = 0;
};

RotatedOctagon rotated_octagon() {
  RotatedOctagon o;
  o.ring = {Eigen::Vector2d(3.0, 0.4),  Eigen::Vector2d(2.1, 2.3),  Eigen::Vector2d(0.2, 3.1),
            Eigen::Vector2d(-1.9, 2.2), Eigen::Vector2d(-2.8, 0.1), Eigen::Vector2d(-2.0, -2.1),
            Eigen::Vector2d(0.3, -2.9), Eigen::Vector2d(2.2, -1.8)};
  o.rotation = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
                Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  o.translation = Eigen::Vector3d(10.3, -7.1, 25.7);
  o.height = 6.5;
  for (double z : {0.0, o.height}) {
    for (const auto& q : o.ring) {
      o.hull.points.push_back(o.rotation * Eigen::Vector3d(q.x(), q.y(), z) + o.translation);
    }
  }
  return o;
}

/// Closed form, in long double: a convex polygon corner with outward unit edge normals n1, n2
/// moves to V + Delta (n1 + n2) / (1 + n1.n2) (mitre), and the caps move Delta outward.
std::array<Eigen::Vector3d, 16> rotated_octagon_reference(const RotatedOctagon& o, double delta) {
  using V2 = Eigen::Matrix<long double, 2, 1>;
  std::array<Eigen::Vector3d, 16> out;
  auto outward = [&](int from, int to) {  // counter-clockwise ring: outward = (dy, -dx)
    const V2 d = (o.ring[to] - o.ring[from]).cast<long double>();
    return V2(d.y(), -d.x()).normalized();
  };
  for (int k = 0; k < 8; ++k) {
    const V2 n1 = outward((k + 7) % 8, k);
    const V2 n2 = outward(k, (k + 1) % 8);
    const V2 v = o.ring[k].cast<long double>() + (n1 + n2) * (delta / (1.0L + n1.dot(n2)));
    for (int cap = 0; cap < 2; ++cap) {
      const long double z = cap == 0 ? -delta : o.height + delta;
      const Eigen::Matrix<long double, 3, 1> local(v.x(), v.y(), z);
      out[k + 8 * cap] = (o.rotation.cast<long double>() * local +
                          o.translation.cast<long double>())
                             .cast<double>();
    }
  }
  return out;
}

TEST(ThesisExpansion, RotatedOctagonMatchesMitreClosedFormInDouble) {
  const RotatedOctagon o = rotated_octagon();
  const auto result = expand_prism_as_thesis<double>(o.hull, 0.75);
  const auto expected = rotated_octagon_reference(o, 0.75);
  for (int k = 0; k < 16; ++k) {
    EXPECT_LT((result.vertices[k] - expected[k]).norm(), 1e-12) << "vertex " << k;
    EXPECT_FALSE(result.parallel_lines[k]);
  }
  EXPECT_LT(result.max_midpoint_gap, 1e-13);
}

TEST(ThesisExpansion, SinglePrecisionDeviatesAtFloatRoundingLevelOnly) {
  const RotatedOctagon o = rotated_octagon();
  const auto single = expand_prism_as_thesis<float>(o.hull, 0.75);
  const auto twice = expand_prism_as_thesis<double>(o.hull, 0.75);
  const auto expected = rotated_octagon_reference(o, 0.75);
  double largest_deviation = 0;
  for (int k = 0; k < 16; ++k) {
    const double deviation = (single.vertices[k].cast<double>() - expected[k]).norm();
    largest_deviation = std::max(largest_deviation, deviation);
  }
  // Coordinates are ~30, float epsilon 1.2e-7: a few ulps, far above double's error, far below
  // any tolerance.
  EXPECT_GT(largest_deviation, 1e-7);
  EXPECT_LT(largest_deviation, 2e-5);
  // Rotated caps are not exactly representable planes in float: the lines miss each other by
  // a float-rounding-sized gap (the thesis saw < 3e-6), double's gap is ~1e9 times smaller.
  EXPECT_GT(single.max_midpoint_gap, 0.0f);
  EXPECT_LT(single.max_midpoint_gap, 1e-5f);
  EXPECT_LT(twice.max_midpoint_gap, 1e-13);
  EXPECT_GT(static_cast<double>(single.max_midpoint_gap), 1e3 * twice.max_midpoint_gap);
}

TEST(ThesisExpansion, NewellNormalMakesEq41SelectPlusOnEveryIbm7545Cap) {
  // docs/expansion-audit.md: (P3-P2) x N points out of a convex cap when N is Newell's normal,
  // so the ambiguous "or" of Eq. 4-1's sign rule never matters on this data.
  const RobotModel robot =
      io::read_robot_file(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/robot.txt");
  int hulls = 0;
  for (const Link& link : robot.links) {
    for (const HullPoints& hull : link.hulls) {
      ++hulls;
      EXPECT_EQ(expand_prism_as_thesis<float>(hull, 0.5).in_plane_minus, 0);
      EXPECT_EQ(expand_prism_as_thesis<double>(hull, 1.0).in_plane_minus, 0);
      EXPECT_EQ(expand_prism_as_thesis<double>(hull, 1.0).degenerate_in_plane_sign, 0);
    }
  }
  EXPECT_EQ(hulls, 11);
  const auto clockwise = expand_prism_as_thesis<double>(box_prism(1.0, 4.0, false), 0.5);
  EXPECT_EQ(clockwise.in_plane_minus, 0);
}

TEST(ThesisExpansion, RejectsWrongVertexCountAndNonPositiveTolerance) {
  HullPoints fifteen = box_prism(1.0, 4.0);
  fifteen.points.pop_back();
  EXPECT_THROW(expand_prism_as_thesis<double>(fifteen, 0.5), std::invalid_argument);
  EXPECT_THROW(expand_prism_as_thesis<float>(box_prism(1.0, 4.0), 0.0), std::invalid_argument);
  EXPECT_THROW(expand_prism_as_thesis<double>(box_prism(1.0, 4.0), -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace grpvss::geometry

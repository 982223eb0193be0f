/// \file
/// \brief Checks of the inequalities in proofs/shape-containment.md against independent
/// references (CGAL hulls in tests/support, exact rationals written here).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "geometry/mesh_fixtures.hpp"
#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/exact_cover_check.hpp"
#include "grpvss/exact/shape_containment.hpp"
#include "support/angles.hpp"
#include "support/geometry_reference.hpp"

namespace grpvss::geometry {
namespace {

using grpvss::test::kPi;

testing::Points random_points(std::mt19937_64& rng, int n, double spread) {
  std::uniform_real_distribution<double> u(-spread, spread);
  testing::Points p;
  for (int i = 0; i < n; ++i) p.emplace_back(u(rng), u(rng), u(rng));
  return p;
}

// proofs/shape-containment.md#lemma-support-function, box: the box is conv(its 8 corners),
// so the support test must agree exactly with "every corner inside" (independent hull).
TEST(LemmaShapeContainment, BoxSupportTestEqualsCornersInsideAnIndependentHull) {
  std::mt19937_64 rng(101);
  std::uniform_real_distribution<double> size(0.2, 2.5);
  int inside = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const testing::Points pts = random_points(rng, 14, 1.6);
    const ConvexPolytope p = ConvexPolytope::from_points(pts);
    const Eigen::Vector3d s(size(rng), size(rng), size(rng));
    const testing::Points corners = testing::box(-s / 2, s / 2);
    const bool reference = testing::count_points_outside_hull_exactly(pts, corners) == 0;
    EXPECT_EQ(box_inside_exactly(p, s), reference) << "trial " << trial;
    inside += reference ? 1 : 0;
  }
  EXPECT_GT(inside, 10);  // both outcomes occur
  EXPECT_LT(inside, 190);
}

// Sphere: the support test must agree with the independent Gmpzf ball-sum reference.
TEST(LemmaShapeContainment, SphereSupportTestEqualsTheIndependentBallReference) {
  std::mt19937_64 rng(102);
  std::uniform_real_distribution<double> radius(0.1, 1.5);
  int inside = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const testing::Points pts = random_points(rng, 16, 1.8);
    const ConvexPolytope p = ConvexPolytope::from_points(pts);
    const double r = radius(rng);
    const bool reference = testing::reference_contains_ball_sum(pts, {Eigen::Vector3d::Zero()}, r);
    EXPECT_EQ(sphere_inside_exactly(p, r), reference) << "trial " << trial;
    inside += reference ? 1 : 0;
  }
  EXPECT_GT(inside, 10);
  EXPECT_LT(inside, 190);
}

// Cylinder: accepted => every sampled rim point (the support maximizers lie on the rims)
// is inside; rejected => some sampled rim or cap point is outside.
TEST(LemmaShapeContainment, CylinderSupportTestAgreesWithSampledRimPoints) {
  std::mt19937_64 rng(103);
  std::uniform_real_distribution<double> dim(0.2, 1.6);
  int accepted = 0, rejected = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const testing::Points pts = random_points(rng, 18, 1.7);
    const ConvexPolytope p = ConvexPolytope::from_points(pts);
    const double r = dim(rng), l = 2 * dim(rng);
    testing::Points rim;
    for (int k = 0; k < 720; ++k) {
      const double a = 2 * kPi * k / 720;
      for (const double z : {-l / 2, l / 2}) {
        rim.emplace_back(r * (1 - 1e-9) * std::cos(a), r * (1 - 1e-9) * std::sin(a), z * (1 - 1e-9));
      }
    }
    const int outside = testing::count_points_outside_hull_exactly(pts, rim);
    if (cylinder_inside_exactly(p, r, l)) {
      ++accepted;
      EXPECT_EQ(outside, 0) << "trial " << trial;
    } else {
      ++rejected;
      EXPECT_GT(outside, 0) << "trial " << trial;
    }
  }
  EXPECT_GT(accepted, 5);
  EXPECT_GT(rejected, 5);
}

// ---- exact cover (proofs/shape-containment.md#lemma-exact-cover) ----------------------------

/// A box piece with the fixture's 12 outward triangles, exact vertices.
RationalPiece box_piece(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const TriangleMesh mesh = testing::meshes::box(lo, hi);
  RationalPiece piece;
  for (const auto& v : mesh.vertices) piece.vertices.push_back({v.x(), v.y(), v.z()});
  piece.triangles = mesh.triangles;
  return piece;
}

ExactCoverCheck check_l(const std::vector<RationalPiece>& pieces) {
  const TriangleMesh l = testing::meshes::l_bracket();  // profile [0,4]x[0,1] u [0,1]x[0,3], y in [0,2]
  return verify_exact_cover(pieces, l.vertices, l.triangles);
}

TEST(LemmaShapeContainment, FaceToFacePiecesOfTheLBracketAreAccepted) {
  const auto foot = box_piece({0, 0, 0}, {4, 2, 1});
  const auto upright = box_piece({0, 0, 1}, {1, 2, 3});
  EXPECT_TRUE(check_l({foot, upright}).covered) << check_l({foot, upright}).failure;
  // The other split, and a three-piece split with a T-junction on the wall z = 1.
  EXPECT_TRUE(check_l({box_piece({0, 0, 0}, {1, 2, 3}), box_piece({1, 0, 0}, {4, 2, 1})}).covered);
  EXPECT_TRUE(check_l({box_piece({0, 0, 0}, {1, 2, 1}), box_piece({1, 0, 0}, {4, 2, 1}), upright})
                  .covered);
}

TEST(LemmaShapeContainment, MissingGappedOrBrokenPiecesAreRejected) {
  const auto foot = box_piece({0, 0, 0}, {4, 2, 1});
  EXPECT_FALSE(check_l({}).covered);
  EXPECT_FALSE(check_l({foot}).covered);  // the upright is not covered
  // A gap between foot and upright: the upright's bottom face is unmatched.
  EXPECT_FALSE(check_l({foot, box_piece({0, 0, 1.5}, {1, 2, 3})}).covered);
  // Overlapping pieces do cover, but the lemma's condition is face-to-face: rejected
  // (sufficient, not necessary).
  EXPECT_FALSE(check_l({foot, box_piece({0, 0, 0.5}, {1, 2, 3})}).covered);
  // Inward triangles: hypothesis (B) fails.
  RationalPiece inverted = box_piece({0, 0, 1}, {1, 2, 3});
  for (auto& t : inverted.triangles) std::swap(t[1], t[2]);
  EXPECT_FALSE(check_l({foot, inverted}).covered);
  // A vertex outside the piece's own triangles: (B) fails.
  RationalPiece extra = box_piece({0, 0, 1}, {1, 2, 3});
  extra.vertices.push_back({mpq_class(5), mpq_class(5), mpq_class(5)});
  EXPECT_FALSE(check_l({foot, extra}).covered);
  // A missing triangle: not a closed surface.
  RationalPiece open = box_piece({0, 0, 1}, {1, 2, 3});
  open.triangles.pop_back();
  EXPECT_FALSE(check_l({foot, open}).covered);
}

// proofs/shape-containment.md#lemma-outward-rounding: every rational vertex lies in the box
// of the returned corners, whose sides are adjacent doubles (or the vertex itself).
TEST(LemmaShapeContainment, OutwardRoundingBracketsEveryRationalVertexByAdjacentDoubles) {
  RationalPiece piece;
  piece.vertices = {{mpq_class(1, 3), mpq_class(-2, 7), mpq_class(5)},
                    {mpq_class(0), mpq_class(1, 10), mpq_class(-1, 3)},
                    {mpq_class(2), mpq_class(3), mpq_class(4)}};
  const auto corners = enclosing_double_points(piece);
  EXPECT_EQ(corners.size(), 4u + 4u + 1u);  // two free coordinates, two free, none
  for (const auto& v : piece.vertices) {
    const std::array<mpq_class, 3> q{v.x, v.y, v.z};
    // The corners around v: those within one ulp in every coordinate.
    std::array<double, 3> lo{}, hi{};
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::numeric_limits<double>::infinity();
      hi[k] = -lo[k];
    }
    for (const auto& c : corners) {
      bool near = true;
      for (int k = 0; k < 3; ++k) near = near && abs(mpq_class(c[k]) - q[k]) < mpq_class(1, 1000000);
      if (!near) continue;
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], c[k]);
        hi[k] = std::max(hi[k], c[k]);
      }
    }
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(mpq_class(lo[k]), q[k]);
      EXPECT_GE(mpq_class(hi[k]), q[k]);
      EXPECT_TRUE(lo[k] == hi[k] ? mpq_class(lo[k]) == q[k] : std::nextafter(lo[k], hi[k]) == hi[k]);
    }
  }
}

}  // namespace
}  // namespace grpvss::geometry

// geometry::recheck_offset: an offset read from outside the process is accepted only if it is
// a vertex list whose hull contains hull (+) B(0, r), decided exactly
// (proofs/offset-containment.md#lemma-cached-offset).
#include "grpvss/exact/offset_recheck.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/exact/minkowski_offset.hpp"

namespace {

using grpvss::geometry::ConvexPolytope;
using grpvss::geometry::OffsetShape;
using grpvss::geometry::recheck_offset;

// A skewed tetrahedron-plus-point hull (not axis aligned, so the faces of its offset are too).
ConvexPolytope sample_hull() {
  return ConvexPolytope::from_points({{0.0, 0.0, 0.0},
                                      {3.0, 0.25, -0.5},
                                      {0.5, 2.0, 0.125},
                                      {0.25, -0.75, 1.5},
                                      {1.0, 1.0, 1.0}});
}

std::vector<std::vector<int>> canonical_offset_faces(const ConvexPolytope& p) {
  std::vector<std::vector<int>> faces = p.faces();
  for (auto& loop : faces) {
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

std::vector<Eigen::Vector3d> offset_vertices(double radius, OffsetShape shape) {
  return grpvss::geometry::minkowski_offset(sample_hull(), radius, shape).vertices();
}

TEST(OffsetRecheck, AcceptsTheOffsetsMinkowskiOffsetBuildsAndKeepsTheirVertexOrder) {
  for (const OffsetShape shape : {OffsetShape::kCube, OffsetShape::kRhombicuboctahedron}) {
    const std::vector<Eigen::Vector3d> vertices = offset_vertices(0.5, shape);
    const auto accepted = recheck_offset(vertices, sample_hull(), 0.5);
    ASSERT_TRUE(accepted.has_value());
    EXPECT_EQ(accepted->vertices().size(), vertices.size());
    // Same polytope as the one the cell would hull from the built offset (faces compared
    // as sets of loops: from_points may list them in another order).
    EXPECT_EQ(canonical_offset_faces(*accepted), canonical_offset_faces(ConvexPolytope::from_points(vertices)));
  }
}

TEST(OffsetRecheck, RejectsAnOffsetBuiltForASmallerRadius) {
  const std::vector<Eigen::Vector3d> smaller = offset_vertices(0.49, OffsetShape::kCube);
  EXPECT_TRUE(recheck_offset(smaller, sample_hull(), 0.49).has_value());
  EXPECT_FALSE(recheck_offset(smaller, sample_hull(), 0.5).has_value());
  // Independent witness: the cube offset's x extent is max_x(H) + r' with r' < 0.5, so the
  // point of H (+) B(0, 0.5) farthest along +x lies outside.
  // (The hull is kept in a variable: a range-for over a temporary's member would dangle.)
  const ConvexPolytope hull = sample_hull();
  double hull_max = -1e300, offset_max = -1e300;
  for (const auto& h : hull.vertices()) hull_max = std::max(hull_max, h.x());
  for (const auto& v : smaller) offset_max = std::max(offset_max, v.x());
  EXPECT_GT(hull_max + 0.5, offset_max);
}

TEST(OffsetRecheck, RejectsAFaceMovedInwardByOneUlp) {
  // The cube offset of a box is the box grown by r exactly: move the +x face in by one ulp.
  const ConvexPolytope box = ConvexPolytope::from_points(
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}});
  std::vector<Eigen::Vector3d> grown;
  for (const auto& v : box.vertices()) grown.push_back(v + 0.5 * (2.0 * v.array() - 1.0).matrix());
  EXPECT_TRUE(recheck_offset(grown, box, 0.5).has_value());
  for (auto& v : grown) {
    if (v.x() == 1.5) v.x() = std::nextafter(1.5, 0.0);
  }
  EXPECT_FALSE(recheck_offset(grown, box, 0.5).has_value());
}

TEST(OffsetRecheck, RejectsPointListsThatAreNotAVertexList) {
  std::vector<Eigen::Vector3d> vertices = offset_vertices(0.5, OffsetShape::kCube);
  std::vector<Eigen::Vector3d> duplicated = vertices;
  duplicated.push_back(vertices.front());
  EXPECT_FALSE(recheck_offset(duplicated, sample_hull(), 0.5).has_value());
  std::vector<Eigen::Vector3d> interior = vertices;
  interior.push_back({1.0, 0.5, 0.5});
  EXPECT_FALSE(recheck_offset(interior, sample_hull(), 0.5).has_value());
  std::vector<Eigen::Vector3d> not_finite = vertices;
  not_finite[2].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(recheck_offset(not_finite, sample_hull(), 0.5).has_value());
  const std::vector<Eigen::Vector3d> flat = {{0, 0, 0}, {9, 0, 0}, {0, 9, 0}, {9, 9, 0}};
  EXPECT_FALSE(recheck_offset(flat, sample_hull(), 0.5).has_value());
  EXPECT_FALSE(recheck_offset({}, sample_hull(), 0.5).has_value());
}

}  // namespace

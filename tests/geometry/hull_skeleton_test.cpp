// The vertex graph GJK climbs on placed link offsets (hull_skeleton.hpp): its rows are the
// hull's edges in the point set's numbering, and a climb from any vertex ends where a full
// scan ends (the maximum), on rotated prisms and on their tolerance offsets; GJK climbing one
// or both sets proposes what GJK scanning proposes.
#include "grpvss/exact/polytope_skeleton.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include <gtest/gtest.h>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/geometry/gjk.hpp"
#include "grpvss/exact/minkowski_offset.hpp"
#include "support/random_shapes.hpp"

namespace grpvss::geometry {
namespace {

using Eigen::Vector3d;

std::vector<int> row(const HullSkeleton& skeleton, int i) {
  return {skeleton.neighbours.begin() + skeleton.first[i],
          skeleton.neighbours.begin() + skeleton.first[i + 1]};
}

TEST(HullSkeleton, ACubesRowsAreItsThreeEdgeNeighboursAndAnInteriorPointHasNone) {
  std::vector<Vector3d> points = test::cube(Vector3d(1, 2, 3), 2.0);  // vertex k: bits of k
  points.insert(points.begin() + 3, Vector3d(2, 3, 4));                // the centre, input 3
  const ConvexPolytope cube = ConvexPolytope::from_points(points);
  const HullSkeleton skeleton = hull_skeleton(cube, static_cast<int>(points.size()));
  ASSERT_EQ(skeleton.point_count(), 9);
  // Input index of cube vertex k (the centre shifts the vertices from 3 on by one).
  const auto input = [](int k) { return k < 3 ? k : k + 1; };
  for (int k = 0; k < 8; ++k) {
    std::vector<int> expected = {input(k ^ 1), input(k ^ 2), input(k ^ 4)};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(row(skeleton, input(k)), expected) << "vertex " << k;
  }
  EXPECT_TRUE(row(skeleton, 3).empty());
}

TEST(HullSkeleton, RowsAreSymmetricAscendingAndTwiceTheEdgeCount) {
  std::mt19937_64 rng(2027);
  for (int trial = 0; trial < 50; ++trial) {
    const auto points = test::random_prism(rng, Vector3d(trial, -trial, 0.5 * trial), 3.0);
    const ConvexPolytope hull = ConvexPolytope::from_points(points);
    const HullSkeleton skeleton = hull_skeleton(hull, static_cast<int>(points.size()));
    EXPECT_EQ(skeleton.neighbours.size(), 2 * hull.edges().size());
    for (int i = 0; i < skeleton.point_count(); ++i) {
      const std::vector<int> neighbours = row(skeleton, i);
      EXPECT_TRUE(std::is_sorted(neighbours.begin(), neighbours.end())) << "trial " << trial;
      EXPECT_EQ(std::adjacent_find(neighbours.begin(), neighbours.end()), neighbours.end());
      for (const int j : neighbours) {
        const std::vector<int> back = row(skeleton, j);
        EXPECT_TRUE(std::binary_search(back.begin(), back.end(), i)) << i << " -> " << j;
      }
    }
  }
}

// The support value a climb reaches, from every start, is the scanned maximum: on 30 random
// prisms and their rhombicuboctahedron offsets (the 50-60-vertex hulls the verifier places),
// 40 random directions each.
TEST(HullSkeleton, ClimbFromEveryVertexReachesTheScannedMaximum) {
  std::mt19937_64 rng(4341);
  std::normal_distribution<double> normal(0.0, 1.0);
  int climbs = 0;
  int longer_than_one_move = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const ConvexPolytope prism =
        ConvexPolytope::from_points(test::random_prism(rng, Vector3d(2, 1, -3), 4.0));
    // Hulled again from its own vertices, as RobotCell does: vertex i is input point i.
    const ConvexPolytope offset = ConvexPolytope::from_points(
        minkowski_offset(prism, 0.5, OffsetShape::kRhombicuboctahedron).vertices());
    for (const ConvexPolytope* hull : {&prism, &offset}) {
      const std::vector<Vector3d>& points = hull->vertices();
      const HullSkeleton skeleton = hull_skeleton(*hull, static_cast<int>(points.size()));
      for (int d = 0; d < 40; ++d) {
        const Vector3d direction(normal(rng), normal(rng), normal(rng));
        const double maximum = points[support_index(points, direction)].dot(direction);
        for (int start = 0; start < static_cast<int>(points.size()); ++start) {
          const int top = climb_support_index(points, skeleton, start, direction);
          ASSERT_EQ(points[top].dot(direction), maximum)
              << "trial " << trial << ", direction " << d << ", start " << start;
          ++climbs;
          if (top != start && std::find(skeleton.neighbours.begin() + skeleton.first[start],
                                        skeleton.neighbours.begin() + skeleton.first[start + 1],
                                        top) == skeleton.neighbours.begin() + skeleton.first[start + 1]) {
            ++longer_than_one_move;
          }
        }
      }
    }
  }
  EXPECT_GT(climbs, 50000);
  EXPECT_GT(longer_than_one_move, climbs / 4);  // the climbs are walks, not one look around
}

// The vertex-numbered skeleton (a raw link hull's: its point set is the hull's vertex list) is
// the input-numbered one renumbered through input_indices(): the same edges, vertex for vertex.
TEST(HullSkeleton, VertexSkeletonIsTheInputSkeletonRenumberedToTheVertexList) {
  std::mt19937_64 rng(7545);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vector3d> points = test::random_prism(rng, Vector3d(trial, 1, -2), 2.0);
    points.insert(points.begin(), Vector3d(trial, 1, -2));  // an interior input point first
    const ConvexPolytope hull = ConvexPolytope::from_points(points);
    const HullSkeleton by_input = hull_skeleton(hull, static_cast<int>(points.size()));
    const HullSkeleton by_vertex = vertex_skeleton(hull);
    ASSERT_EQ(by_vertex.point_count(), static_cast<int>(hull.vertices().size()));
    EXPECT_EQ(by_vertex.neighbours.size(), by_input.neighbours.size());
    const std::vector<int>& input = hull.input_indices();
    for (int v = 0; v < by_vertex.point_count(); ++v) {
      std::vector<int> expected;
      for (const int u : row(by_vertex, v)) expected.push_back(input[static_cast<std::size_t>(u)]);
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(row(by_input, input[static_cast<std::size_t>(v)]), expected)
          << "trial " << trial << ", vertex " << v;
    }
  }
}

// GJK that climbs A's skeleton (and B's when `climb_b`: a self pair's two link hulls), from
// any starts, proposes what GJK that scans both proposes: the same status and distance on 400
// random prism pairs, separated and overlapping.
void expect_climbing_gjk_proposes_what_scanning_proposes(std::uint64_t seed, bool climb_b) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> offset(-5.5, 5.5);
  std::uniform_int_distribution<int> start(-2, 17);  // out of range: 0
  int separated = 0;
  int overlapping = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const ConvexPolytope a =
        ConvexPolytope::from_points(test::random_prism(rng, Vector3d::Zero(), 3.0));
    const ConvexPolytope b = ConvexPolytope::from_points(
        test::random_prism(rng, Vector3d(offset(rng), offset(rng), offset(rng)), 2.0));
    const HullSkeleton a_skeleton = vertex_skeleton(a);
    const HullSkeleton b_skeleton = vertex_skeleton(b);
    const GjkResult scanned = gjk(a.vertices(), b.vertices());
    const GjkResult climbed = gjk(a.vertices(), b.vertices(), nullptr, &a_skeleton, start(rng),
                                  climb_b ? &b_skeleton : nullptr, start(rng));
    ASSERT_EQ(climbed.status, scanned.status) << "trial " << trial;
    EXPECT_NEAR(climbed.distance, scanned.distance, 1e-12 * (1.0 + scanned.distance));
    ASSERT_GE(climbed.last_support_a, 0);
    ASSERT_LT(climbed.last_support_a, static_cast<int>(a.vertices().size()));
    ASSERT_GE(climbed.last_support_b, 0);
    ASSERT_LT(climbed.last_support_b, static_cast<int>(b.vertices().size()));
    separated += scanned.status == GjkStatus::kSeparated;
    overlapping += scanned.status == GjkStatus::kOverlapping;
  }
  EXPECT_GT(separated, 100);
  EXPECT_GT(overlapping, 30);
}

TEST(HullSkeleton, GjkClimbingProposesWhatGjkScanningProposes) {
  expect_climbing_gjk_proposes_what_scanning_proposes(11, false);
}

TEST(HullSkeleton, GjkClimbingBothSetsProposesWhatGjkScanningProposes) {
  expect_climbing_gjk_proposes_what_scanning_proposes(4342, true);
}

TEST(HullSkeleton, GjkRefusesASkeletonOfAnotherPointSet) {
  const auto a = test::cube(Vector3d::Zero(), 1.0);
  const HullSkeleton skeleton = hull_skeleton(ConvexPolytope::from_points(a), 8);
  std::vector<Vector3d> more = a;
  more.push_back(Vector3d(0.5, 0.5, 0.5));
  EXPECT_THROW(gjk(more, test::cube(Vector3d(3, 0, 0), 1.0), nullptr, &skeleton),
               std::invalid_argument);
  EXPECT_THROW(gjk(test::cube(Vector3d(3, 0, 0), 1.0), more, nullptr, nullptr, 0, &skeleton),
               std::invalid_argument);
}


// An n-gon prism between z = 0 and z = 1 (radius 1): the top face has n vertices.
std::vector<Vector3d> polygon_prism(int n) {
  std::vector<Vector3d> points;
  for (int k = 0; k < n; ++k) {
    const double angle = 2.0 * 3.14159265358979323846 * k / n;
    points.emplace_back(std::cos(angle), std::sin(angle), 0.0);
    points.emplace_back(std::cos(angle), std::sin(angle), 1.0);
  }
  return points;
}

std::vector<int> members_of(const TiedSupportSet& set) {
  std::vector<int> members;
  for (int k = 0; k < set.size(); ++k) members.push_back(set.member(k));
  std::sort(members.begin(), members.end());
  return members;
}

std::vector<int> vertices_with_z(const ConvexPolytope& hull, double z) {
  std::vector<int> found;
  for (std::size_t i = 0; i < hull.vertices().size(); ++i) {
    if (hull.vertices()[i].z() == z) found.push_back(static_cast<int>(i));
  }
  return found;
}

// The tied set of a climb that ends on a face facing d is that whole face, whatever vertex of
// it the climb ended on; the neighbours outside it are the faces' other ends (here the
// bottom face), each visited; no vertex outside the face is a member.
TEST(TiedSupportSet, IsTheFaceFacingTheDirectionAndItsOutsideNeighboursAreTheOtherEnds) {
  for (const int n : {4, 17, 60}) {
    const ConvexPolytope prism = ConvexPolytope::from_points(polygon_prism(n));
    const HullSkeleton skeleton = vertex_skeleton(prism);
    const std::vector<int> top = vertices_with_z(prism, 1.0);
    const std::vector<int> bottom = vertices_with_z(prism, 0.0);
    ASSERT_EQ(static_cast<int>(top.size()), n);
    for (const int end : {top.front(), top.back()}) {
      TiedSupportSet tied;
      ASSERT_TRUE(tied.gather(prism.vertices(), skeleton, Vector3d(0, 0, 1), end, 1e-12));
      EXPECT_EQ(members_of(tied), top) << n << "-gon";
      for (const int b : bottom) EXPECT_FALSE(tied.contains(b));
      std::vector<int> outside;
      EXPECT_TRUE(tied.every_outside_neighbour(skeleton, [&](int y) {
        outside.push_back(y);
        return true;
      }));
      std::sort(outside.begin(), outside.end());
      EXPECT_EQ(outside, bottom) << n << "-gon";
      // The first outside neighbour that fails ends the check with false.
      EXPECT_FALSE(tied.every_outside_neighbour(skeleton, [](int) { return false; }));
    }
  }
}

// A plateau of more than kMaxMembers vertices is refused (the callers scan); a tilted
// direction ties only the climb's end.
TEST(TiedSupportSet, RefusesAPlateauAboveItsBoundAndTiesOneVertexOffTheFace) {
  const int n = TiedSupportSet::kMaxMembers + 1;
  const ConvexPolytope prism = ConvexPolytope::from_points(polygon_prism(n));
  const HullSkeleton skeleton = vertex_skeleton(prism);
  const int end = vertices_with_z(prism, 1.0).front();
  TiedSupportSet tied;
  EXPECT_FALSE(tied.gather(prism.vertices(), skeleton, Vector3d(0, 0, 1), end, 1e-12));
  const Vector3d tilted(0.3, 0.1, 1.0);
  const int top = climb_support_index(prism.vertices(), skeleton, end, tilted);
  ASSERT_TRUE(tied.gather(prism.vertices(), skeleton, tilted, top, 1e-12));
  EXPECT_EQ(members_of(tied), std::vector<int>{top});
}

// One set per thread at a time: a later gather can only take marks away from an earlier
// set (whose checks then test those members as neighbours, which is stricter), never make it
// claim a vertex it did not gather.
TEST(TiedSupportSet, ALaterGatherNeverAddsMembersToAnEarlierSet) {
  const ConvexPolytope prism = ConvexPolytope::from_points(polygon_prism(8));
  const HullSkeleton skeleton = vertex_skeleton(prism);
  const std::vector<int> top = vertices_with_z(prism, 1.0);
  const std::vector<int> bottom = vertices_with_z(prism, 0.0);
  TiedSupportSet first;
  TiedSupportSet second;
  ASSERT_TRUE(first.gather(prism.vertices(), skeleton, Vector3d(0, 0, 1), top.front(), 1e-12));
  ASSERT_TRUE(second.gather(prism.vertices(), skeleton, Vector3d(0, 0, -1), bottom.front(), 1e-12));
  EXPECT_EQ(members_of(second), bottom);
  for (int v = 0; v < skeleton.point_count(); ++v) {
    if (first.contains(v)) EXPECT_TRUE(std::binary_search(top.begin(), top.end(), v)) << v;
  }
}

}  // namespace
}  // namespace grpvss::geometry

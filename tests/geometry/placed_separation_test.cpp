// Separation of placed link-frame hulls without placing them (placed_separation.hpp,
// proofs/fast-path.md#placed-separation): every witness it proves holds exactly on the points
// place_points computes (the lemma's inequality, re-checked in rational arithmetic), it proves
// what a scan of those points proves up to ~1e-15 of the coordinates, and GJK on the templates
// proposes what GJK on the placed points proposes.
#include "grpvss/exact/placed_separation.hpp"

#include <random>

#include <gtest/gtest.h>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/polytope_skeleton.hpp"
#include "grpvss/geometry/gjk.hpp"
#include "grpvss/geometry/separation_witness.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "support/random_shapes.hpp"

namespace grpvss::geometry {
namespace {

using Eigen::Vector3d;

/// A link hull as RobotCell keeps it: the exact hull's vertices and their edge graph.
struct LinkTemplate {
  std::vector<Vector3d> vertices_L;
  HullSkeleton skeleton;
};

/// Up to 300 points on a random ellipsoid of semi-axes in [0.02, 0.3] m (a CAD link's hull
/// has hundreds of vertices), hulled exactly.
LinkTemplate random_link(std::mt19937_64& rng, int points) {
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> axis(0.02, 0.3);
  const Vector3d semi(axis(rng), axis(rng), axis(rng));
  std::vector<Vector3d> cloud;
  for (int i = 0; i < points; ++i) {
    const Vector3d direction = Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    cloud.push_back(direction.cwiseProduct(semi));
  }
  const ConvexPolytope hull = ConvexPolytope::from_points(cloud);
  return {hull.vertices(), vertex_skeleton(hull)};
}

Eigen::Isometry3d random_separation_pose(std::mt19937_64& rng, double reach) {
  std::uniform_real_distribution<double> coordinate(-reach, reach);
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = test::random_rotation(rng);
  X.translation() = Vector3d(coordinate(rng), coordinate(rng), coordinate(rng));
  return X;
}

PlacedHull placed_link_hull(const LinkTemplate& link, const Eigen::Isometry3d& X_WL) {
  PlacedHull hull;
  hull.vertices_L = &link.vertices_L;
  hull.skeleton = &link.skeleton;
  hull.X_WL = X_WL;
  hull.max_abs_L = max_abs_coordinate(link.vertices_L);
  return hull;
}

/// Two random 20-300-point links at random poses within `reach` of the origin.
struct RandomPair {
  LinkTemplate link_a;
  LinkTemplate link_b;
  Eigen::Isometry3d X_a;
  Eigen::Isometry3d X_b;
};

RandomPair random_pair(std::mt19937_64& rng, double reach) {
  std::uniform_int_distribution<int> size(20, 300);
  RandomPair pair;
  pair.link_a = random_link(rng, size(rng));
  pair.link_b = random_link(rng, size(rng));
  pair.X_a = random_separation_pose(rng, reach);
  pair.X_b = random_separation_pose(rng, reach);
  return pair;
}

std::vector<Vector3d> placed_points(const LinkTemplate& link, const Eigen::Isometry3d& X_WL) {
  std::vector<Vector3d> points;
  kinematics::place_points(X_WL, link.vertices_L, points);
  return points;
}

// 600 random pairs of 20-300-point links at random poses within 1 m, each with GJK's normal
// and, for pairs close together, B pushed towards A until the gap is 1e-6 to 1e-13 m: the
// witness must hold exactly on the placed points (what the checker re-checks), and the
// bound must be within 1e-14 m of what a scan of those points certifies.
TEST(PlacedSeparation, EveryWitnessHoldsExactlyOnThePlacedPointsAndMatchesTheScan) {
  std::mt19937_64 rng(7545);
  std::uniform_real_distribution<double> exponent(-13.0, -6.0);
  int proven = 0;
  int tight = 0;
  int scanned_only = 0;
  for (int trial = 0; trial < 600; ++trial) {
    auto [link_a, link_b, X_a, X_b] = random_pair(rng, 1.0);
    std::vector<Vector3d> a = placed_points(link_a, X_a);
    std::vector<Vector3d> b = placed_points(link_b, X_b);
    GjkResult g = gjk(a, b);
    if (g.status != GjkStatus::kSeparated) continue;
    if (trial % 2 == 1) {  // a near contact: B moved along -v to a tiny gap
      const double gap = std::pow(10.0, exponent(rng));
      X_b.translation() += g.closest_vector * ((g.distance - gap) / g.distance);
      b = placed_points(link_b, X_b);
      g = gjk(a, b);
      if (g.status != GjkStatus::kSeparated) continue;
    }
    const Vector3d normal = -g.closest_vector;
    int a_start = 0;
    int b_start = 0;
    const auto by_templates =
        certify_placed_separation(placed_link_hull(link_a, X_a), a_start, placed_link_hull(link_b, X_b), b_start, normal);
    const auto by_scan = certify_separation(a, b, normal);
    if (!by_templates) {
      if (by_scan) ++scanned_only;
      continue;
    }
    ++proven;
    if (trial % 2 == 1) ++tight;
    EXPECT_TRUE(check_witness_exactly(a, b, by_templates->witness, by_templates->lower_bound))
        << "trial " << trial;
    ASSERT_TRUE(by_scan) << "trial " << trial << ": the scan must prove what the templates prove";
    EXPECT_LE(by_scan->witness.offset_a, by_templates->witness.offset_a) << "trial " << trial;
    EXPECT_GE(by_scan->witness.offset_b, by_templates->witness.offset_b) << "trial " << trial;
    EXPECT_NEAR(by_templates->lower_bound, by_scan->lower_bound, 1e-14) << "trial " << trial;
  }
  EXPECT_GE(proven, 500);
  EXPECT_GE(tight, 200);
  // The templates' bound is a few 1e-16 m looser and ties are settled by their plateau: here
  // nothing is left to the scan (518 proven, 223 of them at gaps of 1e-13 to 1e-6 m).
  EXPECT_EQ(scanned_only, 0);
}

// A normal square to a face ties its four vertices up to the rounding of R^T n: the plateau
// is settled as one (every outside neighbour is provably lower) and the bound is the face's,
// from every start, under 50 random rotations. (Testing the climb's end alone against its
// neighbours fails on most of these.)
TEST(PlacedSeparation, AFaceSeenHeadOnIsSettledAsATiedPlateau) {
  const ConvexPolytope box = ConvexPolytope::from_points(test::cube(Vector3d(-0.1, -0.1, -0.1), 0.2));
  const LinkTemplate link{box.vertices(), vertex_skeleton(box)};
  std::mt19937_64 rng(545);
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::Isometry3d X_a = Eigen::Isometry3d::Identity();
    X_a.linear() = test::random_rotation(rng);
    Eigen::Isometry3d X_b = X_a;
    X_b.translation() = X_a.linear() * Vector3d(0.05, 0.0, 0.201);  // 1 mm above A's top face
    const Vector3d normal = X_a.linear() * Vector3d(0, 0, 1);
    for (int start = 0; start < 8; ++start) {
      int a_start = start;
      int b_start = start;
      const auto s = certify_placed_separation(placed_link_hull(link, X_a), a_start, placed_link_hull(link, X_b), b_start, normal);
      ASSERT_TRUE(s) << "trial " << trial << " start " << start;
      EXPECT_NEAR(s->lower_bound, 0.001, 1e-14);
      EXPECT_TRUE(check_witness_exactly(placed_points(link, X_a), placed_points(link, X_b), s->witness,
                                        s->lower_bound));
      EXPECT_DOUBLE_EQ(link.vertices_L[static_cast<std::size_t>(a_start)].z(), 0.1);   // A's top face
      EXPECT_DOUBLE_EQ(link.vertices_L[static_cast<std::size_t>(b_start)].z(), -0.1);  // B's bottom face
    }
  }
}

// A normal that does not separate is refused, and so is a zero or non-finite one.
TEST(PlacedSeparation, RefusesNormalsThatDoNotSeparate) {
  std::mt19937_64 rng(4341);
  const LinkTemplate link = random_link(rng, 100);
  const Eigen::Isometry3d X_a = random_separation_pose(rng, 0.5);
  Eigen::Isometry3d X_b = X_a;
  X_b.translation() += Vector3d(0.01, 0, 0);  // overlapping copies
  int a_start = 0;
  int b_start = 0;
  EXPECT_FALSE(certify_placed_separation(placed_link_hull(link, X_a), a_start, placed_link_hull(link, X_b), b_start,
                                         Vector3d(1, 0, 0)));
  EXPECT_FALSE(certify_placed_separation(placed_link_hull(link, X_a), a_start, placed_link_hull(link, X_b), b_start,
                                         Vector3d::Zero()));
  EXPECT_FALSE(certify_placed_separation(placed_link_hull(link, X_a), a_start, placed_link_hull(link, X_b), b_start,
                                         Vector3d(std::nan(""), 1, 0)));
  EXPECT_FALSE(certified_placed_separation_query(placed_link_hull(link, X_a), placed_link_hull(link, X_b), nullptr,
                                                 nullptr, nullptr));
}

// GJK climbing the templates under their poses sees the same pairs as GJK climbing the placed
// points: same status, distances within 1e-12 m, on 300 random pairs.
TEST(PlacedSeparation, GjkOnTemplatesProposesWhatGjkOnThePlacedPointsProposes) {
  std::mt19937_64 rng(1988);
  int separated = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto [link_a, link_b, X_a, X_b] = random_pair(rng, 0.4);
    const GjkResult on_points = gjk(placed_points(link_a, X_a), placed_points(link_b, X_b), nullptr,
                                    &link_a.skeleton, 0, &link_b.skeleton, 0);
    const GjkResult on_templates = gjk(placed_link_hull(link_a, X_a), placed_link_hull(link_b, X_b));
    ASSERT_EQ(on_points.status, on_templates.status) << "trial " << trial;
    if (on_points.status != GjkStatus::kSeparated) continue;
    ++separated;
    EXPECT_NEAR(on_points.distance, on_templates.distance, 1e-12) << "trial " << trial;
  }
  EXPECT_GE(separated, 100);
}

// GJK started from the pair's last simplex (the vertices at their new places) after a small
// motion finds what a fresh start finds, in fewer iterations over 300 random pairs; a hint
// out of range is ignored.
TEST(PlacedSeparation, GjkFromTheLastSimplexFindsWhatAFreshStartFinds) {
  std::mt19937_64 rng(2026);
  std::normal_distribution<double> nudge(0.0, 0.002);
  int separated = 0;
  int fresh_iterations = 0;
  int hinted_iterations = 0;
  for (int trial = 0; trial < 300; ++trial) {
    auto [link_a, link_b, X_a, X_b] = random_pair(rng, 0.4);
    GjkSimplexHint hint;
    const GjkResult before = gjk(placed_link_hull(link_a, X_a), placed_link_hull(link_b, X_b), nullptr, 0, 0, &hint);
    if (before.status != GjkStatus::kSeparated) {
      EXPECT_EQ(hint.size, 0);
      continue;
    }
    EXPECT_EQ(hint.size, before.simplex_size);
    X_b.translation() += Vector3d(nudge(rng), nudge(rng), nudge(rng));
    X_b.rotate(Eigen::AngleAxisd(0.01, Vector3d::UnitZ()));
    const GjkResult fresh = gjk(placed_link_hull(link_a, X_a), placed_link_hull(link_b, X_b));
    const GjkResult hinted = gjk(placed_link_hull(link_a, X_a), placed_link_hull(link_b, X_b), nullptr, 0, 0, &hint);
    ASSERT_EQ(fresh.status, hinted.status) << "trial " << trial;
    if (fresh.status != GjkStatus::kSeparated) continue;
    ++separated;
    EXPECT_NEAR(fresh.distance, hinted.distance, 1e-12) << "trial " << trial;
    fresh_iterations += fresh.iterations;
    hinted_iterations += hinted.iterations;
  }
  EXPECT_GE(separated, 100);
  EXPECT_LT(hinted_iterations, fresh_iterations);
  const LinkTemplate link = random_link(rng, 50);
  GjkSimplexHint out_of_range{3, {0, 1, 100000, 0}, {0, 1, 2, 0}};
  Eigen::Isometry3d X_far = Eigen::Isometry3d::Identity();
  X_far.translation() = Vector3d(2, 0, 0);
  const GjkResult g = gjk(placed_link_hull(link, Eigen::Isometry3d::Identity()), placed_link_hull(link, X_far), nullptr, 0,
                          0, &out_of_range);
  EXPECT_EQ(g.status, GjkStatus::kSeparated);
  EXPECT_NEAR(g.distance, gjk(placed_link_hull(link, Eigen::Isometry3d::Identity()), placed_link_hull(link, X_far)).distance, 1e-12);
}

}  // namespace
}  // namespace grpvss::geometry

// The revolution route of a self pair (proofs/two-ball-cover.md#revolution-route): a hull of
// link a that is round about joint a+1's axis lies in a solid of revolution S about that axis;
// joint a+1 turns S into itself, so a pair (a, b) may be held with joint a+1 frozen, from the
// distances between S and hull b. Tested: the solid's rule and its exact containment, its
// support bound against sampled points, the lemma's inequality against an exact reference
// distance along random steps, and the checker's acceptance and rejections.

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "certify/cell_probe.hpp"
#include "certify/transition_judge.hpp"
#include "checker/revolution_check.hpp"
#include "grpvss/cell/load_cell.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/geometry/revolution_solid.hpp"
#include "grpvss/geometry/separation_witness.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "support/ur5e_self_run.hpp"

namespace grpvss::certify {
namespace {

using Points = std::vector<Eigen::Vector3d>;
using geometry::RevolutionRing;
using geometry::RevolutionSolid;

geometry::JointAxisLine_L next_axis(const RobotCell& cell, const LinkHull& hull) {
  const kinematics::ChainJoint& next = cell.chain().joints[static_cast<std::size_t>(hull.link)];
  return geometry::joint_axis_line(next.X_PJ, next.X_PJ_error.rotation, next.X_PJ_error.translation);
}

// A regular prism of `sides` about the z axis, radius 0.1, from z = 0 to z = 0.2.
Points prism(int sides) {
  Points points;
  for (int i = 0; i < sides; ++i) {
    const double angle = 2.0 * 3.14159265358979323846 * i / sides;
    for (const double z : {0.0, 0.2}) points.emplace_back(0.1 * std::cos(angle), 0.1 * std::sin(angle), z);
  }
  return points;
}

TEST(RevolutionSolid, TheUr5eBaseIsEnclosedTightlyAndTheCheckerDecidesItExactly) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-self.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  int with_solid = 0;
  for (const LinkHull& hull : cell.hulls()) {
    if (!hull.revolution_L) continue;
    ++with_solid;
    EXPECT_EQ(hull.link, 0);  // only the base is round about its next joint (shoulder pan)
    const geometry::JointAxisLine_L axis = next_axis(cell, hull);
    EXPECT_TRUE(solid_encloses_exactly(*hull.revolution_L, hull.raw_L, axis, loaded.robot.hull_point_error));
    // Tight: the largest radius exceeds the hull's largest distance from the axis by < 0.01 mm.
    double radial = 0.0;
    for (const Eigen::Vector3d& v : hull.raw_L) {
      const Eigen::Vector3d d = v - axis.point_L;
      radial = std::max(radial, (d - d.dot(axis.direction_L) * axis.direction_L).norm());
    }
    EXPECT_GT(hull.revolution_L->largest_radius(), radial);
    EXPECT_LT(hull.revolution_L->largest_radius(), radial + 1e-5);
    // The tapered top is followed: more than two rings, and the top ring narrower than the widest.
    ASSERT_GT(hull.revolution_L->rings.size(), 2u);
    EXPECT_LT(hull.revolution_L->rings.back().radius, 0.9 * hull.revolution_L->largest_radius());
    // A solid shrunk by 1 um, or with a ring moved past the hull's end, is rejected exactly.
    RevolutionSolid shrunk = *hull.revolution_L;
    for (RevolutionRing& ring : shrunk.rings) ring.radius -= 1e-6;
    EXPECT_FALSE(solid_encloses_exactly(shrunk, hull.raw_L, axis, loaded.robot.hull_point_error));
    RevolutionSolid short_of_the_end = *hull.revolution_L;
    short_of_the_end.rings.back().axial -= 1e-6;
    EXPECT_FALSE(solid_encloses_exactly(short_of_the_end, hull.raw_L, axis, loaded.robot.hull_point_error));
    // The margin grows with the stored axis's errors: a 1 mm translation error needs more room.
    geometry::JointAxisLine_L loose_axis = axis;
    loose_axis.point_error = 1e-3;
    EXPECT_FALSE(solid_encloses_exactly(*hull.revolution_L, hull.raw_L, loose_axis, loaded.robot.hull_point_error));
  }
  EXPECT_EQ(with_solid, 1);
}

TEST(RevolutionSolid, OnlyHullsRoundAboutACoordinateAxisGetOne) {
  const geometry::JointAxisLine_L z_axis = geometry::joint_axis_line(Eigen::Isometry3d::Identity(), 0.0, 0.0);
  // A 64-gon is round (support across the axis >= 0.98 of the radius); a square is not.
  const auto round = geometry::enclosing_revolution_solid(prism(64), z_axis, 0.0);
  ASSERT_TRUE(round.has_value());
  EXPECT_EQ(round->rings.size(), 2u);  // the end discs, dilated (the collinear middle ones drop)
  EXPECT_NEAR(round->largest_radius(), 0.1, 1e-9);
  EXPECT_NEAR(round->rings.front().axial, 0.0, 1e-9);
  EXPECT_NEAR(round->rings.back().axial, 0.2, 1e-9);
  EXPECT_TRUE(solid_encloses_exactly(*round, prism(64), z_axis, 0.0));
  // A ring dented in at mid-height leaves every vertex (at the two ends) inside F, but not the
  // prism's side: the checker's concavity test refuses it.
  RevolutionSolid dented = *round;
  dented.rings.insert(dented.rings.begin() + 1, RevolutionRing{0.1, 0.05});
  EXPECT_FALSE(solid_encloses_exactly(dented, prism(64), z_axis, 0.0));
  EXPECT_FALSE(geometry::enclosing_revolution_solid(prism(4), z_axis, 0.0).has_value());
  // Off the axis: the hull seen from the axis is not round.
  Points shifted = prism(64);
  for (Eigen::Vector3d& p : shifted) p.x() += 0.05;
  EXPECT_FALSE(geometry::enclosing_revolution_solid(shifted, z_axis, 0.0).has_value());
  // An axis that is not exactly a coordinate axis gets none (|u| = 1 would not be exact).
  Eigen::Isometry3d tilted = Eigen::Isometry3d::Identity();
  tilted.linear() = Eigen::AngleAxisd(1e-3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_FALSE(geometry::enclosing_revolution_solid(
                   prism(64), geometry::joint_axis_line(tilted, 0.0, 0.0), 0.0)
                   .has_value());
  // The hull's point error widens the solid by at least as much.
  const auto wider = geometry::enclosing_revolution_solid(prism(64), z_axis, 1e-4);
  ASSERT_TRUE(wider.has_value());
  EXPECT_GE(wider->largest_radius(), round->largest_radius() + 1e-4);
  EXPECT_TRUE(solid_encloses_exactly(*wider, prism(64), z_axis, 1e-4));
  EXPECT_FALSE(solid_encloses_exactly(*round, prism(64), z_axis, 1e-4));
}

// Independent reference: points on every ring's circle, placed by the same matrix in long
// double; the bound must exceed every one and be within 1e-9 of the largest.
TEST(RevolutionSolid, TheSupportBoundHoldsOnSampledPointsAndTheCheckerAgrees) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    RevolutionSolid solid;
    const int axis = trial % 3;
    solid.axis_L = Eigen::Vector3d::Unit(axis) * (trial % 2 == 0 ? 1.0 : -1.0);
    solid.axis_point_L = Eigen::Vector3d(u(rng), u(rng), u(rng)) * 0.3;
    double axial = -0.2;
    for (int r = 0; r < 2 + trial % 5; ++r) {
      axial += 0.01 + 0.1 * std::fabs(u(rng));
      solid.rings.push_back({axial, 0.02 + 0.1 * std::fabs(u(rng))});
    }
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.linear() = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
    X.translation() = Eigen::Vector3d(u(rng), u(rng), u(rng));
    const Eigen::Vector3d n = Eigen::Vector3d(u(rng), u(rng), u(rng)) * (trial % 7 == 0 ? 1e-3 : 1.0);
    const double bound = geometry::placed_solid_support_upper(solid, X, n);
    const Eigen::Vector3d e1 = Eigen::Vector3d::Unit((axis + 1) % 3);
    const Eigen::Vector3d e2 = Eigen::Vector3d::Unit((axis + 2) % 3);
    long double largest = -1e300L;
    for (const RevolutionRing& ring : solid.rings) {
      for (int k = 0; k < 3600; ++k) {
        const double angle = 2.0 * 3.14159265358979323846 * k / 3600;
        const Eigen::Vector3d c = solid.axis_point_L + ring.axial * solid.axis_L +
                                  ring.radius * (std::cos(angle) * e1 + std::sin(angle) * e2);
        long double value = 0.0L;
        for (int i = 0; i < 3; ++i) {
          long double x = static_cast<long double>(X.translation()[i]);
          for (int j = 0; j < 3; ++j) x += static_cast<long double>(X.linear()(i, j)) * c[j];
          value += static_cast<long double>(n[i]) * x;
        }
        largest = std::max(largest, value);
      }
    }
    ASSERT_GE(static_cast<long double>(bound), largest) << "trial " << trial;
    EXPECT_LT(static_cast<long double>(bound) - largest, 1e-6L * n.norm()) << "trial " << trial;
    // The checker: a slab at the bound holds for lambda 0, a slab below the sampled maximum never.
    geometry::SeparationWitness witness{n, bound, bound};
    EXPECT_TRUE(solid_side_holds_exactly(solid, X, witness, 0.0)) << "trial " << trial;
    witness.offset_b = static_cast<double>(largest) - 1e-9 * n.norm();
    EXPECT_FALSE(solid_side_holds_exactly(solid, X, witness, 0.0)) << "trial " << trial;
    // A certificate's non-finite numbers are refused, never converted.
    EXPECT_FALSE(solid_side_holds_exactly(solid, X, witness, std::numeric_limits<double>::infinity()));
    geometry::SeparationWitness unbounded{n, bound, std::numeric_limits<double>::infinity()};
    EXPECT_FALSE(solid_side_holds_exactly(solid, X, unbounded, 0.0));
    // lambda |n| more room is needed for a claimed distance lambda.
    witness.offset_b = bound + 0.01 * n.norm();
    EXPECT_TRUE(solid_side_holds_exactly(solid, X, witness, 0.0099)) << "trial " << trial;
    EXPECT_FALSE(solid_side_holds_exactly(solid, X, witness, 0.0101 + 1e-6)) << "trial " << trial;
  }
}

// The lemma's statement against an exact reference: along random steps that turn joint 1 far
// and the others a little, every base pair the route proves keeps, at every sampled
// configuration, an exact distance of at least (c_k + c_{k+1} - M')/2 between the true hulls.
TEST(RevolutionRouteLemma, TheExactDistanceKeepsHalfTheSlackAlongStepsTheRouteProves) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-self.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  CellProbe probe(cell);
  kinematics::Workspace workspace(cell.robot());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int proven_only_by_the_route = 0;
  int checked = 0;
  for (int trial = 0; trial < 12; ++trial) {
    Eigen::VectorXd q0(6), q1(6);
    q0 << u(rng), -1.2 + 0.4 * u(rng), 1.6 + 0.4 * u(rng), u(rng), u(rng), u(rng);
    q1 = q0;
    q1[0] += 1.5 * u(rng);  // the base's joint: a long sweep
    for (int j = 1; j < 6; ++j) q1[j] += 0.01 * u(rng);
    ProbeResult from, to;
    probe.probe(q0, false, from);
    probe.probe(q1, false, to);
    const Eigen::VectorXd dq = q1 - q0;
    for (std::size_t p = 0; p < cell.self_pairs().size(); ++p) {
      const SelfPairHulls& pair = cell.self_pairs()[p];
      const LinkHull& a = cell.hulls()[static_cast<std::size_t>(pair.a)];
      const LinkHull& b = cell.hulls()[static_cast<std::size_t>(pair.b)];
      if (!a.revolution_L) continue;
      const double bound = revolution_motion_bound(cell, pair, dq, nullptr);
      const double c_from = from.self_pairs[p].revolution_distance;
      const double c_to = to.self_pairs[p].revolution_distance;
      if (!(bound < allowance_down(c_from, c_to))) continue;
      ++checked;
      Eigen::VectorXd relative = dq;
      relative.head(a.link).setZero();
      if (!(cell.radii().hull_motion_bound(b.link, b.hull, relative) <
            allowance_down(from.self_pairs[p].distance, to.self_pairs[p].distance))) {
        ++proven_only_by_the_route;
      }
      const double kept = 0.5 * (c_from + c_to - bound);
      for (int k = 0; k <= 4; ++k) {
        kinematics::forward_kinematics(cell.chain(), q0 + dq * (k / 4.0), workspace);
        Points placed_a, placed_b;
        kinematics::place_points(workspace.X_WL[static_cast<std::size_t>(a.link)], a.raw_L, placed_a);
        kinematics::place_points(workspace.X_WL[static_cast<std::size_t>(b.link)], b.raw_L, placed_b);
        const double squared = geometry::exact_distance_squared_lower(placed_a, placed_b);
        // The placed hulls are within 2 placement errors of the true ones (~1e-15 m).
        EXPECT_GE(std::sqrt(squared) + 1e-12, kept) << "trial " << trial << " pair " << p << " k " << k;
      }
    }
  }
  EXPECT_EQ(checked, 60);                   // every base pair of the 12 steps
  EXPECT_EQ(proven_only_by_the_route, 28);  // the relative bound alone could not hold these
}

using test::has_failure;

TEST(RevolutionRoute, TheCheckerAcceptsTheRouteAndRejectsAnInflatedOrMissingDistance) {
  const test::Ur5eSelfInputs run = test::load_ur5e_self("ur5e-self.yaml", "ur5e-clear.txt");
  const VerificationRun verified = test::verify_ur5e_self(run);
  ASSERT_EQ(verified.result.verdict, Verdict::kClear);
  const Certificate& certificate = verified.certificate;
  int by_route = 0;
  for (const SegmentCertificate& segment : certificate.segments) {
    for (const StepCertificate& step : segment.steps) {
      for (const int route : step.to_next.self_pair_by_revolution) by_route += route;
    }
  }
  EXPECT_GT(by_route, 0);
  const CheckReport accepted = test::check_ur5e_self(run, certificate);
  EXPECT_TRUE(accepted.accepted) << (accepted.failures.empty() ? "" : accepted.failures.front());

  // A distance from the solid beyond what the slab proves.
  Certificate inflated = certificate;
  bool found = false;
  for (SegmentCertificate& segment : inflated.segments) {
    for (StepCertificate& step : segment.steps) {
      for (SelfPairRecord& pair : step.self_pairs) {
        if (!found && pair.revolution_lower_bound > 0.0) {
          pair.revolution_lower_bound = pair.lower_bound + 1e-3;
          found = true;
        }
      }
    }
  }
  ASSERT_TRUE(found);
  const CheckReport false_distance = test::check_ur5e_self(run, inflated);
  EXPECT_FALSE(false_distance.accepted);
  EXPECT_TRUE(has_failure(false_distance, "the distance from the solid of revolution does not hold"));

  // Without the solid's distances the steps that rest on the route are not proven.
  Certificate stripped = certificate;
  for (SegmentCertificate& segment : stripped.segments) {
    for (StepCertificate& step : segment.steps) {
      for (SelfPairRecord& pair : step.self_pairs) pair.revolution_lower_bound = 0.0;
    }
  }
  const CheckReport missing = test::check_ur5e_self(run, stripped);
  EXPECT_FALSE(missing.accepted);
  EXPECT_TRUE(has_failure(missing, "the relative motion bound is not below d_k + d_k+1"));
}

}  // namespace
}  // namespace grpvss::certify

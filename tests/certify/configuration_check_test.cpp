// The certified verdict of single configurations (grpvss/certify/configuration_check.hpp):
// exact findings on the UR5e test cells, the same verdicts as the clearance probe over many
// configurations, and every slab a verdict rests on holding in rationals.
#include "grpvss/certify/configuration_check.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "certify/cell_probe.hpp"
#include "certify/configuration_verdict.hpp"
#include "grpvss/geometry/broadphase.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "support/exact_witness.hpp"
#include "support/random_configurations.hpp"
#include "support/urdf_cell_oracle.hpp"
#include "support/ur5e_self_run.hpp"

namespace grpvss::certify {
namespace {

std::vector<std::string> described(const ConfigurationVerdict& verdict, const cell::LoadedCell& loaded) {
  std::vector<std::string> text;
  for (const auto& f : verdict.findings) text.push_back(describe(f, loaded.robot, loaded.environment));
  return text;
}

// The cell's home with one joint moved to `degrees`.
Eigen::VectorXd home_with(int joint, double degrees) {
  Eigen::VectorXd q(6);
  q << 0.0, -M_PI / 2, M_PI / 2, 0.0, 0.0, 0.0;
  q[joint] = degrees * M_PI / 180.0;
  return q;
}

// Joint 1 swings the forearm into the post (ur5e-post.yaml, the path ur5e-through-post.txt):
// clear, then within the 5 mm tolerance, then colliding; at 75.5 deg the wrist also passes
// within the tolerance, and the verdict is the worst finding's.
TEST(ConfigurationCheck, NamesEveryFindingOfTheForearmSwingingIntoThePost) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-post.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  ConfigurationCheck check(cell);
  const ConfigurationVerdict clear = check.check(home_with(0, 30.0));
  EXPECT_EQ(clear.verdict, Verdict::kClear);
  EXPECT_TRUE(clear.findings.empty());
  const ConfigurationVerdict grazing = check.check(home_with(0, 63.25));
  EXPECT_EQ(grazing.verdict, Verdict::kWithinTolerance);
  EXPECT_EQ(described(grazing, loaded), std::vector<std::string>{"forearm_link / post: within tolerance"});
  const ConfigurationVerdict hit = check.check(home_with(0, 70.0));
  EXPECT_EQ(hit.verdict, Verdict::kCollision);
  EXPECT_EQ(described(hit, loaded), std::vector<std::string>{"forearm_link / post: collision"});
  const ConfigurationVerdict both = check.check(home_with(0, 75.5));
  EXPECT_EQ(both.verdict, Verdict::kCollision);
  EXPECT_EQ(described(both, loaded), (std::vector<std::string>{"forearm_link / post: collision",
                                                               "wrist_1_link / post: within tolerance"}));
}

// Joint 3 folds the wrist into the upper arm (ur5e-self.yaml, the path ur5e-fold.txt).
TEST(ConfigurationCheck, NamesBothLinksOfASelfCollision) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-self.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  ConfigurationCheck check(cell);
  EXPECT_EQ(check.check(home_with(2, 150.0)).verdict, Verdict::kClear);
  const ConfigurationVerdict folded = check.check(home_with(2, 155.0));
  EXPECT_EQ(folded.verdict, Verdict::kCollision);
  EXPECT_EQ(described(folded, loaded),
            (std::vector<std::string>{"upper_arm_link / wrist_2_link: self-collision",
                                      "upper_arm_link / wrist_3_link: self-collision"}));
}

TEST(ConfigurationCheck, RefusesAConfigurationOfTheWrongSizeOrNotFinite) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-post.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  ConfigurationCheck check(cell);
  try {
    check.check(Eigen::VectorXd::Zero(5));
    FAIL() << "a 5-value configuration was checked";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "configuration: expected 6 joint values, found 5");
  }
  Eigen::VectorXd q = home_with(0, 0.0);
  q[3] = std::nan("");
  try {
    check.check(q);
    FAIL() << "a NaN joint value was checked";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "configuration: joint 4: expected a finite value, found nan");
  }
}

// Placed points of every hull's offset and raw hull at q (the checker's placement).
struct PlacedHulls {
  std::vector<std::vector<Eigen::Vector3d>> offset_W, raw_W;
};
PlacedHulls placed_hulls(const RobotCell& cell, const Eigen::VectorXd& q) {
  kinematics::Workspace workspace(cell.robot());
  kinematics::forward_kinematics(cell.chain(), q, workspace);
  PlacedHulls placed;
  placed.offset_W.resize(cell.hulls().size());
  placed.raw_W.resize(cell.hulls().size());
  for (std::size_t i = 0; i < cell.hulls().size(); ++i) {
    const LinkHull& hull = cell.hulls()[i];
    const auto& X_WL = workspace.X_WL[static_cast<std::size_t>(hull.link)];
    kinematics::place_points(X_WL, hull.expanded_L, placed.offset_W[i]);
    kinematics::place_points(X_WL, hull.raw_L, placed.raw_W[i]);
  }
  return placed;
}

// Property: over configurations swept through the post and random ones, one warm verdict
// probe (kept normals, any ball slab) finds exactly what a fresh clearance probe (closest
// witnesses) finds, every separation it claims holds in rationals on the placed hulls (the
// self pairs' axis slabs between placed boxes included), and every obstacle it leaves without
// evidence has a box apart from the placed offset's.
// It settles most terms without its closest witness: its radii are smaller.
TEST(ConfigurationCheck, AVerdictProbeFindsWhatTheClearanceProbeFindsOnSlabsThatHoldExactly) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-post.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  ASSERT_FALSE(cell.self_pairs().empty());
  CellProbe verdict_probe(cell);
  verdict_probe.set_need(ProbeNeed::kVerdict);
  std::vector<Eigen::VectorXd> qs;
  for (int k = 0; k <= 80; ++k) qs.push_back(home_with(0, 1.25 * k));  // through the post and out
  std::mt19937_64 generator(20261127);
  for (int k = 0; k < 40; ++k) qs.push_back(test::random_configuration(loaded.robot, generator));
  int clear = 0, not_clear = 0, smaller_radii = 0, settled_by_boxes = 0, axis_slabs = 0;
  ProbeResult by_verdict, by_clearance;
  for (std::size_t k = 0; k < qs.size(); ++k) {
    verdict_probe.probe(qs[k], false, by_verdict);
    CellProbe(cell).probe(qs[k], false, by_clearance);
    const ConfigurationVerdict want = verdict_of(cell, by_clearance);
    const ConfigurationVerdict got = verdict_of(cell, by_verdict);
    ASSERT_EQ(got.verdict, want.verdict) << "configuration " << k;
    ASSERT_EQ(described(got, loaded), described(want, loaded)) << "configuration " << k;
    (got.verdict == Verdict::kClear ? clear : not_clear) += 1;
    const PlacedHulls placed = placed_hulls(cell, qs[k]);
    for (const PairEvidence& evidence : by_verdict.evidence) {
      if (!evidence.separated) continue;
      const auto h = static_cast<std::size_t>(evidence.hull_index);
      EXPECT_TRUE(test::witness_holds_exactly(evidence.witness, evidence.expanded ? placed.offset_W[h] : placed.raw_W[h],
                                              cell.obstacles().vertices_W(evidence.obstacle)))
          << "configuration " << k << " hull " << h << " obstacle " << evidence.obstacle;
    }
    // (B): an obstacle without evidence has a box apart from the placed offset's box.
    for (std::size_t h = 0; h < cell.hulls().size(); ++h) {
      for (int o = 0; o < cell.obstacles().size(); ++o) {
        const bool has_evidence = std::any_of(by_verdict.evidence.begin(), by_verdict.evidence.end(), [&](const PairEvidence& e) {
          return e.hull_index == static_cast<int>(h) && e.obstacle == o;
        });
        if (has_evidence) continue;
        ++settled_by_boxes;
        EXPECT_FALSE(geometry::Aabb::of_points(placed.offset_W[h]).overlaps(geometry::Aabb::of_points(cell.obstacles().vertices_W(o))))
            << "configuration " << k << " hull " << h << " obstacle " << o;
      }
    }
    for (std::size_t p = 0; p < cell.self_pairs().size(); ++p) {
      const SelfPairEvidence& evidence = by_verdict.self_pairs[p];
      if (!evidence.separated) continue;
      EXPECT_TRUE(test::witness_holds_exactly(evidence.witness,
                                              placed.raw_W[static_cast<std::size_t>(cell.self_pairs()[p].a)],
                                              placed.raw_W[static_cast<std::size_t>(cell.self_pairs()[p].b)]))
          << "configuration " << k << " pair " << p;
      axis_slabs += evidence.witness.normal.cwiseAbs().maxCoeff() == 1.0 && evidence.witness.normal.squaredNorm() == 1.0;
    }
    for (std::size_t i = 0; i < cell.hulls().size(); ++i) {
      smaller_radii += by_verdict.hulls[i].radius < by_clearance.hulls[i].radius - 1e-9;
    }
  }
  EXPECT_GT(clear, 50);  // 63 of 121 when written
  EXPECT_GT(not_clear, 40);
  EXPECT_GT(smaller_radii, 250);  // 367 of 847 hull radii
  EXPECT_GT(settled_by_boxes, 1000);  // 1,528 of 1,694 (hull, obstacle) pairs when written
  EXPECT_GT(axis_slabs, 100);  // self pairs settled by their placed boxes: 145 when written
}

// Soundness against the independent URDF oracle (reference FK from the URDF text, exact
// rational LP for contact; support/urdf_cell_oracle.hpp): over random UR5e configurations on
// its table beside the post, no configuration where the oracle finds a contact (with the table,
// the post or the robot itself) is CLEAR, and every COLLISION is one the oracle confirms or
// finds within a micrometre.
TEST(ConfigurationCheck, NoConfigurationTheOracleFindsInContactIsClear) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-post.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  const test::UrdfCellOracle oracle(loaded);
  ConfigurationCheck check(cell);
  std::mt19937_64 generator(27112026);
  int contacts = 0, self_contacts = 0, clear = 0;
  for (int k = 0; k < 60; ++k) {
    const Eigen::VectorXd q = test::random_configuration(loaded.robot, generator);
    const ConfigurationVerdict verdict = check.check(q);
    const test::UrdfOracleContact truth = oracle.check(q);
    if (truth.contact) {
      ++contacts;
      self_contacts += truth.self;
      EXPECT_NE(verdict.verdict, Verdict::kClear) << "configuration " << k;
    }
    if (verdict.verdict == Verdict::kClear) ++clear;
    if (verdict.verdict == Verdict::kCollision) {
      EXPECT_TRUE(truth.contact || std::min(truth.obstacle_distance, truth.self_distance) < 1e-6)
          << "configuration " << k;
    }
  }
  EXPECT_GT(contacts, 30);  // 41 of 60 when written, 8 of them self-contacts; 19 CLEAR
  EXPECT_GT(self_contacts, 5);
  EXPECT_GT(clear, 12);
}

// A probe keeps an unmoved hull's proof for the next configuration; a verdict's proof has
// radii far below the closest, so a probe told a clearance after a verdict decides every hull
// again and gives a fresh clearance probe's radii.
TEST(ConfigurationCheck, AProbeToldAClearanceAfterAVerdictDecidesEveryHullAgain) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-post.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  const Eigen::VectorXd q = home_with(0, 55.0);
  CellProbe probe(cell);
  probe.set_need(ProbeNeed::kVerdict);
  ProbeResult by_verdict, after_verdict, fresh;
  probe.probe(q, false, by_verdict);
  probe.set_need(ProbeNeed::kClearance);
  probe.probe(q, false, after_verdict);
  CellProbe(cell).probe(q, false, fresh);
  int verdict_radii_below = 0;
  for (std::size_t i = 0; i < cell.hulls().size(); ++i) {
    EXPECT_NEAR(after_verdict.hulls[i].radius, fresh.hulls[i].radius, 1e-9 * (1.0 + fresh.hulls[i].radius)) << "hull " << i;
    verdict_radii_below += by_verdict.hulls[i].radius < fresh.hulls[i].radius;
  }
  EXPECT_GE(verdict_radii_below, 3);  // the kept proofs would have lowered these
}

}  // namespace
}  // namespace grpvss::certify

// CellProbe::add_interference_points, which the verifier uses for accepted steps, adds exactly
// the points a probe with points finds: same pairs, same exact points, same order.
#include "certify/cell_probe.hpp"

#include <algorithm>
#include <map>
#include <utility>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/exact_contact.hpp"
#include "grpvss/geometry/gjk.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/io/robot_file.hpp"
#include "support/data_paths.hpp"
#include "support/exact_witness.hpp"
#include "support/random_configurations.hpp"
#include "support/ur5e_self_run.hpp"

namespace grpvss::certify {
namespace {

using grpvss::test::ibm7545_file;

void expect_same_points(const std::vector<InterferencePoint>& expected,
                        const std::vector<InterferencePoint>& actual, int configuration) {
  ASSERT_EQ(expected.size(), actual.size()) << "configuration " << configuration;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(expected[i].link, actual[i].link);
    EXPECT_EQ(expected[i].hull, actual[i].hull);
    EXPECT_EQ(expected[i].obstacle, actual[i].obstacle);
    EXPECT_EQ(expected[i].kind, actual[i].kind);
    EXPECT_EQ(expected[i].p_W, actual[i].p_W) << "configuration " << configuration << " point " << i;
  }
}

// Calls visit(cell, q, k) for 300 random configurations q of the IBM 7545 in each of its two
// sample cells (tolerance 0.5).
template <class Visit>
void for_random_configurations(std::uint64_t seed, Visit visit) {
  const RobotModel robot = io::read_robot_file(ibm7545_file("robot.txt"));
  std::mt19937_64 rng(seed);
  for (const char* environment_file : {"environment.txt", "bench-environment.txt"}) {
    const Environment environment = io::read_environment_file(ibm7545_file(environment_file));
    CellSettings options;
    options.tolerance = 0.5;
    const RobotCell cell(robot, environment, options);
    for (int k = 0; k < 300; ++k) visit(cell, test::random_configuration(robot, rng), k);
  }
}

TEST(CellProbe, AddedInterferencePointsAreThoseOfAProbeWithPoints) {
  int with_points = 0;
  for_random_configurations(7545, [&](const RobotCell& cell, const Eigen::VectorXd& q, int k) {
    CellProbe reference(cell);
    CellProbe added(cell);
    ProbeResult full, trial;
    reference.probe(q, /*with_points=*/true, full);
    added.probe(q, /*with_points=*/false, trial);
    ASSERT_TRUE(trial.interference_points.empty());
    added.add_interference_points(trial);
    expect_same_points(full.interference_points, trial.interference_points, k);
    with_points += full.interference_points.empty() ? 0 : 1;
  });
  EXPECT_GT(with_points, 20);  // the property is exercised, not vacuous
}

// True if some point of `points` has `kind` and lies within 1e-9 in. of `p`.
bool has_point_near(const std::vector<std::pair<std::string, Eigen::Vector3d>>& points,
                    const std::string& kind, const Eigen::Vector3d& p) {
  return std::any_of(points.begin(), points.end(), [&](const auto& point) {
    return point.first == kind && (point.second - p).norm() < 1e-9;
  });
}

// The probe computes a pair's points in the link frame (the offset's exact hull prebuilt, the
// obstacle placed by X_LW) and maps them back by X_WL. Reference: the exact points of the
// offset placed in the world frame and hulled from scratch with the obstacle's world hull,
// as the probe did before. Each is exact for its own placement; the placements differ by the
// FK rounding. The contained vertices agree both ways within 1e-9 in. Edge points can
// differ where faces are coplanar only up to rounding (the offset's vertices are rounded
// Minkowski sums, the obstacle's decimal inputs): such a face is two triangles, and which
// diagonal is an edge depends on the rounding, in either frame. So every edge point must lie
// on both placed hulls in the world frame (within 1e-9 in. of each) and the pair must have a
// point in both computations.
TEST(CellProbe, LinkFramePointsAreTheWorldFramePlacedOffsetsPoints) {
  int pairs_compared = 0;
  for_random_configurations(4341, [&](const RobotCell& cell, const Eigen::VectorXd& q, int k) {
    CellProbe probe(cell);
    ProbeResult result;
    probe.probe(q, /*with_points=*/true, result);
    kinematics::Workspace workspace(cell.robot());
    kinematics::forward_kinematics(cell.chain(), q, workspace);
    std::vector<Eigen::Vector3d> placed_W;
    for (const PairEvidence& evidence : result.evidence) {
      if (!evidence.expanded || evidence.separated) continue;
      const LinkHull& hull = cell.hulls()[static_cast<std::size_t>(evidence.hull_index)];
      kinematics::place_points(workspace.X_WL[hull.link], hull.expanded_L, placed_W);
      std::vector<std::pair<std::string, Eigen::Vector3d>> reference, found;
      for (const auto& point : geometry::interference_points(
               geometry::ConvexPolytope::from_points(placed_W),
               cell.obstacles().polytope_W(evidence.obstacle))) {
        reference.emplace_back(geometry::to_string(point.kind), point.point);
      }
      for (const InterferencePoint& point : result.interference_points) {
        if (point.link == hull.link && point.hull == hull.hull &&
            point.obstacle == evidence.obstacle) {
          found.emplace_back(geometry::to_string(point.kind), point.p_W);
        }
      }
      ASSERT_FALSE(found.empty()) << "configuration " << k;
      ASSERT_FALSE(reference.empty()) << "configuration " << k;
      const auto& obstacle_W = cell.obstacles().vertices_W(evidence.obstacle);
      for (const auto& [kind, p] : found) {
        if (kind.rfind("vertex", 0) == 0) {
          EXPECT_TRUE(has_point_near(reference, kind, p)) << "configuration " << k;
        } else {
          EXPECT_LT(geometry::gjk({p}, placed_W).distance, 1e-9) << "configuration " << k;
          EXPECT_LT(geometry::gjk({p}, obstacle_W).distance, 1e-9) << "configuration " << k;
        }
      }
      for (const auto& [kind, p] : reference) {
        if (kind.rfind("vertex", 0) == 0) {
          EXPECT_TRUE(has_point_near(found, kind, p)) << "configuration " << k;
        }
      }
      ++pairs_compared;
    }
  });
  EXPECT_GT(pairs_compared, 20);  // the property is exercised, not vacuous
}

std::vector<PairEvidence> evidence_of(const ProbeResult& result, int hull_index) {
  std::vector<PairEvidence> found;
  for (const PairEvidence& evidence : result.evidence) {
    if (evidence.hull_index == hull_index) found.push_back(evidence);
  }
  return found;
}

void expect_same_evidence(const std::vector<PairEvidence>& expected,
                          const std::vector<PairEvidence>& actual, int configuration) {
  ASSERT_EQ(expected.size(), actual.size()) << "configuration " << configuration;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(expected[i].obstacle, actual[i].obstacle);
    EXPECT_EQ(expected[i].expanded, actual[i].expanded);
    EXPECT_EQ(expected[i].separated, actual[i].separated);
    EXPECT_EQ(expected[i].witness.normal, actual[i].witness.normal);
    EXPECT_EQ(expected[i].witness.offset_a, actual[i].witness.offset_a);
    EXPECT_EQ(expected[i].witness.offset_b, actual[i].witness.offset_b);
    EXPECT_EQ(expected[i].lower_bound, actual[i].lower_bound) << "configuration " << configuration;
  }
}

// A probe keeps what it proved for a hull none of whose offset's pairs interfere and copies it
// when the hull's link is placed bit for bit the same again. After a move of one joint the
// links before it are such hulls: their proofs must be exactly what a fresh probe proves there
// (same inputs, no warm start in either), and the links the joint moves must be decided anew
// (a stale copy would keep the old radius; checked by breaking the pose comparison).
TEST(CellProbe, AHullWhoseLinkDidNotMoveKeepsItsProofAndAMovedOneIsDecidedAgain) {
  int unmoved = 0;
  int decided_again = 0;
  std::mt19937_64 joint_rng(42);
  for_random_configurations(4341, [&](const RobotCell& cell, const Eigen::VectorXd& q1, int k) {
    const int joint = std::uniform_int_distribution<int>(0, 3)(joint_rng);  // moves links > joint
    Eigen::VectorXd q2 = q1;
    const Joint& limits = cell.robot().joints[static_cast<std::size_t>(joint)];
    q2[joint] = 0.5 * (limits.minimum + limits.maximum) + 0.25 * (limits.maximum - q1[joint]);
    CellProbe reusing(cell);
    CellProbe fresh(cell);
    ProbeResult first, second, reference;
    reusing.probe(q1, /*with_points=*/false, first);
    reusing.probe(q2, /*with_points=*/false, second);
    fresh.probe(q2, /*with_points=*/false, reference);
    for (int i = 0; i < static_cast<int>(cell.hulls().size()); ++i) {
      const HullState& got = second.hulls[static_cast<std::size_t>(i)];
      const HullState& want = reference.hulls[static_cast<std::size_t>(i)];
      EXPECT_EQ(got.expanded_interferes, want.expanded_interferes) << "configuration " << k;
      EXPECT_EQ(got.raw_collides, want.raw_collides) << "configuration " << k;
      // A hull whose offset meets an obstacle is decided anew even when it did not move.
      if (cell.hulls()[static_cast<std::size_t>(i)].link <= joint && !want.expanded_interferes) {
        ++unmoved;
        EXPECT_EQ(got.radius, want.radius) << "configuration " << k << " hull " << i;
        expect_same_evidence(evidence_of(reference, i), evidence_of(second, i), k);
      } else {
        ++decided_again;
        // Warm-started from q1's witnesses: the same proof up to GJK's convergence.
        EXPECT_NEAR(got.radius, want.radius, 1e-9 * (1.0 + want.radius))
            << "configuration " << k << " hull " << i;
      }
    }
  });
  EXPECT_GT(unmoved, 2000);
  EXPECT_GT(decided_again, 2000);
}

// The UR5e motion beside the post of the kept-normal tests (ur5e-post.yaml): configuration k of
// kBesideThePostSteps + 1 from the cell's home, probed by `warm` and by a fresh probe.
constexpr int kBesideThePostSteps = 60;
struct WarmAndFresh {
  ProbeResult warm;
  ProbeResult fresh;
};
WarmAndFresh probe_beside_the_post(const RobotCell& cell, CellProbe& warm, int k) {
  Eigen::VectorXd from(6), to(6);
  from << 0.0, -1.5708, 1.5708, 0.0, 0.0, 0.0;  // the cell's home
  to << -0.9, -1.3, 1.4, -0.3, 0.5, 0.2;
  const Eigen::VectorXd q = from + (to - from) * (static_cast<double>(k) / kBesideThePostSteps);
  WarmAndFresh result;
  warm.probe(q, /*with_points=*/false, result.warm);
  CellProbe(cell).probe(q, /*with_points=*/false, result.fresh);
  return result;
}

// Once a nearer obstacle has set a hull's smallest clearance, the probe proves the next ones on
// their last witness normal (no GJK) and keeps that proof only when it does not lower the
// clearance. Along a UR5e motion beside the post, probed step after step by one warm probe and
// by a fresh probe at each configuration: every hull's radius is the fresh probe's (a kept
// normal never sets it), the kept-normal proofs are there (the same normal as the step before,
// a smaller bound than the fresh query's), and every witness holds exactly on the placed offset.
TEST(CellProbe, AKeptNormalProvesAFartherObstacleWithoutChangingAnyHullsRadius) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-post.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  CellProbe warm(cell);
  std::map<std::pair<int, int>, Eigen::Vector3d> last_normal;  // (hull, obstacle) -> normal
  kinematics::Workspace workspace(cell.robot());
  std::vector<Eigen::Vector3d> placed_offset_W;
  int kept_normal_proofs = 0;
  for (int k = 0; k <= kBesideThePostSteps; ++k) {
    const auto [warm_result, fresh_result] = probe_beside_the_post(cell, warm, k);
    ASSERT_FALSE(warm_result.any_expanded_interference) << "step " << k;
    kinematics::forward_kinematics(cell.chain(), warm_result.q, workspace);
    for (int i = 0; i < static_cast<int>(cell.hulls().size()); ++i) {
      const double want = fresh_result.hulls[static_cast<std::size_t>(i)].radius;
      EXPECT_NEAR(warm_result.hulls[static_cast<std::size_t>(i)].radius, want, 1e-9 * (1.0 + want))
          << "step " << k << " hull " << i;
      const LinkHull& hull = cell.hulls()[static_cast<std::size_t>(i)];
      kinematics::place_points(workspace.X_WL[static_cast<std::size_t>(hull.link)], hull.expanded_L,
                               placed_offset_W);
      const std::vector<PairEvidence> fresh_evidence = evidence_of(fresh_result, i);
      double smallest = std::numeric_limits<double>::infinity();
      for (const PairEvidence& evidence : evidence_of(warm_result, i)) smallest = std::min(smallest, evidence.lower_bound);
      for (const PairEvidence& evidence : evidence_of(warm_result, i)) {
        ASSERT_TRUE(evidence.separated);
        EXPECT_TRUE(test::witness_holds_exactly(evidence.witness, placed_offset_W,
                                          cell.obstacles().vertices_W(evidence.obstacle)))
            << "step " << k << " hull " << i << " obstacle " << evidence.obstacle;
        const auto key = std::make_pair(i, evidence.obstacle);
        const auto last = last_normal.find(key);
        const auto fresh = std::find_if(fresh_evidence.begin(), fresh_evidence.end(),
                                        [&](const PairEvidence& e) { return e.obstacle == evidence.obstacle; });
        if (k > 0 && last != last_normal.end() && last->second == evidence.witness.normal &&
            fresh != fresh_evidence.end() && evidence.lower_bound < fresh->lower_bound - 1e-12) {
          ++kept_normal_proofs;
          EXPECT_GT(evidence.lower_bound, smallest) << "step " << k << " hull " << i;  // not the nearest
        }
        last_normal[key] = evidence.witness.normal;
      }
    }
  }
  EXPECT_GT(kept_normal_proofs, 20);  // the kept normals are exercised, not vacuous
}

// How many loose terms a warm probe proved on their kept normals along a motion (next test).
struct LooseProofs {
  int hulls = 0;
  int pairs = 0;
};

// A term the march's last transition left loose (far from limiting the step) may be proven on its
// kept witness normal alone, its nearest obstacle included: no GJK. Along `steps` + 1
// configurations from `from` to `to`, one warm probe told every hull and pair is loose, against a
// fresh probe at each configuration: every witness holds exactly on the placed offset or raw hulls
// (a proven slab is evidence), such proofs are there (the normal kept from the step before, a
// bound below the fresh query's), and each keeps at least kLooseKeep of the bound its normal was
// found with (by GJK) -- below that the normal is stale and GJK runs again.
LooseProofs expect_loose_terms_on_kept_normals(const RobotCell& cell, const Eigen::VectorXd& from,
                                               const Eigen::VectorXd& to, int steps) {
  CellProbe warm(cell);
  // Every term loose, with no floor: only kLooseKeep limits the kept normals.
  const double no_floor = -std::numeric_limits<double>::infinity();
  warm.set_loose_terms({std::vector<double>(cell.hulls().size(), no_floor),
                        std::vector<double>(cell.self_pairs().size(), no_floor)});
  struct Kept {
    Eigen::Vector3d normal;
    double found_with = 0.0;  // the bound at the probe that found the normal
  };
  std::map<std::pair<int, int>, Kept> kept;  // (hull, obstacle) or (-1, pair) -> its normal
  kinematics::Workspace workspace(cell.robot());
  std::vector<Eigen::Vector3d> placed_offset_W;
  std::vector<std::vector<Eigen::Vector3d>> placed_raw_W(cell.hulls().size());
  LooseProofs proofs;
  // A bound proven on the normal kept from the step before, below the fresh query's: a loose
  // term's must keep kLooseKeep of the bound that normal was found with; a farther obstacle's
  // (`nearest_bound` below it) must not lower the hull's radius, as in the test above.
  const auto check_kept = [&](const std::pair<int, int>& key, const Eigen::Vector3d& normal, double bound,
                              double fresh_bound, double nearest_bound, int step, int& proven) {
    const auto last = kept.find(key);
    if (step > 0 && last != kept.end() && last->second.normal == normal && bound < fresh_bound - 1e-12) {
      if (nearest_bound < bound) {
        EXPECT_GE(bound, nearest_bound) << "step " << step;
        return;
      }
      ++proven;
      EXPECT_GE(bound, kLooseKeep * last->second.found_with) << "step " << step;
      return;
    }
    kept[key] = {normal, bound};
  };
  for (int k = 0; k <= steps; ++k) {
    const Eigen::VectorXd q = from + (to - from) * (static_cast<double>(k) / steps);
    ProbeResult warm_result;
    ProbeResult fresh_result;
    warm.probe(q, /*with_points=*/false, warm_result);
    CellProbe(cell).probe(q, /*with_points=*/false, fresh_result);
    EXPECT_FALSE(warm_result.any_expanded_interference) << "step " << k;
    if (warm_result.any_expanded_interference) return proofs;
    kinematics::forward_kinematics(cell.chain(), warm_result.q, workspace);
    for (int i = 0; i < static_cast<int>(cell.hulls().size()); ++i) {
      const LinkHull& hull = cell.hulls()[static_cast<std::size_t>(i)];
      kinematics::place_points(workspace.X_WL[static_cast<std::size_t>(hull.link)], hull.expanded_L, placed_offset_W);
      kinematics::place_points(workspace.X_WL[static_cast<std::size_t>(hull.link)], hull.raw_L,
                               placed_raw_W[static_cast<std::size_t>(i)]);
      const std::vector<PairEvidence> fresh_evidence = evidence_of(fresh_result, i);
      double nearest_bound = std::numeric_limits<double>::infinity();
      for (const PairEvidence& evidence : evidence_of(warm_result, i)) nearest_bound = std::min(nearest_bound, evidence.lower_bound);
      for (const PairEvidence& evidence : evidence_of(warm_result, i)) {
        EXPECT_TRUE(evidence.separated);
        EXPECT_TRUE(test::witness_holds_exactly(evidence.witness, placed_offset_W,
                                          cell.obstacles().vertices_W(evidence.obstacle)))
            << "step " << k << " hull " << i << " obstacle " << evidence.obstacle;
        const auto fresh = std::find_if(fresh_evidence.begin(), fresh_evidence.end(),
                                        [&](const PairEvidence& e) { return e.obstacle == evidence.obstacle; });
        EXPECT_NE(fresh, fresh_evidence.end());
        if (fresh == fresh_evidence.end()) continue;
        check_kept({i, evidence.obstacle}, evidence.witness.normal, evidence.lower_bound, fresh->lower_bound,
                   nearest_bound, k, proofs.hulls);
      }
    }
    for (std::size_t p = 0; p < cell.self_pairs().size(); ++p) {
      const SelfPairEvidence& evidence = warm_result.self_pairs[p];
      EXPECT_TRUE(evidence.separated) << "step " << k << " pair " << p;
      const SelfPairHulls& pair = cell.self_pairs()[p];
      EXPECT_TRUE(test::witness_holds_exactly(evidence.witness, placed_raw_W[static_cast<std::size_t>(pair.a)],
                                        placed_raw_W[static_cast<std::size_t>(pair.b)]))
          << "step " << k << " pair " << p;
      check_kept({-1, static_cast<int>(p)}, evidence.witness.normal, evidence.lower_bound,
                 fresh_result.self_pairs[p].lower_bound, evidence.lower_bound, k, proofs.pairs);
    }
  }
  return proofs;
}

// The UR5e beside the post: its CAD hulls and offsets are proven on their templates.
TEST(CellProbe, ALooseTermIsProvenOnItsKeptNormalWhileItKeepsMostOfItsLastClosestBound) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-post.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  ASSERT_FALSE(cell.self_pairs().empty());
  Eigen::VectorXd from(6), to(6);
  from << 0.0, -1.5708, 1.5708, 0.0, 0.0, 0.0;  // the cell's home
  to << -0.9, -1.3, 1.4, -0.3, 0.5, 0.2;
  const LooseProofs proofs = expect_loose_terms_on_kept_normals(cell, from, to, kBesideThePostSteps);
  // Exercised, not vacuous: hulls' nearest obstacles and self pairs both.
  EXPECT_GT(proofs.hulls, 20);
  EXPECT_GT(proofs.pairs, 20);
}

// The six-axis robot past its post and over its table: every hull and offset is below the
// template size, so the kept normals are proven on the placed points.
TEST(CellProbe, ALooseTermOfHullsBelowTheTemplateSizeIsProvenOnThePlacedPoints) {
  const cell::LoadedCell loaded = cell::load_cell(test::kSourceDir + "/data/sixaxis/cell.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  ASSERT_FALSE(cell.self_pairs().empty());
  for (const LinkHull& hull : cell.hulls()) {
    ASSERT_FALSE(hull.raw_on_template);
    ASSERT_LT(hull.expanded_template_max_abs_L, 0.0);
  }
  Eigen::VectorXd from(6), to(6);
  from << 0.0, 0.0, 0.0, 0.0, 0.0, 0.0;  // the cell's home
  to << -0.675, 0.375, 0.45, -0.225, 0.375, 0.15;
  const LooseProofs proofs = expect_loose_terms_on_kept_normals(cell, from, to, 45);
  EXPECT_GT(proofs.hulls, 20);  // 187 when written
  EXPECT_GT(proofs.pairs, 20);  // 341
}

// The probe is asked for points only when the world-frame query finds the pair interfering.
// If the pair merely touches there, the link-frame images (the obstacle placed by X_LW, rounded
// differently) may miss by a rounding, and the probe must fall back to the world-frame placed
// offset rather than list no point. Each case puts a box exactly against the world-placed
// quill offset's extreme vertex in x, so the pair touches there only (in that vertex, or along
// the vertical edge through it: the joints turn about z).
TEST(CellProbe, APairTouchingOnlyInTheWorldFrameStillHasItsPoint) {
  const RobotModel robot = io::read_robot_file(ibm7545_file("robot.txt"));
  const CellSettings options{0.5, geometry::OffsetShape::kCube};
  const std::size_t quill = 10;  // link 4 hull 0, the last of the IBM 7545's 11 hulls
  std::mt19937_64 rng(7545);
  int touching = 0;
  for (int k = 0; k < 40; ++k) {
    const Eigen::VectorXd q = test::random_configuration(robot, rng);
    // The world-placed offset, exactly as the probe places it (the cell is obstacle-free).
    // The cell refers to its environment: it must outlive the cell (no temporary).
    const Environment free_environment{1.0, 0.1, {}};
    const RobotCell free_cell(robot, free_environment, options);
    ASSERT_EQ(free_cell.hulls()[quill].link, 4);
    kinematics::Workspace workspace(robot);
    kinematics::forward_kinematics(free_cell.chain(), q, workspace);
    std::vector<Eigen::Vector3d> placed_W;
    kinematics::place_points(workspace.X_WL[4], free_cell.hulls()[quill].expanded_L, placed_W);
    const Eigen::Vector3d v = *std::max_element(
        placed_W.begin(), placed_W.end(),
        [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a.x() < b.x(); });
    HullPoints box;
    for (double dx : {0.0, 1.0}) {
      for (double dy : {-1.0, 1.0}) {
        for (double dz : {-1.0, 1.0}) box.points.emplace_back(v.x() + dx, v.y() + dy, v.z() + dz);
      }
    }
    const Environment environment{1.0, 0.1, {box}};
    const RobotCell cell(robot, environment, options);
    CellProbe probe(cell);
    ProbeResult result;
    probe.probe(q, /*with_points=*/true, result);
    if (!result.hulls[quill].expanded_interferes) continue;
    ++touching;
    int quill_points = 0;
    for (const InterferencePoint& point : result.interference_points) {
      if (point.link != 4) continue;  // other links may reach into the box
      ++quill_points;
      // On the box's face x = v.x: the vertex, or the vertical edge through it.
      EXPECT_LT(std::abs(point.p_W.x() - v.x()), 1e-9) << "configuration " << k;
    }
    EXPECT_GT(quill_points, 0) << "configuration " << k;
  }
  EXPECT_GT(touching, 20);
}

}  // namespace
}  // namespace grpvss::certify

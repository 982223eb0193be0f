// The revolution route weighed vertex by vertex (proofs/two-ball-cover.md#revolution-vertex-bound):
// when hull b's own revolute joint is all that moves it relative to hull a's solid of revolution,
// M_v = max_v (V_b D(v) - min(e_k(v), e_k+1(v))) stands in for the route's M'. Tested: the lemma's
// pointwise inequality on sampled points of the hull and its distance statement against CGAL's
// exact distance, along steps of the UR5e's shoulder-lift joint; the checker's exact M_v against a
// long-double reference built from the definition, and its refusals.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "certify/cell_probe.hpp"
#include "certify/step_axis_radius.hpp"
#include "certify/transition_judge.hpp"
#include "certify/vertex_route.hpp"
#include "checker/checked_cell.hpp"
#include "checker/transition_check.hpp"
#include "grpvss/cell/load_cell.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/geometry/separation_witness.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "support/ur5e_self_run.hpp"

namespace grpvss::certify {
namespace {

using Points = std::vector<Eigen::Vector3d>;
using Vector3l = Eigen::Matrix<long double, 3, 1>;

// X p in long double (the reference's placement of a link point).
Vector3l place_long(const Eigen::Isometry3d& X, const Vector3l& p) {
  Vector3l out = X.translation().cast<long double>();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out[i] += static_cast<long double>(X.linear()(i, j)) * p[j];
  }
  return out;
}

// The point's clearance beyond the witness's plane on b's side, (n.x - o_b) / |n|.
long double excess_long(const geometry::SeparationWitness& witness, const Vector3l& x) {
  const Vector3l n = witness.normal.cast<long double>();
  return (n.dot(x) - static_cast<long double>(witness.offset_b)) / std::sqrt(n.dot(n));
}

// The distance of x from the z axis of the joint frame X_WJ.
long double axis_distance_long(const Eigen::Isometry3d& X_WJ, const Vector3l& x) {
  const Vector3l o = X_WJ.translation().cast<long double>();
  Vector3l z = X_WJ.linear().col(2).cast<long double>();
  z /= std::sqrt(z.dot(z));
  const Vector3l d = x - o;
  return std::sqrt(std::max(0.0L, d.dot(d) - d.dot(z) * d.dot(z)));
}

struct Step {
  Eigen::VectorXd q0, q1;
};

// Steps of the shoulder-lift joint (up to 0.6 rad) with the base turning (frozen on the route)
// and the other joints a little, near the base.
std::vector<Step> shoulder_steps(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Step> steps;
  for (int trial = 0; trial < count; ++trial) {
    Step step{Eigen::VectorXd(6), Eigen::VectorXd(6)};
    step.q0 << u(rng), -2.2 + 0.5 * u(rng), 2.2 + 0.4 * u(rng), u(rng), u(rng), u(rng);
    step.q1 = step.q0;
    step.q1[0] += 1.0 * u(rng);
    step.q1[1] += 0.6 * u(rng);
    for (int j = 2; j < 6; ++j) step.q1[j] += 0.01 * u(rng);
    steps.push_back(step);
  }
  return steps;
}

TEST(VertexRouteLemma, TheExactDistanceKeepsTheGapAlongStepsTheVertexBoundProves) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-self.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  const StepAxisRadii radii(cell);
  CellProbe probe(cell);
  kinematics::Workspace workspace(cell.robot());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> weight(0.0, 1.0);
  int with_vertex_route = 0;
  int checked = 0;
  int proven_only_by_vertices = 0;
  long double tightest_pointwise = 1e300L;
  for (const Step& step : shoulder_steps(40, 9)) {
    ProbeResult from, to;
    probe.probe(step.q0, false, from);
    probe.probe(step.q1, false, to);
    StepAxisDistances axis;
    axis.radii = &radii;
    radii.axis_distances(from, axis.from);
    radii.axis_distances(to, axis.to);
    axis.increments_up = increments_up(step.q0, step.q1, Eigen::VectorXd());
    const Eigen::VectorXd dq = step.q1 - step.q0;
    for (std::size_t p = 0; p < cell.self_pairs().size(); ++p) {
      const SelfPairHulls& pair = cell.self_pairs()[p];
      if (!has_vertex_route(cell, pair)) continue;
      ++with_vertex_route;
      const LinkHull& a = cell.hulls()[static_cast<std::size_t>(pair.a)];
      const LinkHull& b = cell.hulls()[static_cast<std::size_t>(pair.b)];
      const double vertex_bound = vertex_route_motion_bound(cell, p, from, to, axis);
      const double route_bound = revolution_motion_bound(cell, pair, dq, &axis);
      const double c_from = from.self_pairs[p].revolution_distance;
      const double c_to = to.self_pairs[p].revolution_distance;
      if (!(vertex_bound < allowance_down(c_from, c_to))) continue;
      ++checked;
      if (!(route_bound < allowance_down(c_from, c_to))) ++proven_only_by_vertices;
      // The core inequality: V rho(p) <= min(e_k(p), e_k+1(p)) + M_v at points inside hull b.
      const long double variation = std::fabs(static_cast<long double>(dq[b.link - 1]));
      // Every vertex (where the maximum is), then points inside drawn towards a vertex or two.
      const int vertices = static_cast<int>(b.raw_L.size());
      for (int sample = 0; sample < vertices + 200; ++sample) {
        Vector3l point = Vector3l::Zero();
        if (sample < vertices) {
          point = b.raw_L[static_cast<std::size_t>(sample)].cast<long double>();
        } else {
          long double total = 0.0L;
          for (const Eigen::Vector3d& v : b.raw_L) {
            const long double w = std::pow(static_cast<long double>(weight(rng)), 8.0L);
            point += w * v.cast<long double>();
            total += w;
          }
          point /= total;
        }
        const Vector3l at_from = place_long(from.X_WL[static_cast<std::size_t>(b.link)], point);
        const Vector3l at_to = place_long(to.X_WL[static_cast<std::size_t>(b.link)], point);
        const long double arc =
            variation * axis_distance_long(from.X_WJ[static_cast<std::size_t>(b.link - 1)], at_from);
        const long double excess = std::min(excess_long(from.self_pairs[p].witness, at_from),
                                            excess_long(to.self_pairs[p].witness, at_to));
        tightest_pointwise = std::min(tightest_pointwise, vertex_bound - (arc - excess));
        EXPECT_LE(arc - excess, static_cast<long double>(vertex_bound) + 1e-12L) << "pair " << p;
      }
      // The statement: the true hulls keep the gap at every sampled configuration of the step.
      const double kept = std::max(0.5 * (c_from + c_to - vertex_bound), std::max(c_from, c_to) - vertex_bound);
      for (int k = 0; k <= 8; ++k) {
        kinematics::forward_kinematics(cell.chain(), step.q0 + dq * (k / 8.0), workspace);
        Points placed_a, placed_b;
        kinematics::place_points(workspace.X_WL[static_cast<std::size_t>(a.link)], a.raw_L, placed_a);
        kinematics::place_points(workspace.X_WL[static_cast<std::size_t>(b.link)], b.raw_L, placed_b);
        const double squared = geometry::exact_distance_squared_lower(placed_a, placed_b);
        // The placed hulls are within 2 placement errors of the true ones (~1e-15 m).
        EXPECT_GE(std::sqrt(squared) + 1e-12, kept) << "pair " << p << " k " << k;
      }
    }
  }
  EXPECT_EQ(with_vertex_route, 40);  // the base / upper-arm pair, once per step
  EXPECT_EQ(checked, 12);                  // the vertex bound proves the pair
  EXPECT_EQ(proven_only_by_vertices, 9);   // M' alone could not
  EXPECT_GE(tightest_pointwise, 0.0L);
}

// The checker's exact M_v (TransitionCheck) on a certified UR5e path, against a long-double
// reference from the definition: max(0, max_v (V min(rho_k(v), rho_k+1(v)) - min(e_k(v), e_k+1(v)))).
// The checker adds the placement error to each rho: it may exceed the reference by V eps only.
TEST(VertexRoute, TheCheckerFormsItExactlyFromTheCertificateAndRefusesAWitnessOnTheWrongSide) {
  const test::Ur5eSelfInputs run = test::load_ur5e_self("ur5e-self.yaml", "ur5e-shoulder.txt");
  const VerificationRun verified = test::verify_ur5e_self(run);
  ASSERT_EQ(verified.result.verdict, Verdict::kClear);
  const Certificate& certificate = verified.certificate;
  const CheckReport accepted = test::check_ur5e_self(run, certificate);
  EXPECT_TRUE(accepted.accepted) << (accepted.failures.empty() ? "" : accepted.failures.front());

  CheckReport report;
  CheckLedger ledger(report, 1000);
  ClaimFacts facts;
  MotionClearances clearances(run.cell.robot.links.size());  // per link, as the checker keeps them
  const std::optional<CheckedCell> cell =
      CheckedCell::build(run.cell.robot, run.cell.environment, certificate, ledger);
  ASSERT_TRUE(cell.has_value());
  TransitionCheck transitions(*cell, certificate, ledger, facts, clearances);
  kinematics::Workspace from_frames(run.cell.robot), to_frames(run.cell.robot);
  const auto placed_hulls = [&](const kinematics::Workspace& frames) {
    std::vector<Points> placed(cell->hulls().size());
    for (std::size_t i = 0; i < placed.size(); ++i) {
      const CheckedHull& hull = cell->hulls()[i];
      kinematics::place_points(frames.X_WL[static_cast<std::size_t>(hull.link)], hull.raw_L, placed[i]);
    }
    return placed;
  };
  const std::vector<Rational> no_radius(cell->hulls().size(), Rational(0));
  int compared = 0;
  int below_the_route = 0;
  bool refused = false;
  for (const SegmentCertificate& segment : certificate.segments) {
    for (std::size_t k = 0; k + 1 < segment.steps.size(); ++k) {
      const StepCertificate& from = segment.steps[k];
      StepCertificate to = segment.steps[k + 1];
      kinematics::forward_kinematics(cell->chain(), from.q, from_frames);
      kinematics::forward_kinematics(cell->chain(), to.q, to_frames);
      const std::vector<Points> placed_from = placed_hulls(from_frames);
      const std::vector<Points> placed_to = placed_hulls(to_frames);
      transitions.check(from, to, no_radius, no_radius, placed_from, placed_to, false, "t");
      const SelfPairBounds& bounds = transitions.self_pair_bounds();
      for (std::size_t p = 0; p < cell->self_pairs().size(); ++p) {
        const std::optional<Rational> vertex_bound = transitions.vertex_route_bound(p, from, to, placed_from, placed_to);
        if (!vertex_bound) continue;
        const int b = cell->self_pairs()[p].second;
        const int joint = cell->hulls()[static_cast<std::size_t>(b)].link;
        const long double variation = std::fabs(static_cast<long double>(to.q[joint - 1]) - from.q[joint - 1]);
        long double reference = 0.0L;
        for (std::size_t v = 0; v < placed_from[static_cast<std::size_t>(b)].size(); ++v) {
          const Vector3l at_from = placed_from[static_cast<std::size_t>(b)][v].cast<long double>();
          const Vector3l at_to = placed_to[static_cast<std::size_t>(b)][v].cast<long double>();
          const long double rho =
              std::min(axis_distance_long(from_frames.X_WJ[static_cast<std::size_t>(joint - 1)], at_from),
                       axis_distance_long(to_frames.X_WJ[static_cast<std::size_t>(joint - 1)], at_to));
          const long double excess = std::min(excess_long(from.self_pairs[p].witness, at_from),
                                              excess_long(to.self_pairs[p].witness, at_to));
          reference = std::max(reference, variation * rho - excess);
        }
        const long double exact_bound = vertex_bound->get_d();
        EXPECT_GE(exact_bound, reference - 1e-15L) << "step " << from.step << " pair " << p;
        EXPECT_LE(exact_bound, reference + variation * 1e-9L + 1e-15L) << "step " << from.step;
        ++compared;
        if (bounds.revolution[p] && *vertex_bound < *bounds.revolution[p]) ++below_the_route;
        if (refused) continue;
        // A witness whose plane passes beyond one of hull b's vertices gives no excess: refused.
        to.self_pairs[p].witness.offset_b += 1.0;
        transitions.check(from, to, no_radius, no_radius, placed_from, placed_to, false, "t");
        EXPECT_FALSE(transitions.vertex_route_bound(p, from, to, placed_from, placed_to).has_value());
        to.self_pairs[p].witness.offset_b = std::numeric_limits<double>::infinity();
        transitions.check(from, to, no_radius, no_radius, placed_from, placed_to, false, "t");
        EXPECT_FALSE(transitions.vertex_route_bound(p, from, to, placed_from, placed_to).has_value());
        refused = true;
      }
    }
  }
  // M_v belongs to the transition checked last: asking for another is the caller's mistake.
  const SegmentCertificate& first = certificate.segments.front();
  ASSERT_GE(first.steps.size(), 2u);
  ASSERT_NE(first.steps[1].step, certificate.segments.back().steps.back().step);
  EXPECT_THROW(static_cast<void>(transitions.vertex_route_bound(0, first.steps[0], first.steps[1], {}, {})),
               std::logic_error);
  EXPECT_EQ(compared, 26);         // transitions with both ends' witnesses usable
  EXPECT_EQ(below_the_route, 24);  // where M_v is the smaller route bound
  EXPECT_TRUE(refused);
}

// The round-off margin of e (proofs/two-ball-cover.md#vertex-excess): every vertex's e, and every
// cluster's, is at most the exact (n.x - o_b)/|n| of its placed vertices, decided in rationals.
TEST(VertexRouteEnd, EveryExcessIsAtMostTheExactClearanceBeyondThePlane) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-self.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  const StepAxisRadii radii(cell);
  CellProbe probe(cell);
  int ends = 0;
  int positive = 0;
  for (const Step& step : shoulder_steps(20, 21)) {
    ProbeResult at;
    probe.probe(step.q0, false, at);
    for (std::size_t p = 0; p < cell.self_pairs().size(); ++p) {
      if (!has_vertex_route(cell, cell.self_pairs()[p])) continue;
      VertexRouteEnd end;
      if (!end.reset(radii, p, at)) continue;
      ++ends;
      const LinkHull& b = cell.hulls()[static_cast<std::size_t>(cell.self_pairs()[p].b)];
      const geometry::SeparationWitness& w = at.self_pairs[p].witness;
      mpq_class normal_square = 0;
      for (int k = 0; k < 3; ++k) normal_square += mpq_class(w.normal[k]) * mpq_class(w.normal[k]);
      // e <= (n.x - o_b)/|n| with n.x - o_b >= 0: e < 0 never, e |n| <= n.x - o_b, squared.
      const auto below_exact = [&](double excess, const Eigen::Vector3d& x) {
        mpq_class beyond = -mpq_class(w.offset_b);
        for (int k = 0; k < 3; ++k) beyond += mpq_class(w.normal[k]) * mpq_class(x[k]);
        if (excess == 0.0) return true;
        return excess > 0.0 && beyond >= 0 && mpq_class(excess) * mpq_class(excess) * normal_square <= beyond * beyond;
      };
      for (std::size_t i = 0; i < end.cluster_count(); ++i) {
        end.evaluate(i);
        for (const int v : b.vertex_clusters_L[i].members) {
          const Eigen::Vector3d placed = at.X_WL[static_cast<std::size_t>(b.link)] * b.raw_L[static_cast<std::size_t>(v)];
          EXPECT_TRUE(below_exact(end.vertex_excess(v), placed)) << "vertex " << v;
          EXPECT_TRUE(below_exact(end.cluster_excess(i), placed)) << "cluster " << i << " vertex " << v;
          if (end.vertex_excess(v) > 0.0) ++positive;
        }
      }
    }
  }
  EXPECT_EQ(ends, 20);
  EXPECT_GT(positive, 1000);  // the margin costs ~1e-15 m, not the terms themselves
}

// The kept ends (vertex_route_end) are reused only for the same run, configuration and evidence:
// e and c must come from one slab, and a later run's StepAxisRadii is another cell.
TEST(VertexRouteEnd, IsKeptOnlyForTheSameRunConfigurationAndEvidence) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-self.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  const StepAxisRadii radii(cell);
  CellProbe probe(cell);
  ProbeResult at;
  probe.probe(shoulder_steps(1, 21).front().q0, false, at);
  std::size_t p = 0;
  while (p < cell.self_pairs().size() && !has_vertex_route(cell, cell.self_pairs()[p])) ++p;
  ASSERT_LT(p, cell.self_pairs().size());
  VertexRouteEnd* first = vertex_route_end(radii, p, at);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(vertex_route_end(radii, p, at), first);
  // The same configuration with the witness's plane 1 mm farther from hull b: another end, whose
  // e is 1 mm / |n| larger.
  ProbeResult moved = at;
  moved.self_pairs[p].witness.offset_b -= 1e-3;
  VertexRouteEnd* other = vertex_route_end(radii, p, moved);
  ASSERT_NE(other, nullptr);
  EXPECT_NE(other, first);
  first = vertex_route_end(radii, p, at);
  first->evaluate(0);
  other->evaluate(0);
  const int v = cell.hulls()[static_cast<std::size_t>(cell.self_pairs()[p].b)].vertex_clusters_L[0].members.front();
  EXPECT_NEAR(other->vertex_excess(v) - first->vertex_excess(v), 1e-3 / at.self_pairs[p].witness.normal.norm(), 1e-12);
  // Another run over the same cell: never the first run's end.
  const StepAxisRadii another_run(cell);
  EXPECT_NE(vertex_route_end(another_run, p, at), first);
}

}  // namespace
}  // namespace grpvss::certify

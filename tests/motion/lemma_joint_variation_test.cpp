// Checks the inequalities of proofs/joint-variation.md against references written here:
// an exact Hermite evaluation in the textbook basis (h00, h10, h01, h11), exact sampled
// variations, an independent planar-chain forward kinematics.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <gmpxx.h>
#include <gtest/gtest.h>

#include "grpvss/io/trajectory_file.hpp"
#include "grpvss/motion/exact_joint_variation.hpp"
#include "grpvss/motion/joint_trajectory_motion.hpp"

namespace grpvss::motion {
namespace {

const std::vector<unsigned> kSeeds = {1, 7, 42, 1234, 98765};

// ---------- references ----------

/// q of piece k of joint j at the exact time t (t_k <= t <= t_{k+1}), textbook Hermite basis.
mpq_class reference_q(const JointTrajectory& trajectory, int k, int j, const mpq_class& t) {
  const mpq_class t0(trajectory.times[k]), t1(trajectory.times[k + 1]);
  const mpq_class h = t1 - t0, s = (t - t0) / h;
  const mpq_class p0(trajectory.positions[k][j]), p1(trajectory.positions[k + 1][j]);
  if (!trajectory.has_velocities()) return p0 + s * (p1 - p0);
  const mpq_class m0(trajectory.velocities[k][j]), m1(trajectory.velocities[k + 1][j]);
  const mpq_class s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * m0 + (-2 * s3 + 3 * s2) * p1 +
         (s3 - s2) * h * m1;
}

/// The exact chord sum of q_j over `samples` equal steps of every piece part of [a, b].
mpq_class sampled_variation(const JointTrajectory& trajectory, int j, double a, double b,
                            int samples = 100) {
  mpq_class total = 0;
  for (int k = 0; k + 1 < trajectory.waypoint_count(); ++k) {
    const mpq_class lo = std::max(mpq_class(a), mpq_class(trajectory.times[k]));
    const mpq_class hi = std::min(mpq_class(b), mpq_class(trajectory.times[k + 1]));
    if (lo >= hi) continue;
    mpq_class previous = reference_q(trajectory, k, j, lo);
    for (int i = 1; i <= samples; ++i) {
      const mpq_class q = reference_q(trajectory, k, j, lo + (hi - lo) * mpq_class(i, samples));
      total += abs(q - previous);
      previous = q;
    }
  }
  return total;
}

/// A random one-joint trajectory with `waypoints` waypoints; with velocities unless `linear`.
JointTrajectory random_trajectory(std::mt19937& rng, int waypoints, bool linear) {
  std::uniform_real_distribution<double> step(0.05, 3.0), position(-3.0, 3.0), rate(-6.0, 6.0);
  std::uniform_int_distribution<int> kind(0, 5);
  JointTrajectory trajectory;
  trajectory.joint_names = {"a"};
  double t = std::uniform_real_distribution<double>(0.0, 2.0)(rng);
  for (int k = 0; k < waypoints; ++k) {
    trajectory.times.push_back(t);
    t += step(rng);
    trajectory.positions.push_back(Eigen::VectorXd::Constant(1, position(rng)));
    if (!linear) trajectory.velocities.push_back(Eigen::VectorXd::Constant(1, kind(rng) == 0 ? 0.0 : rate(rng)));
  }
  return trajectory;
}

/// A random sub-interval of the trajectory's time range (whole range, a whole piece, or any).
std::pair<double, double> random_interval(std::mt19937& rng, const JointTrajectory& trajectory) {
  const double start = trajectory.times.front(), end = trajectory.times.back();
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
    case 0: return {start, end};
    case 1: {
      const int k = std::uniform_int_distribution<int>(0, trajectory.waypoint_count() - 2)(rng);
      return {trajectory.times[k], trajectory.times[k + 1]};
    }
    default: {
      double a = start + (end - start) * unit(rng), b = start + (end - start) * unit(rng);
      if (a > b) std::swap(a, b);
      return {a, b};
    }
  }
}

// ---------- Lemmas 1-3 on their own ----------

TEST(LemmaJointVariation, ControlPolygonBoundsTheVariation) {
  // proofs/joint-variation.md#lemma-bezier-form, #lemma-control-polygon
  for (unsigned seed : kSeeds) {
    std::mt19937 rng(seed);
    for (int trial = 0; trial < 40; ++trial) {
      const JointTrajectory trajectory = random_trajectory(rng, 2, false);
      auto [a, b] = random_interval(rng, trajectory);
      if (!(a < b)) continue;
      const mpq_class qa = reference_q(trajectory, 0, 0, a), qb = reference_q(trajectory, 0, 0, b);
      // dq/dt at a and b by the exact difference quotient of the cubic's blossom is awkward;
      // use the textbook derivative of the basis instead.
      const auto rate = [&](const mpq_class& t) -> mpq_class {
        const mpq_class t0(trajectory.times[0]), h = mpq_class(trajectory.times[1]) - t0;
        const mpq_class s = (t - t0) / h;
        const mpq_class p0(trajectory.positions[0][0]), p1(trajectory.positions[1][0]);
        const mpq_class m0(trajectory.velocities[0][0]), m1(trajectory.velocities[1][0]);
        return ((6 * s * s - 6 * s) * p0 + (3 * s * s - 4 * s + 1) * h * m0 +
                (-6 * s * s + 6 * s) * p1 + (3 * s * s - 2 * s) * h * m1) / h;
      };
      const mpq_class width = mpq_class(b) - mpq_class(a);
      const mpq_class c0 = qa, c1 = qa + width * rate(a) / 3, c2 = qb - width * rate(b) / 3, c3 = qb;
      // Lemma 1: the Bernstein form reproduces q at sample points.
      for (int i = 0; i <= 8; ++i) {
        const mpq_class u(i, 8), v = 1 - u;
        const mpq_class bernstein = c0 * v * v * v + 3 * c1 * u * v * v + 3 * c2 * u * u * v + c3 * u * u * u;
        ASSERT_EQ(bernstein, reference_q(trajectory, 0, 0, mpq_class(a) + width * u));
      }
      // Lemma 2: the control polygon's variation bounds the (sampled) variation.
      const mpq_class polygon = abs(c1 - c0) + abs(c2 - c1) + abs(c3 - c2);
      ASSERT_GE(polygon, sampled_variation(trajectory, 0, a, b)) << "seed " << seed;
    }
  }
}

/// The lemma's test, written from its statement.
bool lemma_monotone(const mpq_class& d0, const mpq_class& d1, const mpq_class& d2) {
  const bool rising = d0 >= 0 && d2 >= 0 && (d1 >= 0 || d1 * d1 <= d0 * d2);
  const bool falling = d0 <= 0 && d2 <= 0 && (d1 <= 0 || d1 * d1 <= d0 * d2);
  return rising || falling;
}

TEST(LemmaJointVariation, MonotoneTestAgreesWithSampledDerivative) {
  // proofs/joint-variation.md#lemma-monotone-test: phi(u) = d0 (1-u)^2 + 2 d1 u (1-u) + d2 u^2
  // keeps one sign on [0, 1] iff the test holds. The samples include the vertex of phi, where a
  // sign change is deepest, so "not monotone" is also checked exactly.
  int monotone_count = 0, changing_count = 0;
  for (int d0 = -3; d0 <= 3; ++d0) {
    for (int d1 = -4; d1 <= 4; ++d1) {
      for (int d2 = -3; d2 <= 3; ++d2) {
        const auto phi = [&](const mpq_class& u) -> mpq_class {
          return d0 * (1 - u) * (1 - u) + 2 * d1 * u * (1 - u) + d2 * u * u;
        };
        std::vector<mpq_class> samples;
        for (int i = 0; i <= 64; ++i) samples.emplace_back(i, 64);
        const mpq_class a = d0 - 2 * d1 + d2;  // phi = a u^2 + 2 (d1 - d0) u + d0
        if (a != 0) {
          const mpq_class vertex = (d0 - d1) / a;
          if (vertex > 0 && vertex < 1) samples.push_back(vertex);
        }
        bool nonnegative = true, nonpositive = true;
        for (const mpq_class& u : samples) {
          nonnegative = nonnegative && phi(u) >= 0;
          nonpositive = nonpositive && phi(u) <= 0;
        }
        EXPECT_EQ(lemma_monotone(d0, d1, d2), nonnegative || nonpositive) << d0 << " " << d1 << " " << d2;
        (nonnegative || nonpositive ? monotone_count : changing_count)++;
      }
    }
  }
  EXPECT_GT(monotone_count, 100);  // both outcomes are exercised
  EXPECT_GT(changing_count, 100);
}

// ---------- Theorem 4, Corollary 5, Lemma 6 through the library ----------

TEST(LemmaJointVariation, BoundIsNeverBelowTheSampledVariationOfRandomCubics) {
  // proofs/joint-variation.md#theorem-piece-variation, #corollary-interval-variation
  double worst_relative_excess = 0.0;
  for (unsigned seed : kSeeds) {
    std::mt19937 rng(seed);
    for (int trial = 0; trial < 24; ++trial) {
      const JointTrajectory trajectory = random_trajectory(rng, 4, trial % 5 == 0);
      const JointTrajectoryMotion motion(trajectory);
      for (int interval = 0; interval < 3; ++interval) {
        const auto [a, b] = random_interval(rng, trajectory);
        const mpq_class sampled = sampled_variation(trajectory, 0, a, b);
        const mpq_class exact = exact_variation_bound(motion, a, b)[0];
        const double rounded = motion.variation_bound(a, b)[0];
        ASSERT_GE(exact, sampled) << "seed " << seed << " trial " << trial;
        ASSERT_GE(mpq_class(rounded), exact) << "seed " << seed << " trial " << trial;
        if (sampled > 0) {
          worst_relative_excess = std::max(worst_relative_excess, mpq_class((exact - sampled) / sampled).get_d());
        }
      }
    }
  }
  // Tightness (not a soundness claim): subdivision keeps the bound within 0.2 % of the true
  // variation on these pieces (measured: see the test output).
  EXPECT_LT(worst_relative_excess, 2e-3);
  std::printf("largest (exact bound - sampled variation) / sampled variation: %.3g\n",
              worst_relative_excess);
}

TEST(LemmaJointVariation, BoundEqualsTheIncrementOnMonotonePieces) {
  // Fritsch-Carlson: velocities alpha delta, beta delta with alpha, beta >= 0 and
  // alpha^2 + beta^2 <= 9 make the cubic monotone; the bound must then be |q(b) - q(a)|.
  for (unsigned seed : kSeeds) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> position(-3, 3), unit(0, 1), step(0.05, 3);
    for (int trial = 0; trial < 40; ++trial) {
      JointTrajectory trajectory;
      trajectory.joint_names = {"a"};
      const double t0 = unit(rng), h = step(rng), p0 = position(rng), p1 = position(rng);
      const double delta = (p1 - p0) / h, angle = 1.5707963 * unit(rng), radius = 2.99 * unit(rng);
      trajectory.times = {t0, t0 + h};
      trajectory.positions = {Eigen::VectorXd::Constant(1, p0), Eigen::VectorXd::Constant(1, p1)};
      trajectory.velocities = {Eigen::VectorXd::Constant(1, radius * std::cos(angle) * delta),
                               Eigen::VectorXd::Constant(1, radius * std::sin(angle) * delta)};
      const JointTrajectoryMotion motion(trajectory);
      const double a = trajectory.times[0], b = trajectory.times[1];
      const mpq_class increment = abs(mpq_class(p1) - mpq_class(p0));
      EXPECT_EQ(exact_variation_bound(motion, a, b)[0], increment);
      const double rounded = motion.variation_bound(a, b)[0];
      EXPECT_GE(mpq_class(rounded), increment);  // the smallest double >= |p1 - p0|
      EXPECT_LT(mpq_class(std::nextafter(rounded, 0.0)), increment);
      const double c = a + (b - a) * unit(rng), d = c + (b - c) * unit(rng);
      if (c < d) {
        EXPECT_EQ(exact_variation_bound(motion, c, d)[0],
                  abs(reference_q(trajectory, 0, 0, d) - reference_q(trajectory, 0, 0, c)));
      }
    }
  }
}

TEST(LemmaJointVariation, RoundedBoundIsNeverBelowTheExactBound) {
  // proofs/joint-variation.md#rounded-evaluation, with awkward scales: tiny and huge pieces,
  // large positions, zero velocities, intervals one ulp from a waypoint.
  double worst_relative_gap = 0.0;
  for (unsigned seed : kSeeds) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int trial = 0; trial < 60; ++trial) {
      JointTrajectory trajectory = random_trajectory(rng, 3, false);
      const double time_scale = std::pow(10.0, std::uniform_int_distribution<int>(-3, 3)(rng));
      const double value_scale = std::pow(10.0, std::uniform_int_distribution<int>(-3, 3)(rng));
      for (double& t : trajectory.times) t *= time_scale;
      for (auto& p : trajectory.positions) p *= value_scale;
      for (auto& v : trajectory.velocities) v *= value_scale / time_scale;
      const JointTrajectoryMotion motion(trajectory);
      const double t1 = trajectory.times[1];
      const std::vector<std::pair<double, double>> intervals = {
          random_interval(rng, trajectory), random_interval(rng, trajectory),
          {std::nextafter(t1, 0.0), std::nextafter(t1, 1e300)},
          {trajectory.times[0], std::nextafter(t1, 0.0)}};
      for (const auto& [a, b] : intervals) {
        const mpq_class exact = exact_variation_bound(motion, a, b)[0];
        const double rounded = motion.variation_bound(a, b)[0];
        ASSERT_GE(mpq_class(rounded), exact) << "seed " << seed << " trial " << trial;
        // The rounding excess comes from interval widths at interior points (Horner in the
        // power basis: about sum |c_i| ulp): measured against the scale of the joint values.
        worst_relative_gap =
            std::max(worst_relative_gap, mpq_class((rounded - exact) / value_scale).get_d());
      }
    }
  }
  EXPECT_LT(worst_relative_gap, 1e-10);  // measured 6.5e-12
  std::printf("largest (rounded - exact) / (scale of the joint values): %.3g\n", worst_relative_gap);
}

TEST(LemmaJointVariation, OvershootPieceBoundIsNearItsTrueVariation) {
  // The elbow of data/trajectories/overshoot.json on [1.5, 2.5] s goes 2 -> 2 + 2/9 -> 2:
  // total variation 4/9, increment 0, control polygon of the whole piece 1.
  const JointTrajectoryMotion motion(
      io::read_trajectory_file(std::string(GRPVSS_SOURCE_DIR) + "/data/trajectories/overshoot.json"));
  const mpq_class exact = exact_variation_bound(motion, 1.5, 2.5)[2];
  EXPECT_GE(exact, mpq_class(4, 9));
  EXPECT_LE(exact, mpq_class(4, 9) + mpq_class(1, 40000));
  EXPECT_GE(motion.variation_bound(1.5, 2.5)[2], exact.get_d());
  std::printf("overshoot piece: exact bound - 4/9 = %.3g\n", mpq_class(exact - mpq_class(4, 9)).get_d());
  // The first piece (1 -> 2, monotone) contributes exactly 1.
  EXPECT_EQ(exact_variation_bound(motion, 0.5, 1.5)[2], 1);
  EXPECT_EQ(exact_variation_bound(motion, 0.5, 2.5)[2], 1 + exact);
}

TEST(LemmaJointVariation, SampledEndsBoundCoversTheOffsetOfTheRoundedEnds) {
  // proofs/joint-variation.md#corollary-sampled-ends
  for (unsigned seed : kSeeds) {
    std::mt19937 rng(seed);
    for (int trial = 0; trial < 30; ++trial) {
      const JointTrajectory trajectory = random_trajectory(rng, 3, trial % 4 == 0);
      const JointTrajectoryMotion motion(trajectory);
      const auto [a, b] = random_interval(rng, trajectory);
      const Eigen::VectorXd qa = motion.q_at(a), qb = motion.q_at(b);
      const mpq_class offsets = abs(mpq_class(qa[0]) - reference_q(trajectory, motion.piece_at(a), 0, a)) +
                                abs(mpq_class(qb[0]) - reference_q(trajectory, motion.piece_at(b), 0, b));
      const mpq_class exact = exact_variation_bound_from_samples(motion, a, qa, b, qb)[0];
      EXPECT_EQ(exact, exact_variation_bound(motion, a, b)[0] + offsets);
      EXPECT_GE(mpq_class(motion.variation_bound_from_samples(a, b)[0]), exact);
    }
  }
  // At waypoint times the samples are the stored positions: no offset.
  const JointTrajectoryMotion motion(
      io::read_trajectory_file(std::string(GRPVSS_SOURCE_DIR) + "/data/trajectories/overshoot.json"));
  EXPECT_EQ(motion.variation_bound_from_samples(0.5, 1.5), motion.variation_bound(0.5, 1.5));
}

// ---------- Theorem 7 on a planar chain ----------

/// Planar chain of revolute joints about parallel z axes at the origin of each link: the
/// point `offset` of the last link, in the plane.
Eigen::Vector2d planar_point(const std::vector<double>& lengths, const Eigen::VectorXd& q,
                             const Eigen::Vector2d& offset) {
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  double angle = 0.0;
  for (std::size_t j = 0; j < lengths.size(); ++j) {
    angle += q[static_cast<Eigen::Index>(j)];
    if (j + 1 < lengths.size()) p += lengths[j] * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  }
  const Eigen::Rotation2Dd rotation(angle);
  return p + rotation * (Eigen::Vector2d(lengths.back(), 0.0) + offset);
}

TEST(LemmaJointVariation, PointPathLengthIsWithinTheVariationMotionBound) {
  // proofs/joint-variation.md#theorem-variation-motion-bound, with R_j = (sum of the link
  // lengths from joint j on) + |offset|, a valid axis distance for every configuration.
  const std::vector<double> lengths = {1.0, 0.7, 0.4};
  int increment_bound_exceeded = 0;
  for (unsigned seed : kSeeds) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> position(-2, 2), rate(-4, 4), side(-0.2, 0.2);
    for (int trial = 0; trial < 8; ++trial) {
      JointTrajectory trajectory;
      trajectory.joint_names = {"j1", "j2", "j3"};
      for (int k = 0; k < 3; ++k) {
        trajectory.times.push_back(0.8 * k);
        trajectory.positions.push_back(Eigen::Vector3d(position(rng), position(rng), position(rng)));
        trajectory.velocities.push_back(Eigen::Vector3d(rate(rng), rate(rng), rate(rng)));
      }
      const JointTrajectoryMotion motion(trajectory);
      const Eigen::Vector2d offset(side(rng), side(rng));
      const double a = 0.3, b = 1.5;
      const Eigen::VectorXd variation = motion.variation_bound(a, b);
      const Eigen::VectorXd increment = (motion.q_at(b) - motion.q_at(a)).cwiseAbs();
      double bound = 0.0, increment_bound = 0.0;
      for (int j = 0; j < 3; ++j) {
        double radius = offset.norm();
        for (int m = j; m < 3; ++m) radius += lengths[m];
        bound += variation[j] * radius;
        increment_bound += increment[j] * radius;
      }
      double chords = 0.0;
      Eigen::Vector2d previous = planar_point(lengths, motion.q_at(a), offset);
      constexpr int kSamples = 20000;
      for (int i = 1; i <= kSamples; ++i) {
        const Eigen::Vector2d p = planar_point(lengths, motion.q_at(a + (b - a) * i / kSamples), offset);
        chords += (p - previous).norm();
        previous = p;
      }
      ASSERT_LE(chords, bound * (1 + 1e-12)) << "seed " << seed << " trial " << trial;
      if (chords > increment_bound) ++increment_bound_exceeded;
    }
  }
  // Joints that go out and back make the monotone formula sum |dq_j| R_j unsound here.
  EXPECT_GT(increment_bound_exceeded, 0);
  std::printf("cases where sum |dq_j| R_j is below the sampled path length: %d of 40\n",
              increment_bound_exceeded);
}

}  // namespace
}  // namespace grpvss::motion

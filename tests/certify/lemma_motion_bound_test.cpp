// Checks proofs/motion-bound.md: the path of every point of a link hull is no longer than
// M_h = sum_rev |dq_j| R_jh + sum_pri |dq_j| under monotone joint motion, and R_jh bounds the
// distance to axis j for every configuration within the limits. Independent reference FK.

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "certify/lemma_reference.hpp"

namespace {

using lemma_ref::DhJoint;
using lemma_ref::Vec3;

struct Link {
  std::vector<std::vector<Vec3>> hulls;  // vertices in link frame
};

struct Robot {
  std::vector<DhJoint> chain;  // joints 1..N at 0..N-1
  std::vector<Link> links;     // links 1..N at 0..N-1
};

Robot random_robot(std::mt19937& rng) {
  std::uniform_int_distribution<int> joint_count(3, 6);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  Robot robot;
  const int n = joint_count(rng);
  for (int j = 0; j < n; ++j) {
    DhJoint joint;
    joint.prismatic = u01(rng) < 0.3;
    joint.theta0 = M_PI * u(rng);
    joint.d0 = 2.0 * u(rng);
    joint.a = 2.0 * u(rng);
    joint.alpha = M_PI * u(rng);
    // Many real arms twist by multiples of 90 degrees (a SCARA by 0 and 180): there the
    // radial/axial recursion is tightest, so those cases are common here.
    const double snap = u01(rng);
    if (snap < 0.2) joint.alpha = 0.0;
    else if (snap < 0.3) joint.alpha = M_PI;
    else if (snap < 0.45) joint.alpha = (u(rng) < 0.0 ? -0.5 : 0.5) * M_PI;
    if (joint.prismatic) {
      joint.qmin = -u01(rng);
      joint.qmax = 1.5 * u01(rng);
    } else {
      joint.qmin = -3.0 * u01(rng);
      joint.qmax = 3.0 * u01(rng);
    }
    robot.chain.push_back(joint);
    Link link;
    const int hull_count = 1 + static_cast<int>(u01(rng) * 2.0);
    for (int h = 0; h < hull_count; ++h) {
      // Some hulls stick far out of the skeleton (scale 8), like a tool.
      const double s = u01(rng) < 0.4 ? 8.0 : 1.0;
      const int vertex_count = 4 + static_cast<int>(u01(rng) * 5.0);
      std::vector<Vec3> hull;
      for (int v = 0; v < vertex_count; ++v) hull.push_back({s * u(rng), s * u(rng), s * u(rng)});
      link.hulls.push_back(hull);
    }
    robot.links.push_back(link);
  }
  return robot;
}

double dmax(const DhJoint& j) {
  return j.prismatic ? std::max(std::abs(j.d0 + j.qmin), std::abs(j.d0 + j.qmax)) : std::abs(j.d0);
}

// R_jh of proofs/motion-bound.md#lemma-axis-radius (radial/axial recursion, clamped by the
// absolute-sum norm bound); i and j are 1-based. Plain doubles: the comparisons below allow
// 1e-12 relative.
double axis_radius(const Robot& robot, int i, int j, const std::vector<Vec3>& hull) {
  double rho = 0.0, zeta = 0.0, norm = 0.0;
  for (const Vec3& v : hull) {
    rho = std::max(rho, std::hypot(v[0], v[1]));
    zeta = std::max(zeta, std::abs(v[2]));
    norm = std::max(norm, std::abs(v[0]) + std::abs(v[1]) + std::abs(v[2]));
  }
  for (int m = i; m > j; --m) {
    const DhJoint& joint = robot.chain[m - 1];
    const double s = std::abs(std::sin(joint.alpha)), c = std::abs(std::cos(joint.alpha));
    const double a = std::abs(joint.a), reach = dmax(joint);
    const double next_norm = a + reach + norm;
    const double next_rho = std::min(next_norm, a + rho + s * zeta);
    const double next_zeta = std::min(next_norm, reach + s * rho + c * zeta);
    norm = next_norm, rho = next_rho, zeta = next_zeta;
  }
  const DhJoint& joint_j = robot.chain[j - 1];
  return std::abs(joint_j.a) + std::min(norm, rho + std::abs(std::sin(joint_j.alpha)) * zeta);
}

double motion_bound(const Robot& robot, int i, const std::vector<Vec3>& hull, const std::vector<double>& dq) {
  double m = 0.0;
  for (int j = 1; j <= i; ++j) {
    const double step = std::abs(dq[j - 1]);
    m += robot.chain[j - 1].prismatic ? step : step * axis_radius(robot, i, j, hull);
  }
  return m;
}

// Normalised trapezoid: s(0)=0, s(1)=1, non-decreasing; accel/decel fractions fa, fd.
double trapezoid(double tau, double fa, double fd) {
  tau = std::clamp(tau, 0.0, 1.0);
  const double v = 1.0 / (1.0 - 0.5 * fa - 0.5 * fd);
  if (tau < fa) return v * tau * tau / (2.0 * fa);
  if (tau <= 1.0 - fd) return v * (tau - 0.5 * fa);
  const double r = 1.0 - tau;
  return 1.0 - v * r * r / (2.0 * fd);
}

struct Profile {
  double start = 0.0, end = 1.0, fa = 0.2, fd = 0.2;
  double at(double t) const { return trapezoid((t - start) / (end - start), fa, fd); }
};

// Link-frame points whose paths are measured: the vertices and random interior points.
std::vector<Vec3> probe_points(const std::vector<Vec3>& hull, std::mt19937& rng) {
  std::vector<Vec3> points = hull;
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int k = 0; k < 5; ++k) {
    std::vector<double> w(hull.size());
    double sum = 0.0;
    for (double& x : w) sum += (x = u01(rng));
    Vec3 p{0.0, 0.0, 0.0};
    for (std::size_t v = 0; v < hull.size(); ++v) p = lemma_ref::add(p, lemma_ref::scale(hull[v], w[v] / sum));
    points.push_back(p);
  }
  return points;
}

TEST(LemmaMotionBound, ChordSumOfVertexAndInteriorPathsIsBelowBound) {
  std::mt19937 rng(20261121);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  constexpr int kSamples = 2400;
  int checked_paths = 0;
  double max_ratio_formula = 0.0;  // chord / M_h
  double max_ratio_lemma1 = 0.0;   // chord / (Lemma 1 with the sampled axis distances)
  for (int trial = 0; trial < 36; ++trial) {
    const Robot robot = random_robot(rng);
    const std::size_t n = robot.chain.size();
    std::vector<double> q0(n), q1(n), dq(n);
    const std::size_t only_joint = static_cast<std::size_t>(u01(rng) * n);
    for (std::size_t j = 0; j < n; ++j) {
      const DhJoint& jt = robot.chain[j];
      q0[j] = jt.qmin + (jt.qmax - jt.qmin) * u01(rng);
      q1[j] = jt.qmin + (jt.qmax - jt.qmin) * u01(rng);
      if (trial % 3 == 2 && j != only_joint) q1[j] = q0[j];  // one joint moves: Lemma 1 is tight
      dq[j] = q1[j] - q0[j];
    }
    // trial % 3 == 1: every joint its own monotone trapezoid; otherwise joint-linear.
    std::vector<Profile> profiles(n);
    if (trial % 3 == 1) {
      for (Profile& p : profiles) {
        p.start = 0.3 * u01(rng);
        p.end = 0.7 + 0.3 * u01(rng);
        p.fa = 0.05 + 0.45 * u01(rng);
        p.fd = 0.05 + 0.45 * u01(rng);
      }
    }
    // Per link, hull, probe point: chord sum, previous position, max distance to each axis.
    struct Probe {
      Vec3 p_L;
      Vec3 previous{};
      double chord = 0.0;
      std::vector<double> max_axis_distance;
    };
    std::vector<std::vector<std::vector<Probe>>> probes(n);
    for (std::size_t i = 0; i < n; ++i) {
      for (const auto& hull : robot.links[i].hulls) {
        std::vector<Probe> ps;
        for (const Vec3& v : probe_points(hull, rng)) ps.push_back(Probe{v, {}, 0.0, std::vector<double>(i + 1, 0.0)});
        probes[i].push_back(ps);
      }
    }
    for (int s = 0; s <= kSamples; ++s) {
      const double t = static_cast<double>(s) / kSamples;
      std::vector<double> q(n);
      for (std::size_t j = 0; j < n; ++j) {
        const double frac = (trial % 3 == 1) ? profiles[j].at(t) : t;
        q[j] = (s == kSamples) ? q1[j] : q0[j] + frac * dq[j];
      }
      const auto frames = lemma_ref::forward_frames(robot.chain, q);
      for (std::size_t i = 0; i < n; ++i) {
        for (auto& ps : probes[i]) {
          for (Probe& probe : ps) {
            const Vec3 p = frames[i + 1].apply(probe.p_L);
            if (s > 0) probe.chord += lemma_ref::norm(lemma_ref::sub(p, probe.previous));
            probe.previous = p;
            for (std::size_t j = 0; j <= i; ++j) {
              const double d = lemma_ref::distance_to_axis(p, frames[j].origin(), frames[j].z_axis());
              probe.max_axis_distance[j] = std::max(probe.max_axis_distance[j], d);
            }
          }
        }
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t h = 0; h < probes[i].size(); ++h) {
        const double bound = motion_bound(robot, static_cast<int>(i + 1), robot.links[i].hulls[h], dq);
        for (const Probe& probe : probes[i][h]) {
          // Lemma 1 with R_j = the (sampled) largest axis distance along this motion.
          double lemma1 = 0.0;
          for (std::size_t j = 0; j <= i; ++j)
            lemma1 += std::abs(dq[j]) * (robot.chain[j].prismatic ? 1.0 : probe.max_axis_distance[j]);
          // The chord sum is a lower bound of the path length; slack only for FK rounding and
          // for the sampled maximum of the axis distance.
          EXPECT_LE(probe.chord, lemma1 * (1.0 + 1e-6) + 1e-9) << "trial " << trial << " link " << i + 1;
          EXPECT_LE(lemma1, bound + 1e-9 * (1.0 + bound));
          EXPECT_LE(probe.chord, bound + 1e-9 * (1.0 + bound)) << "trial " << trial << " link " << i + 1;
          if (bound > 0.0) max_ratio_formula = std::max(max_ratio_formula, probe.chord / bound);
          if (lemma1 > 0.0) max_ratio_lemma1 = std::max(max_ratio_lemma1, probe.chord / lemma1);
          ++checked_paths;
        }
      }
    }
  }
  EXPECT_GT(checked_paths, 1000);
  // Neither bound is vacuous here: with one moving joint Lemma 1 is attained up to sampling.
  EXPECT_GT(max_ratio_lemma1, 0.999);
  EXPECT_GT(max_ratio_formula, 0.25);
}

TEST(LemmaMotionBound, AxisRadiusBoundsSampledAxisDistance) {
  std::mt19937 rng(7545);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Robot robot = random_robot(rng);
    const std::size_t n = robot.chain.size();
    std::vector<std::vector<std::vector<Vec3>>> probes(n);
    for (std::size_t i = 0; i < n; ++i)
      for (const auto& hull : robot.links[i].hulls) probes[i].push_back(probe_points(hull, rng));
    for (int sample = 0; sample < 200; ++sample) {
      std::vector<double> q(n);
      for (std::size_t j = 0; j < n; ++j) {
        const DhJoint& jt = robot.chain[j];
        // Include the limits themselves, where the prismatic d_m is extreme.
        const double r = u01(rng);
        q[j] = r < 0.1 ? jt.qmin : (r > 0.9 ? jt.qmax : jt.qmin + (jt.qmax - jt.qmin) * u01(rng));
      }
      const auto frames = lemma_ref::forward_frames(robot.chain, q);
      for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t h = 0; h < probes[i].size(); ++h) {
          for (int j = 1; j <= static_cast<int>(i + 1); ++j) {
            const double radius = axis_radius(robot, static_cast<int>(i + 1), j, robot.links[i].hulls[h]);
            for (const Vec3& v : probes[i][h]) {
              const Vec3 p = frames[i + 1].apply(v);
              const double dist = lemma_ref::distance_to_axis(p, frames[j - 1].origin(), frames[j - 1].z_axis());
              EXPECT_LE(dist, radius + 1e-12 * (1.0 + radius));
              ++checked;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 100000);
}

TEST(LemmaMotionBound, BoundIsAttainedByPointOnAxisCircle) {
  // One revolute joint, a = d = 0, hull point (R,0,0): its path is an arc of length R|dq| = M.
  Robot robot;
  DhJoint joint;
  joint.qmin = -2.0;
  joint.qmax = 2.0;
  robot.chain.push_back(joint);
  const double radius = 3.0;
  robot.links.push_back(Link{{{{radius, 0.0, 0.0}}}});
  const std::vector<double> dq{1.5};
  const double bound = motion_bound(robot, 1, robot.links[0].hulls[0], dq);
  EXPECT_DOUBLE_EQ(bound, 4.5);
  double length = 0.0;
  Vec3 previous = robot.links[0].hulls[0][0];
  for (int s = 1; s <= 4000; ++s) {
    const auto frames = lemma_ref::forward_frames(robot.chain, {dq[0] * s / 4000.0});
    const Vec3 p = frames[1].apply(robot.links[0].hulls[0][0]);
    length += lemma_ref::norm(lemma_ref::sub(p, previous));
    previous = p;
  }
  EXPECT_LE(length, bound);
  EXPECT_GT(length, bound * (1.0 - 1e-6));
}

TEST(LemmaMotionBound, NonMonotoneMotionCanExceedIncrementBound) {
  // The joint goes out and back (dq = 0): the increment bound is 0 but the point moves.
  Robot robot;
  DhJoint joint;
  joint.qmin = -2.0;
  joint.qmax = 2.0;
  robot.chain.push_back(joint);
  robot.links.push_back(Link{{{{1.0, 0.0, 0.0}}}});
  const double bound = motion_bound(robot, 1, robot.links[0].hulls[0], {0.0});
  double length = 0.0;
  Vec3 previous = robot.links[0].hulls[0][0];
  for (int s = 1; s <= 2000; ++s) {
    const auto frames = lemma_ref::forward_frames(robot.chain, {0.5 * std::sin(M_PI * s / 2000.0)});
    const Vec3 p = frames[1].apply(robot.links[0].hulls[0][0]);
    length += lemma_ref::norm(lemma_ref::sub(p, previous));
    previous = p;
  }
  EXPECT_EQ(bound, 0.0);
  EXPECT_NEAR(length, 1.0, 1e-6);  // out 0.5 rad and back on a unit circle
}

}  // namespace

namespace {

// P_h of proofs/motion-bound.md#lemma-joint-linear-chord, by the reference formula (plain
// doubles, i 1-based).
double curvature_bound(const Robot& robot, int i, const std::vector<Vec3>& hull,
                       const std::vector<double>& dq, double pair_factor = 2.0) {
  double bound = 0.0, revolute_before = 0.0;
  for (int m = 1; m <= i; ++m) {
    const bool revolute = !robot.chain[m - 1].prismatic;
    const double weight = revolute ? axis_radius(robot, i, m, hull) : 1.0;
    const double step = std::abs(dq[m - 1]);
    bound += weight * step * (pair_factor * revolute_before + (revolute ? step : 0.0));
    if (revolute) revolute_before += step;
  }
  return bound;
}

}  // namespace

// Lemma 4 on 40 random chains (the generator above: hulls off the skeleton, twists snapped to
// 0/90/180 degrees), joint-linear moves of up to 0.5 rad / 0.5 units per joint: for every
// vertex and 5 interior points per hull, (a) the sampled second derivative |p''(s)| never
// exceeds P_h, (b) the path's chord sum never exceeds max over the hull's vertices of the
// end-to-end chord plus P_h / 3, and the bound is below M_h on most hulls. Dropping the factor
// 2 of the mixed terms makes (a) fail (checked below on the same motions).
TEST(LemmaMotionBound, JointLinearPathIsWithinTheVertexChordPlusAThirdOfTheCurvatureBound) {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  constexpr int kSamples = 1200;
  int checked_paths = 0, tighter_than_sum = 0, hulls_checked = 0;
  bool single_factor_fails = false;
  double largest_curvature_share = 0.0;  // sampled max |p''| / P_h
  for (int trial = 0; trial < 40; ++trial) {
    const Robot robot = random_robot(rng);
    const std::size_t n = robot.chain.size();
    std::vector<double> q0(n), q1(n), dq(n);
    for (std::size_t j = 0; j < n; ++j) {
      const DhJoint& jt = robot.chain[j];
      const double reach = 0.5 * u01(rng);
      q0[j] = jt.qmin + (jt.qmax - jt.qmin) * u01(rng);
      q1[j] = std::clamp(q0[j] + reach * (u01(rng) < 0.5 ? -1.0 : 1.0), jt.qmin, jt.qmax);
      dq[j] = q1[j] - q0[j];
    }
    const double h = 1.0 / kSamples;
    std::vector<std::vector<double>> q_at(kSamples + 1, std::vector<double>(n));
    for (int s = 0; s <= kSamples; ++s)
      for (std::size_t j = 0; j < n; ++j) q_at[s][j] = s == kSamples ? q1[j] : q0[j] + dq[j] * s * h;
    std::vector<std::vector<lemma_ref::Frame>> frames;
    for (const auto& q : q_at) frames.push_back(lemma_ref::forward_frames(robot.chain, q));
    for (std::size_t i = 0; i < n; ++i) {
      for (const auto& hull : robot.links[i].hulls) {
        const int link = static_cast<int>(i + 1);
        const double curvature = curvature_bound(robot, link, hull, dq);
        const double single = curvature_bound(robot, link, hull, dq, 1.0);
        double vertex_chord = 0.0;
        for (const Vec3& v : hull) {
          vertex_chord = std::max(vertex_chord, lemma_ref::norm(lemma_ref::sub(
                                                    frames[kSamples][i + 1].apply(v), frames[0][i + 1].apply(v))));
        }
        const double bound = vertex_chord + curvature / 3.0;
        for (const Vec3& v : probe_points(hull, rng)) {
          double length = 0.0, largest_second = 0.0;
          for (int s = 1; s <= kSamples; ++s) {
            const Vec3 p = frames[s][i + 1].apply(v), previous = frames[s - 1][i + 1].apply(v);
            length += lemma_ref::norm(lemma_ref::sub(p, previous));
            if (s < kSamples) {
              const Vec3 next = frames[s + 1][i + 1].apply(v);
              const Vec3 second = lemma_ref::scale(
                  lemma_ref::add(lemma_ref::sub(next, p), lemma_ref::sub(previous, p)), 1.0 / (h * h));
              largest_second = std::max(largest_second, lemma_ref::norm(second));
            }
          }
          // Central differences are within O(h^2 |p''''|) of p'' (a relative 1e-4) plus rounding
          // noise of ~1e-14 / h^2 (an absolute 1e-6).
          EXPECT_LE(largest_second, curvature * (1.0 + 1e-4) + 1e-6) << "trial " << trial << " link " << link;
          if (largest_second > single * (1.0 + 1e-3) + 1e-9) single_factor_fails = true;
          if (curvature > 0.0) largest_curvature_share = std::max(largest_curvature_share, largest_second / curvature);
          EXPECT_LE(length, bound * (1.0 + 1e-9) + 1e-9) << "trial " << trial << " link " << link;
          ++checked_paths;
        }
        if (bound < motion_bound(robot, link, hull, dq)) ++tighter_than_sum;
        ++hulls_checked;
      }
    }
  }
  EXPECT_GT(checked_paths, 1000);
  EXPECT_TRUE(single_factor_fails);           // the mixed terms need their factor 2
  EXPECT_GT(largest_curvature_share, 0.5);    // P_h is not vacuous
  EXPECT_GT(tighter_than_sum, hulls_checked / 2);  // and the chord bound is worth having
}

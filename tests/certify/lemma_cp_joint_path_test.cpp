// Checks proofs/cp-joint-path.md: joint-linear motion between in-limit samples is monotone and
// within the limits (so the motion bound applies), and the stated detection rules separate a
// regular CP step from an IK branch flip and flag the elbow singularity. Reference: a planar 2R
// arm with the IBM 7545's first two link lengths, closed-form IK written here.

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace {

constexpr double kL1 = 15.8, kL2 = 9.8;
using V2 = std::array<double, 2>;

V2 fk(const V2& q) {
  return {kL1 * std::cos(q[0]) + kL2 * std::cos(q[0] + q[1]), kL1 * std::sin(q[0]) + kL2 * std::sin(q[0] + q[1])};
}

// Closed-form IK; branch +1 / -1 is the sign of sin(theta2) (the elbow).
V2 ik(const V2& p, int branch) {
  const double c2 = (p[0] * p[0] + p[1] * p[1] - kL1 * kL1 - kL2 * kL2) / (2 * kL1 * kL2);
  const double t2 = branch * std::acos(std::clamp(c2, -1.0, 1.0));
  const double t1 = std::atan2(p[1], p[0]) - std::atan2(kL2 * std::sin(t2), kL1 + kL2 * std::cos(t2));
  return {t1, t2};
}

int branch_of(const V2& q) { return std::sin(q[1]) >= 0 ? 1 : -1; }

std::array<V2, 2> jacobian_columns(const V2& q) {
  const double s1 = std::sin(q[0]), c1 = std::cos(q[0]), s12 = std::sin(q[0] + q[1]), c12 = std::cos(q[0] + q[1]);
  return {V2{-kL1 * s1 - kL2 * s12, kL1 * c1 + kL2 * c12}, V2{-kL2 * s12, kL2 * c12}};
}

// proofs/cp-joint-path.md#joint-jump: |J(q_k) dq - dx_cmd| > eta |dx_cmd| + tau.
bool joint_jump(const V2& qk, const V2& qk1, const V2& dx_cmd, double eta = 0.5, double tau = 1e-9) {
  const auto j = jacobian_columns(qk);
  const V2 dq{qk1[0] - qk[0], qk1[1] - qk[1]};
  const V2 r{j[0][0] * dq[0] + j[1][0] * dq[1] - dx_cmd[0], j[0][1] * dq[0] + j[1][1] * dq[1] - dx_cmd[1]};
  return std::hypot(r[0], r[1]) > eta * std::hypot(dx_cmd[0], dx_cmd[1]) + tau;
}

double smallest_singular_value(const V2& q) {
  const auto j = jacobian_columns(q);
  const double a = j[0][0], b = j[1][0], c = j[0][1], d = j[1][1];  // [[a b],[c d]]
  const double s1 = a * a + b * b + c * c + d * d, det = a * d - b * c;
  return std::sqrt(std::max(0.0, (s1 - std::sqrt(std::max(0.0, s1 * s1 - 4 * det * det))) / 2));
}

TEST(LemmaCpJointPath, JointLinearPathIsMonotoneAndWithinLimits) {
  std::mt19937 rng(909);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 4;
    std::vector<double> lo(n), hi(n), q0(n), q1(n);
    for (int j = 0; j < n; ++j) {
      lo[j] = -3 * u01(rng);
      hi[j] = 3 * u01(rng);
      q0[j] = lo[j] + (hi[j] - lo[j]) * u01(rng);
      q1[j] = lo[j] + (hi[j] - lo[j]) * u01(rng);
    }
    // A non-decreasing s(t) with s(0)=0, s(1)=1 (smoothstep with random warp).
    const double warp = 0.2 + 3 * u01(rng);
    std::vector<double> previous = q0;
    for (int k = 0; k <= 500; ++k) {
      const double t = std::pow(k / 500.0, warp), s = t * t * (3 - 2 * t);
      for (int j = 0; j < n; ++j) {
        const double q = q0[j] + s * (q1[j] - q0[j]);
        EXPECT_GE(q, lo[j]);
        EXPECT_LE(q, hi[j]);
        // Monotone in the direction of the increment.
        EXPECT_GE((q - previous[j]) * (q1[j] - q0[j]), 0.0);
        previous[j] = q;
      }
    }
  }
}

TEST(LemmaCpJointPath, JumpRuleFlagsBranchFlipButNotRegularSteps) {
  // CP line from (20, -5) to (20, 10), sampled every 0.25 in., elbow branch +1.
  const V2 start{20, -5}, end{20, 10};
  const int samples = 60;
  for (int k = 0; k < samples; ++k) {
    const V2 p0{start[0] + (end[0] - start[0]) * k / samples, start[1] + (end[1] - start[1]) * k / samples};
    const V2 p1{start[0] + (end[0] - start[0]) * (k + 1) / samples,
                start[1] + (end[1] - start[1]) * (k + 1) / samples};
    const V2 dx{p1[0] - p0[0], p1[1] - p0[1]};
    const V2 qk = ik(p0, 1), qk1 = ik(p1, 1), flipped = ik(p1, -1);
    // IK hits the samples.
    EXPECT_NEAR(fk(qk1)[0], p1[0], 1e-9);
    EXPECT_NEAR(fk(flipped)[1], p1[1], 1e-9);
    EXPECT_EQ(branch_of(qk), branch_of(qk1));
    EXPECT_NE(branch_of(qk), branch_of(flipped));  // proofs/cp-joint-path.md#branch-change
    EXPECT_FALSE(joint_jump(qk, qk1, dx)) << "regular step " << k;
    EXPECT_TRUE(joint_jump(qk, flipped, dx)) << "flip at step " << k;
    // The joint-linear midpoint leaves the line (not certified), slightly for a regular step and
    // grossly for a flip.
    const V2 line_mid{(p0[0] + p1[0]) / 2, (p0[1] + p1[1]) / 2};
    const V2 joint_mid = fk({(qk[0] + qk1[0]) / 2, (qk[1] + qk1[1]) / 2});
    const V2 flip_mid = fk({(qk[0] + flipped[0]) / 2, (qk[1] + flipped[1]) / 2});
    EXPECT_LT(std::hypot(joint_mid[0] - line_mid[0], joint_mid[1] - line_mid[1]), 0.01);
    EXPECT_GT(std::hypot(flip_mid[0] - line_mid[0], flip_mid[1] - line_mid[1]), 1.0);
  }
}

TEST(LemmaCpJointPath, SingularityProximityFlagsTheStretchedElbow) {
  const double threshold = 1e-3 * (kL1 + kL2);  // proofs/cp-joint-path.md#singularity
  EXPECT_LT(smallest_singular_value({0.3, 1e-5}), threshold);
  EXPECT_LT(smallest_singular_value({-1.0, M_PI - 1e-5}), threshold);
  EXPECT_GT(smallest_singular_value({0.3, 1.0}), threshold);
  // sigma_min * sigma_max = |det J| = l1 l2 |sin theta2|: vanishes exactly at the elbow singularity.
  for (double t2 : {0.5, 1e-2, 1e-4}) {
    const auto j = jacobian_columns({0.2, t2});
    const double det = j[0][0] * j[1][1] - j[1][0] * j[0][1];
    EXPECT_NEAR(det, kL1 * kL2 * std::sin(t2), 1e-9);
  }
}

}  // namespace

#include "grpvss/kinematics/opw_kinematics.hpp"

#include <algorithm>
#include <cmath>

#include "elementary_rotations.hpp"

namespace grpvss::kinematics {
namespace {

using detail::kPi;
using detail::rot_y;
using detail::rot_z;
using detail::wrap_angle;

// Below this, hypot(R_ce(0,2), R_ce(1,2)) = |sin theta_5| counts as zero and theta_4 is taken
// from the caller: theta_6 is then solved from the rest, so the pose error stays O(1e-12).
constexpr double kWristSingular = 1e-12;
// Relative slack on cosines computed by the law of cosines before a branch is unreachable;
// clamping by this much moves the reached point by about 1e-10 of the arm's length.
constexpr double kCosineSlack = 1e-10;

// The two elbow solutions of the planar arm: lower arm c2 from axis 2, forearm of length k at
// angle psi3 = atan2(a2, c3) from the lower arm's continuation (angles measured from z toward
// x, as theta_2). (x, z): the wrist centre relative to axis 2 in the axis-1 frame.
struct ArmAngles {
  double theta2[2];
  double theta3[2];
  bool valid = false;
};

ArmAngles solve_planar_arm(const OpwParameters& p, double x, double z) {
  ArmAngles arm;
  const double k = std::hypot(p.a2, p.c3);
  const double psi3 = std::atan2(p.a2, p.c3);
  const double cos_beta = (x * x + z * z - p.c2 * p.c2 - k * k) / (2 * p.c2 * k);
  if (!(std::abs(cos_beta) <= 1 + kCosineSlack)) return arm;
  const double c = std::clamp(cos_beta, -1.0, 1.0);
  const double s = std::sqrt(std::max(0.0, 1 - c * c));
  for (int e = 0; e < 2; ++e) {
    // beta = theta_3 + psi3 is the forearm's angle from the lower arm; e = 0 puts the wrist
    // centre in front of the lower arm (sin beta >= 0).
    const double sin_beta = e == 0 ? s : -s;
    const double beta = std::atan2(sin_beta, c);
    arm.theta3[e] = wrap_angle(beta - psi3);
    arm.theta2[e] = wrap_angle(std::atan2(x, z) - std::atan2(k * sin_beta, p.c2 + k * c));
  }
  arm.valid = true;
  return arm;
}

// theta_4..6 from R_ce = Rz(t4) Ry(t5) Rz(t6) (ZYZ), non-flipped (theta_5 >= 0) then flipped.
// theta_6 is solved from what theta_4 and theta_5 leave, so the product reproduces R_ce even
// when theta_4 is only approximately determined (near theta_5 = 0).
void solve_wrist(const Eigen::Matrix3d& R_ce, double theta4_free, ModelAngles& plain,
                 ModelAngles& flipped) {
  const double s5 = std::hypot(R_ce(0, 2), R_ce(1, 2));
  const double t4 = s5 > kWristSingular ? std::atan2(R_ce(1, 2), R_ce(0, 2)) : theta4_free;
  const double t5 = std::atan2(s5, R_ce(2, 2));
  const Eigen::Matrix3d R_rest = rot_y(-t5) * rot_z(-t4) * R_ce;
  const double t6 = std::atan2(R_rest(1, 0), R_rest(0, 0));
  plain[3] = wrap_angle(t4);
  plain[4] = t5;
  plain[5] = wrap_angle(t6);
  flipped[3] = wrap_angle(t4 + kPi);
  flipped[4] = -t5;
  flipped[5] = wrap_angle(t6 + kPi);
}

}  // namespace

Eigen::Isometry3d opw_forward(const OpwParameters& p, const ModelAngles& t) {
  const double t23 = t[1] + t[2];
  // Wrist centre in the axis-1 frame, then turned by theta_1.
  const Eigen::Vector3d c_1(p.a1 + p.c2 * std::sin(t[1]) + p.a2 * std::cos(t23) + p.c3 * std::sin(t23),
                            p.b,
                            p.c1 + p.c2 * std::cos(t[1]) - p.a2 * std::sin(t23) + p.c3 * std::cos(t23));
  const Eigen::Matrix3d R_0c = rot_z(t[0]) * rot_y(t23);
  const Eigen::Matrix3d R_BF = R_0c * rot_z(t[3]) * rot_y(t[4]) * rot_z(t[5]);
  Eigen::Isometry3d X_BF = Eigen::Isometry3d::Identity();
  X_BF.linear() = R_BF;
  X_BF.translation() = rot_z(t[0]) * c_1 + p.c4 * R_BF.col(2);
  return X_BF;
}

OpwArmSides opw_arm_sides(const OpwParameters& p, const ModelAngles& t) {
  const double t23 = t[1] + t[2];
  OpwArmSides sides;
  sides.wrist_ahead_of_axis1 =
      p.a1 + p.c2 * std::sin(t[1]) + p.a2 * std::cos(t23) + p.c3 * std::sin(t23);
  sides.wrist_ahead_of_lower_arm = p.a2 * std::cos(t[2]) + p.c3 * std::sin(t[2]);
  return sides;
}

std::array<ModelBranch, 8> opw_inverse(const OpwParameters& p, const Eigen::Isometry3d& X_BF,
                                       const OpwSingularChoice& choice) {
  std::array<ModelBranch, 8> branches{};
  const Eigen::Matrix3d& R = X_BF.linear();
  const Eigen::Vector3d c = X_BF.translation() - p.c4 * R.col(2);
  const double radial_squared = c.x() * c.x() + c.y() * c.y() - p.b * p.b;
  const double scale = std::max({std::abs(p.a1), std::abs(p.b), p.c2, std::hypot(p.a2, p.c3)});
  if (radial_squared < -kCosineSlack * scale * scale) return branches;
  const double radial = std::sqrt(std::max(0.0, radial_squared));
  // On axis 1 (only possible with b = 0) the bearing is free: take the caller's theta_1.
  const bool on_axis1 = std::hypot(c.x(), c.y()) <= 1e-12 * scale;
  const double bearing = on_axis1 ? choice.theta1 : std::atan2(c.y(), c.x());
  for (int s = 0; s < 2; ++s) {
    // s = 0: wrist centre at x = +radial in the axis-1 frame (in front), s = 1: behind.
    const double x1 = s == 0 ? radial : -radial;
    const double theta1 = wrap_angle(on_axis1 ? bearing + s * kPi : bearing - std::atan2(p.b, x1));
    const ArmAngles arm = solve_planar_arm(p, x1 - p.a1, c.z() - p.c1);
    if (!arm.valid) continue;
    for (int e = 0; e < 2; ++e) {
      const Eigen::Matrix3d R_0c = rot_z(theta1) * rot_y(arm.theta2[e] + arm.theta3[e]);
      ModelBranch& plain = branches[static_cast<std::size_t>(4 * s + 2 * e)];
      ModelBranch& flipped = branches[static_cast<std::size_t>(4 * s + 2 * e + 1)];
      plain.theta[0] = flipped.theta[0] = theta1;
      plain.theta[1] = flipped.theta[1] = arm.theta2[e];
      plain.theta[2] = flipped.theta[2] = arm.theta3[e];
      solve_wrist(R_0c.transpose() * R, choice.theta4, plain.theta, flipped.theta);
      plain.valid = flipped.valid = true;
    }
  }
  return branches;
}

}  // namespace grpvss::kinematics

#include "grpvss/kinematics/ur_kinematics.hpp"

#include <algorithm>
#include <cmath>

#include "elementary_rotations.hpp"

namespace grpvss::kinematics {
namespace {

using detail::kPi;
using detail::wrap_angle;

constexpr double kUrWristSingular = 1e-12;  // |sin theta_5| below which theta_6 is free
constexpr double kUrCosineSlack = 1e-10;    // as in opw_kinematics.cpp

// UR's DH link transform A = Rot_z(theta) Trans_z(d) Trans_x(a) Rot_x(alpha), alpha in
// {0, pi/2, -pi/2} written exactly (no cos(pi/2) residue).
Eigen::Isometry3d dh_link(double theta, double d, double a, int alpha_quarter_turns) {
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  const double ca = alpha_quarter_turns == 0 ? 1.0 : 0.0;
  const double sa = static_cast<double>(alpha_quarter_turns);  // +1, -1 or 0
  Eigen::Isometry3d A = Eigen::Isometry3d::Identity();
  A.linear() << c, -s * ca, s * sa,
                s, c * ca, -c * sa,
                0, sa, ca;
  A.translation() << a * c, a * s, d;
  return A;
}

std::array<Eigen::Isometry3d, 6> dh_links(const UrParameters& p, const ModelAngles& t) {
  return {dh_link(t[0], p.d1, 0, 1), dh_link(t[1], 0, p.a2, 0), dh_link(t[2], 0, p.a3, 0),
          dh_link(t[3], p.d4, 0, 1), dh_link(t[4], p.d5, 0, -1), dh_link(t[5], p.d6, 0, 0)};
}

// theta_2, theta_3, theta_4 of the planar 3R arm from X_14 (frame 4 in frame 1); branch e = 0
// has sin(theta_3) >= 0. False when the elbow cannot reach.
bool solve_ur_planar_arm(const UrParameters& p, const Eigen::Isometry3d& X_14, int e,
                      ModelAngles& theta) {
  const double x = X_14(0, 3);
  const double y = X_14(1, 3);
  const double cos3 = (x * x + y * y - p.a2 * p.a2 - p.a3 * p.a3) / (2 * p.a2 * p.a3);
  if (!(std::abs(cos3) <= 1 + kUrCosineSlack)) return false;
  const double c3 = std::clamp(cos3, -1.0, 1.0);
  const double s3 = (e == 0 ? 1.0 : -1.0) * std::sqrt(std::max(0.0, 1 - c3 * c3));
  theta[2] = std::atan2(s3, c3);
  theta[1] = wrap_angle(std::atan2(y, x) - std::atan2(p.a3 * s3, p.a2 + p.a3 * c3));
  const double theta234 = std::atan2(X_14(1, 0), X_14(0, 0));
  theta[3] = wrap_angle(theta234 - theta[1] - theta[2]);
  return true;
}

}  // namespace

Eigen::Isometry3d ur_forward(const UrParameters& p, const ModelAngles& theta) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  for (const Eigen::Isometry3d& A : dh_links(p, theta)) X = X * A;
  return X;
}

UrArmSides ur_arm_sides(const UrParameters& p, const ModelAngles& t) {
  UrArmSides sides;
  sides.wrist_ahead_of_axis1 = p.a2 * std::cos(t[1]) + p.a3 * std::cos(t[1] + t[2]) +
                               p.d5 * std::sin(t[1] + t[2] + t[3]);
  sides.elbow_over_chord = -p.a2 * p.a3 * std::sin(t[2]);
  return sides;
}

std::array<ModelBranch, 8> ur_inverse(const UrParameters& p, const Eigen::Isometry3d& X_BF,
                                      double theta6_free) {
  std::array<ModelBranch, 8> branches{};
  const Eigen::Matrix3d& R = X_BF.linear();
  // P5 lies d4 along the parallel axes from axis 1: P5 . z1(theta_1) = d4 with
  // z1 = (sin t1, -cos t1, 0).
  const Eigen::Vector3d p5 = X_BF.translation() - p.d6 * R.col(2);
  const double radial_squared = p5.x() * p5.x() + p5.y() * p5.y() - p.d4 * p.d4;
  const double scale = std::max({std::abs(p.a2), std::abs(p.a3), std::abs(p.d4), std::abs(p.d5)});
  if (radial_squared < -kUrCosineSlack * scale * scale) return branches;
  const double radial = std::sqrt(std::max(0.0, radial_squared));
  for (int s = 0; s < 2; ++s) {
    const double x1 = s == 0 ? radial : -radial;  // P5 . x1
    ModelAngles theta{};
    theta[0] = wrap_angle(std::atan2(p5.y(), p5.x()) - std::atan2(-p.d4, x1));
    const Eigen::Vector3d z1(std::sin(theta[0]), -std::cos(theta[0]), 0.0);
    // cos t5 = z6 . z1 (axis 6 against the parallel axes), |sin t5| = |z6 x z1|.
    const double cos5 = R.col(2).dot(z1);
    const double abs_sin5 = R.col(2).cross(z1).norm();
    for (int w = 0; w < 2; ++w) {
      const double sin5 = w == 0 ? abs_sin5 : -abs_sin5;
      theta[4] = std::atan2(sin5, cos5);
      // x6 . z1 = sin t5 cos t6, y6 . z1 = -sin t5 sin t6.
      theta[5] = abs_sin5 > kUrWristSingular
                     ? std::atan2(-R.col(1).dot(z1) / sin5, R.col(0).dot(z1) / sin5)
                     : theta6_free;
      const std::array<Eigen::Isometry3d, 6> A = dh_links(p, theta);
      const Eigen::Isometry3d X_14 = A[0].inverse() * X_BF * (A[4] * A[5]).inverse();
      for (int e = 0; e < 2; ++e) {
        ModelBranch& branch = branches[static_cast<std::size_t>(4 * s + 2 * e + w)];
        branch.theta = theta;
        branch.valid = solve_ur_planar_arm(p, X_14, e, branch.theta);
      }
    }
  }
  return branches;
}

}  // namespace grpvss::kinematics

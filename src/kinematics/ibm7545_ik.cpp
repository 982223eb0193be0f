#include "grpvss/kinematics/ibm7545_ik.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace grpvss::kinematics {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kAngleSlack = 1e-9;   // structure recognition, rad
constexpr double kLengthSlack = 1e-12;  // structure recognition, length
// Roundoff in the trigonometry may put an exact boundary solution (e.g. theta1 = 0) a few ulps
// outside a limit; such values are accepted and clamped onto the limit.
constexpr double kIkLimitSlack = 1e-10;
constexpr double kToolZSlack = 1e-9;

bool near_angle(double angle, double expected) {
  return std::abs(std::remainder(angle - expected, 2 * kPi)) <= kAngleSlack;
}

// Fits value + 2 pi k into [minimum, maximum] choosing k so that the result is nearest to
// `near`; returns false when no k fits.
bool fit_revolute(double value, double minimum, double maximum, double near, double& out) {
  // The common case first: value fits and neither value - 2 pi nor value + 2 pi does, so it is
  // the only candidate (no division, no search).
  if (value >= minimum - kIkLimitSlack && value <= maximum + kIkLimitSlack &&
      value + 2 * kPi > maximum + kIkLimitSlack && value - 2 * kPi < minimum - kIkLimitSlack) {
    out = std::clamp(value, minimum, maximum);
    return true;
  }
  bool found = false;
  const double k_low = std::ceil((minimum - kIkLimitSlack - value) / (2 * kPi));
  const double k_high = std::floor((maximum + kIkLimitSlack - value) / (2 * kPi));
  for (double k = k_low; k <= k_high; k += 1.0) {
    const double candidate = std::clamp(value + 2 * kPi * k, minimum, maximum);
    if (!found || std::abs(candidate - near) < std::abs(out - near)) out = candidate;
    found = true;
  }
  return found;
}

class Ibm7545Ik final : public InverseKinematics {
 public:
  explicit Ibm7545Ik(const RobotModel& model) : joints_(model.joints) {}

  IkSolution solve(const Eigen::Isometry3d& X_WE_target,
                   const Eigen::VectorXd& q_near) const override {
    if (q_near.size() != 4) throw std::logic_error("Ibm7545Ik: q_near must have 4 values");
    const Eigen::Matrix3d& R = X_WE_target.linear();
    if ((R.col(2) - Eigen::Vector3d(0, 0, -1)).cwiseAbs().maxCoeff() > kToolZSlack) {
      return {IkStatus::kOutOfWorkspace, {}};
    }
    const Eigen::Vector3d p = X_WE_target.translation();
    const double yaw = std::atan2(R(1, 0), R(0, 0));
    const DhParameters& dh1 = joints_[0].dh;
    const DhParameters& dh2 = joints_[1].dh;
    const DhParameters& dh3 = joints_[2].dh;
    const DhParameters& dh4 = joints_[3].dh;

    // z = d1 + d2 - (d3 + q3) - d4 (alpha_2 = 180 deg turns z2 down).
    const double q3 = dh1.d + dh2.d - dh4.d - dh3.d - p.z();
    if (q3 < joints_[2].minimum - kIkLimitSlack || q3 > joints_[2].maximum + kIkLimitSlack) {
      return {IkStatus::kOutOfWorkspace, {}};
    }
    // Planar two-link arm: x + i y = a1 e^{i theta1} + a2 e^{i (theta1 + theta2)}.
    const double a1 = dh1.a;
    const double a2 = dh2.a;
    const double r2 = p.x() * p.x() + p.y() * p.y();
    double c2 = (r2 - a1 * a1 - a2 * a2) / (2 * a1 * a2);
    if (std::abs(c2) > 1 + 1e-12) return {IkStatus::kOutOfWorkspace, {}};
    c2 = std::clamp(c2, -1.0, 1.0);

    // Fixed-size candidates (no allocation per branch: CP lines solve the IK every 0.5 in.).
    const Eigen::Vector4d near = q_near;
    const double bearing = std::atan2(p.y(), p.x());
    const double elbow = std::acos(c2);
    // The two elbow branches mirror each other: theta2 = +-elbow, and the angle between the
    // bearing and link 1 is +-atan2(a2 sin(elbow), a1 + a2 cos(elbow)), with sin(elbow) =
    // sqrt(1 - c2^2) and cos(elbow) = c2. One atan2 serves both branches (a CP line solves
    // the IK every 0.5 in.; the trigonometry was most of its cost).
    const double sin_elbow = std::sqrt((1.0 - c2) * (1.0 + c2));  // c2 is in [-1, 1]
    const double link1_from_bearing = std::atan2(a2 * sin_elbow, a1 + a2 * c2);
    bool solved = false;
    Eigen::Vector4d best_q;
    double best_distance = std::numeric_limits<double>::infinity();
    for (const double branch : {1.0, -1.0}) {
      const double theta2 = branch * elbow;
      const double theta1 = bearing - branch * link1_from_bearing;
      // yaw = theta1 + theta2 - theta3_offset - theta4, theta_i = dh_i.theta + q_i.
      const double theta4 = theta1 + theta2 - dh3.theta - yaw;
      Eigen::Vector4d q;
      q[2] = std::clamp(q3, joints_[2].minimum, joints_[2].maximum);
      if (!fit_revolute(theta1 - dh1.theta, joints_[0].minimum, joints_[0].maximum, near[0],
                        q[0]) ||
          !fit_revolute(theta2 - dh2.theta, joints_[1].minimum, joints_[1].maximum, near[1],
                        q[1]) ||
          !fit_revolute(theta4 - dh4.theta, joints_[3].minimum, joints_[3].maximum, near[3],
                        q[3])) {
        continue;
      }
      const double distance = (q - near).norm();
      if (distance < best_distance) {
        best_distance = distance;
        best_q = q;
        solved = true;
      }
    }
    if (!solved) return {IkStatus::kOutOfWorkspace, {}};
    return {IkStatus::kSolved, Eigen::VectorXd(best_q)};
  }

  std::string name() const override { return "IBM 7545 closed form"; }

 private:
  std::vector<Joint> joints_;
};

}  // namespace

bool is_ibm7545_structure(const RobotModel& model) {
  if (model.joint_count() != 4) return false;
  const auto& j = model.joints;
  // Its closed form reads the DH parameters: general frames (a cell's base pose) are not DH.
  for (const Joint& joint : j) {
    if (joint.frames) return false;
  }
  const JointType expected_types[4] = {JointType::kRevolute, JointType::kRevolute,
                                       JointType::kPrismatic, JointType::kRevolute};
  const double expected_alpha[4] = {0.0, kPi, 0.0, 0.0};
  for (int i = 0; i < 4; ++i) {
    if (j[static_cast<std::size_t>(i)].type != expected_types[i]) return false;
    if (!near_angle(j[static_cast<std::size_t>(i)].dh.alpha, expected_alpha[i])) return false;
  }
  // The planar arm needs two non-zero links for the elbow formula.
  return std::abs(j[2].dh.a) <= kLengthSlack && std::abs(j[3].dh.a) <= kLengthSlack &&
         std::abs(j[0].dh.a) > kLengthSlack && std::abs(j[1].dh.a) > kLengthSlack;
}

std::unique_ptr<InverseKinematics> make_ibm7545_ik(const RobotModel& model) {
  if (!is_ibm7545_structure(model)) {
    throw std::invalid_argument("make_ibm7545_ik: robot '" + model.name +
                                "' does not have the IBM 7545 structure");
  }
  return std::make_unique<Ibm7545Ik>(model);
}

}  // namespace grpvss::kinematics

// recognise_opw: the OPW model of a chain (see family_recognition.hpp for the conventions).
#include <cmath>
#include <cstdio>

#include "chain_geometry.hpp"
#include "elementary_rotations.hpp"
#include "grpvss/kinematics/family_recognition.hpp"

namespace grpvss::kinematics {
namespace {

using namespace detail;

Recognition<OpwChainModel> not_opw(const std::string& reason) {
  return {std::nullopt, reason};
}

// The family's structure at q = 0; fills the wrist centre. A reason when it does not hold.
std::optional<std::string> opw_structure_problem(const std::vector<AxisLine>& a, double length_tol,
                                                 Eigen::Vector3d& wrist_centre) {
  const double angle_tol = kStructureTolerance;
  const auto& u = [&](int i) -> const Eigen::Vector3d& { return a[static_cast<std::size_t>(i - 1)].direction; };
  if (std::abs(u(1).dot(u(2))) > angle_tol) return "axes 1 and 2 are not perpendicular";
  if (u(2).cross(u(3)).norm() > angle_tol) return "axes 2 and 3 are not parallel";
  if (line_distance(a[1], a[2]) <= length_tol) return "axes 2 and 3 coincide";
  if (std::abs(u(2).dot(u(4))) > angle_tol) return "axis 4 is not perpendicular to axes 2 and 3";
  if (std::abs(u(4).dot(u(5))) > angle_tol) return "axes 4 and 5 are not perpendicular";
  if (std::abs(u(5).dot(u(6))) > angle_tol) return "axes 5 and 6 are not perpendicular";
  if (line_distance(a[3], a[4]) > length_tol) return "axes 4 and 5 do not meet (no spherical wrist)";
  wrist_centre = closest_point(a[3], a[4]);
  if ((foot(a[5], wrist_centre) - wrist_centre).norm() > length_tol) {
    return "axis 6 misses the meeting point of axes 4 and 5 (no spherical wrist)";
  }
  return std::nullopt;
}

// B, then a1, b, c1, c2, a2, c3 and joints 1-3's signs and offsets. Returns theta_2 + theta_3
// at q = 0 (the forearm's tilt), which the wrist fit needs.
double fit_arm(const ChainGeometry& g, const Eigen::Vector3d& C, double length_tol,
               OpwChainModel& m) {
  const AxisLine& axis1 = g.axes[0];
  const Eigen::Vector3d origin = base_origin(axis1);
  const Eigen::Vector3d shoulder = closest_point(g.axes[1], axis1);
  const Eigen::Vector3d z_B = base_up(axis1, origin, shoulder, length_tol);
  const Eigen::Vector3d side = g.axes[1].direction.cross(z_B).normalized();
  const double a1_side = side.dot(shoulder - origin);
  const double c_side = side.dot(C - origin);
  const double x_sign = std::abs(a1_side) > length_tol ? sign_of(a1_side)
                        : std::abs(c_side) > length_tol ? sign_of(c_side) : 1.0;
  m.placement.X_WB = frame_from(origin, z_B, x_sign * side);
  const Eigen::Isometry3d X_BW = m.placement.X_WB.inverse();
  const Eigen::Vector3d p2 = X_BW * shoulder;
  const Eigen::Vector3d p3 = X_BW * g.axes[2].point;
  const Eigen::Vector3d c = X_BW * C;
  OpwParameters& p = m.parameters;
  p.a1 = p2.x();
  p.c1 = p2.z();
  p.b = c.y();
  // Arm-plane vectors as (x, z) of B: element 0 is x, element 1 is z.
  const Eigen::Vector2d lower_arm(p3.x() - p2.x(), p3.z() - p2.z());
  p.c2 = lower_arm.norm();
  const double theta2 = std::atan2(lower_arm[0], lower_arm[1]);
  // Forearm direction: +-axis 4, the sign that makes c3 >= 0.
  const Eigen::Vector3d u4 = X_BW.linear() * g.axes[3].direction;
  Eigen::Vector2d forearm = Eigen::Vector2d(u4.x(), u4.z()).normalized();
  const Eigen::Vector2d elbow_to_wrist(c.x() - p3.x(), c.z() - p3.z());
  const double sign4 = sign_of(elbow_to_wrist.dot(forearm));
  forearm *= sign4;
  const double theta23 = std::atan2(forearm[0], forearm[1]);
  p.c3 = elbow_to_wrist.dot(forearm);
  p.a2 = elbow_to_wrist[0] * std::cos(theta23) - elbow_to_wrist[1] * std::sin(theta23);
  const Eigen::Vector3d y_B = m.placement.X_WB.linear().col(1);
  m.placement.sign = {sign_of(axis1.direction.dot(z_B)), sign_of(g.axes[1].direction.dot(y_B)),
                      sign_of(g.axes[2].direction.dot(y_B)), sign4, 1.0, 1.0};
  m.placement.offset = {0.0, theta2, wrap_angle(theta23 - theta2), 0.0, 0.0, 0.0};
  return theta23;
}

// Joints 4-6's signs and offsets, c4 and the tool on the flange.
void fit_wrist(const ChainGeometry& g, const Eigen::Vector3d& C, double theta23, OpwChainModel& m) {
  const Eigen::Isometry3d X_BW = m.placement.X_WB.inverse();
  const Eigen::Matrix3d R_B0c = rot_y(theta23);
  Eigen::Vector3d v5 = R_B0c.transpose() * X_BW.linear() * g.axes[4].direction;
  const double sign5 = sign_of(v5.y());  // model axis 5 = Rz(t4) y: keep |t4 offset| <= pi/2
  v5 *= sign5;
  const double theta4 = std::atan2(-v5.x(), v5.y());
  const Eigen::Matrix3d R_B4 = R_B0c * rot_z(theta4);
  Eigen::Vector3d v6 = R_B4.transpose() * X_BW.linear() * g.axes[5].direction;
  const double sign6 = sign_of(v6.z());  // model axis 6 = Ry(t5) z
  v6 *= sign6;
  const double theta5 = std::atan2(v6.x(), v6.z());
  const Eigen::Matrix3d R_B5 = R_B4 * rot_y(theta5);
  const Eigen::Isometry3d X_BT = X_BW * g.X_WT;
  const Eigen::Vector3d c = X_BW * C;
  m.parameters.c4 = R_B5.col(2).dot(X_BT.translation() - c);
  const double theta6 = tool_roll(R_B5, X_BT.linear());
  Eigen::Isometry3d X_BF = Eigen::Isometry3d::Identity();
  X_BF.linear() = R_B5 * rot_z(theta6);
  X_BF.translation() = c + m.parameters.c4 * R_B5.col(2);
  m.placement.X_FT = X_BF.inverse() * X_BT;
  m.placement.sign[4] = sign5;
  m.placement.sign[5] = sign6;
  m.placement.offset[3] = theta4;
  m.placement.offset[4] = theta5;
  m.placement.offset[5] = theta6;
}

}  // namespace

Recognition<OpwChainModel> recognise_opw(const KinematicChain& chain, const Eigen::Isometry3d& X_ET) {
  if (auto reason = six_revolute_joints(chain)) return not_opw(*reason);
  const ChainGeometry g = chain_geometry_at_zero(chain, X_ET);
  const double length_tol = kStructureTolerance * g.length_scale;
  Eigen::Vector3d C;
  if (auto reason = opw_structure_problem(g.axes, length_tol, C)) return not_opw(*reason);
  OpwChainModel m;
  m.X_ET = X_ET;
  const double theta23 = fit_arm(g, C, length_tol, m);
  if (std::hypot(m.parameters.a2, m.parameters.c3) <= length_tol) {
    return not_opw("the wrist centre lies on axis 3");
  }
  fit_wrist(g, C, theta23, m);
  const OpwParameters parameters = m.parameters;
  m.fk_deviation = model_fk_deviation(chain, X_ET, g.length_scale, m.placement,
                                      [&](const ModelAngles& t) { return opw_forward(parameters, t); });
  if (!(m.fk_deviation <= kFamilyFkTolerance)) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "the fitted OPW model's FK differs from the chain's by %.3g (relative), more than %.0e",
                  m.fk_deviation, kFamilyFkTolerance);
    return not_opw(text);
  }
  return {m, ""};
}

}  // namespace grpvss::kinematics

// recognise_ur: the UR model of a chain (see family_recognition.hpp for the conventions).
#include <cmath>
#include <cstdio>

#include "chain_geometry.hpp"
#include "elementary_rotations.hpp"
#include "grpvss/kinematics/family_recognition.hpp"

namespace grpvss::kinematics {
namespace {

using namespace detail;

Recognition<UrChainModel> not_ur(const std::string& reason) {
  return {std::nullopt, reason};
}

std::optional<std::string> ur_structure_problem(const std::vector<AxisLine>& a, double length_tol) {
  const double angle_tol = kStructureTolerance;
  const auto u = [&](int i) -> const Eigen::Vector3d& { return a[static_cast<std::size_t>(i - 1)].direction; };
  if (std::abs(u(1).dot(u(2))) > angle_tol) return "axes 1 and 2 are not perpendicular";
  if (line_distance(a[0], a[1]) > length_tol) return "axes 1 and 2 do not meet";
  if (u(2).cross(u(3)).norm() > angle_tol || u(2).cross(u(4)).norm() > angle_tol) {
    return "axes 2, 3 and 4 are not parallel";
  }
  if (line_distance(a[1], a[2]) <= length_tol) return "axes 2 and 3 coincide";
  if (line_distance(a[2], a[3]) <= length_tol) return "axes 3 and 4 coincide";
  if (std::abs(u(4).dot(u(5))) > angle_tol) return "axes 4 and 5 are not perpendicular";
  if (line_distance(a[3], a[4]) > length_tol) return "axes 4 and 5 do not meet";
  if (std::abs(u(5).dot(u(6))) > angle_tol) return "axes 5 and 6 are not perpendicular";
  if (line_distance(a[4], a[5]) > length_tol) return "axes 5 and 6 do not meet";
  return std::nullopt;
}

// B, d1, a2, a3 and joints 1-4's signs, joints 2-3's offsets. Returns theta_2 + theta_3 at
// q = 0. (x, y) below are the arm plane's coordinates: B's x and z relative to the shoulder.
double fit_ur_arm(const ChainGeometry& g, double length_tol, UrChainModel& m) {
  const AxisLine& axis1 = g.axes[0];
  const Eigen::Vector3d origin = base_origin(axis1);
  const Eigen::Vector3d shoulder = closest_point(axis1, g.axes[1]);
  const Eigen::Vector3d z_B = base_up(axis1, origin, shoulder, length_tol);
  // Joint 2 turns about z1 = -y_B at theta_1 = 0; its sign is made +1: y_B = -axis 2.
  m.placement.X_WB = frame_from(origin, z_B, -g.axes[1].direction.cross(z_B));
  const Eigen::Isometry3d X_BW = m.placement.X_WB.inverse();
  UrParameters& p = m.parameters;
  p.d1 = (X_BW * shoulder).z();
  const auto in_plane = [&](const Eigen::Vector3d& point_W) {
    const Eigen::Vector3d b = X_BW * point_W;
    return Eigen::Vector2d(b.x(), b.z() - p.d1);
  };
  // a_i (cos, sin)(angle) spans axis i to axis i+1; a_i < 0 as UR writes it.
  const Eigen::Vector2d upper = in_plane(g.axes[2].point);
  const Eigen::Vector2d fore = in_plane(g.axes[3].point) - upper;
  p.a2 = -upper.norm();
  p.a3 = -fore.norm();
  const double theta2 = std::atan2(-upper.y(), -upper.x());
  const double theta23 = std::atan2(-fore.y(), -fore.x());
  const Eigen::Vector3d z1 = -m.placement.X_WB.linear().col(1);
  m.placement.sign = {sign_of(axis1.direction.dot(z_B)), sign_of(g.axes[1].direction.dot(z1)),
                      sign_of(g.axes[2].direction.dot(z1)), sign_of(g.axes[3].direction.dot(z1)),
                      1.0, 1.0};
  m.placement.offset = {0.0, theta2, wrap_angle(theta23 - theta2), 0.0, 0.0, 0.0};
  return theta23;
}

// d4, d5, d6, joints 4-6's offsets, joints 5-6's signs and the tool on the flange.
void fit_ur_wrist(const ChainGeometry& g, double theta23, UrChainModel& m) {
  const Eigen::Isometry3d X_BW = m.placement.X_WB.inverse();
  const Eigen::Vector3d p45 = X_BW * closest_point(g.axes[3], g.axes[4]);
  const Eigen::Vector3d p56 = X_BW * closest_point(g.axes[4], g.axes[5]);
  m.parameters.d4 = -p45.y();  // along z1 = -y_B from the shoulder (which has y = 0)
  const Eigen::Matrix3d R_B3 = rot_x(kPi / 2) * rot_z(theta23);
  Eigen::Vector3d v5 = R_B3.transpose() * X_BW.linear() * g.axes[4].direction;
  const double sign5 = v5.y() <= 0 ? 1.0 : -1.0;  // model axis 5 = (sin t4, -cos t4, 0)
  v5 *= sign5;
  const double theta4 = std::atan2(v5.x(), -v5.y());
  const Eigen::Matrix3d R_B4 = R_B3 * rot_z(theta4) * rot_x(kPi / 2);
  m.parameters.d5 = (p56 - p45).dot(R_B4.col(2));
  Eigen::Vector3d v6 = R_B4.transpose() * X_BW.linear() * g.axes[5].direction;
  const double sign6 = sign_of(v6.y());  // model axis 6 = (-sin t5, cos t5, 0)
  v6 *= sign6;
  const double theta5 = std::atan2(-v6.x(), v6.y());
  const Eigen::Matrix3d R_B5 = R_B4 * rot_z(theta5) * rot_x(-kPi / 2);
  const Eigen::Isometry3d X_BT = X_BW * g.X_WT;
  m.parameters.d6 = (X_BT.translation() - p56).dot(R_B5.col(2));
  const double theta6 = tool_roll(R_B5, X_BT.linear());
  Eigen::Isometry3d X_BF = Eigen::Isometry3d::Identity();
  X_BF.linear() = R_B5 * rot_z(theta6);
  X_BF.translation() = p56 + m.parameters.d6 * R_B5.col(2);
  m.placement.X_FT = X_BF.inverse() * X_BT;
  m.placement.sign[4] = sign5;
  m.placement.sign[5] = sign6;
  m.placement.offset[3] = theta4;
  m.placement.offset[4] = theta5;
  m.placement.offset[5] = theta6;
}

}  // namespace

Recognition<UrChainModel> recognise_ur(const KinematicChain& chain, const Eigen::Isometry3d& X_ET) {
  if (auto reason = six_revolute_joints(chain)) return not_ur(*reason);
  const ChainGeometry g = chain_geometry_at_zero(chain, X_ET);
  const double length_tol = kStructureTolerance * g.length_scale;
  if (auto reason = ur_structure_problem(g.axes, length_tol)) return not_ur(*reason);
  UrChainModel m;
  m.X_ET = X_ET;
  fit_ur_wrist(g, fit_ur_arm(g, length_tol, m), m);
  const UrParameters parameters = m.parameters;
  m.fk_deviation = model_fk_deviation(chain, X_ET, g.length_scale, m.placement,
                                      [&](const ModelAngles& t) { return ur_forward(parameters, t); });
  if (!(m.fk_deviation <= kFamilyFkTolerance)) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "the fitted UR model's FK differs from the chain's by %.3g (relative), more than %.0e",
                  m.fk_deviation, kFamilyFkTolerance);
    return not_ur(text);
  }
  return {m, ""};
}

}  // namespace grpvss::kinematics

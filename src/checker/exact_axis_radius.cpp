#include "exact_axis_radius.hpp"

#include <algorithm>
#include <cmath>

#include "exact_rational.hpp"
#include "grpvss/geometry/rounded_bounds.hpp"

namespace grpvss::certify {
namespace {

Rational smaller(const Rational& a, const Rational& b) { return a < b ? a : b; }

Rational exact_reach(const Joint& joint) {
  if (joint.type != JointType::kPrismatic) return abs(exact(joint.dh.d));
  const Rational low = abs(exact(joint.dh.d) + exact(joint.minimum));
  const Rational high = abs(exact(joint.dh.d) + exact(joint.maximum));
  return low > high ? low : high;
}

// |t^|_1 + error >= |t|_2 for the exact translation t of a stored frame.
Rational exact_translation_norm(const Eigen::Isometry3d& X, double translation_error) {
  const Eigen::Vector3d t = X.translation();
  return abs(exact(t.x())) + abs(exact(t.y())) + abs(exact(t.z())) + exact(translation_error);
}

Rational exact_prismatic_travel(const Joint& joint) {
  if (joint.type != JointType::kPrismatic) return 0;
  const Rational low = abs(exact(joint.minimum));
  const Rational high = abs(exact(joint.maximum));
  return low > high ? low : high;
}

// Carries the norm bound of a point in frame m to frame m-1 across a joint with general frames.
// proof: proofs/motion-bound.md#lemma-general-axis-radius
Rational exact_general_step(const Joint& joint, const Rational& norm) {
  const JointFrames& frames = *joint.frames;
  return exact_translation_norm(frames.X_PJ, frames.X_PJ_translation_error) +
         exact_translation_norm(frames.X_JC, frames.X_JC_translation_error) +
         exact_prismatic_travel(joint) + norm;
}

}  // namespace

// proof: proofs/motion-bound.md#lemma-axis-radius
mpq_class exact_axis_radius(const RobotModel& robot, int link, const HullPoints& hull, int joint) {
  // Base (frame `link`): rho >= distance from the z axis, zeta >= |z|, norm >= |u|_2, each
  // the maximum over the hull's points (convex functions: the maximum is at a vertex).
  Rational norm = 0;
  Rational zeta = 0;
  const double radial_candidate = geometry::radial_extent_upper(hull);
  // A non-finite candidate (coordinates beyond ~1e154; the file readers allow 1e9) falls back.
  bool radial_candidate_holds = std::isfinite(radial_candidate);
  Rational rho = radial_candidate_holds ? exact(radial_candidate) : Rational(0);
  Rational radial_l1 = 0;  // fallback if the rounded square root were ever too small
  for (const auto& p : hull.points) {
    const Rational x = abs(exact(p.x()));
    const Rational y = abs(exact(p.y()));
    const Rational z = abs(exact(p.z()));
    norm = std::max(norm, Rational(x + y + z));
    zeta = std::max(zeta, z);
    radial_l1 = std::max(radial_l1, Rational(x + y));
    radial_candidate_holds = radial_candidate_holds && rho * rho >= x * x + y * y;
  }
  if (!radial_candidate_holds) rho = radial_l1;
  rho = smaller(rho, norm);
  // The exact points lie within hull_point_error of the stored ones.
  // proof: proofs/cell-geometry.md#lemma-geometry-error
  const Rational point_error = exact(robot.hull_point_error);
  norm += point_error;
  rho += point_error;
  zeta += point_error;
  // Frames link-1 .. joint: apply A_m = Rot_z Trans_z(d_m) Trans_x(a_m) Rot_x(alpha_m).
  for (int m = link; m > joint; --m) {
    const Joint& joint_m = robot.joints[m - 1];
    if (joint_m.frames) {
      norm = exact_general_step(joint_m, norm);
      rho = norm;
      zeta = norm;
      continue;
    }
    const Rational s = exact(geometry::trig_magnitude_upper(std::sin(joint_m.dh.alpha)));
    const Rational c = exact(geometry::trig_magnitude_upper(std::cos(joint_m.dh.alpha)));
    const Rational a = abs(exact(joint_m.dh.a));
    const Rational reach = exact_reach(joint_m);
    const Rational next_norm = a + reach + norm;
    const Rational next_rho = smaller(next_norm, a + rho + s * zeta);
    const Rational next_zeta = smaller(next_norm, reach + s * rho + c * zeta);
    norm = next_norm;
    rho = next_rho;
    zeta = next_zeta;
  }
  // Distance from axis `joint` (the z axis of frame joint-1): d_joint and Rot_z do not change it.
  const Joint& joint_j = robot.joints[joint - 1];
  if (joint_j.frames) {
    // rho(t_JC) + |w_j|: the motion about the axis and X_PJ keep the distance from it.
    const Eigen::Vector3d t = joint_j.frames->X_JC.translation();
    return abs(exact(t.x())) + abs(exact(t.y())) + exact(joint_j.frames->X_JC_translation_error) +
           norm;
  }
  const Rational s = exact(geometry::trig_magnitude_upper(std::sin(joint_j.dh.alpha)));
  return abs(exact(joint_j.dh.a)) + smaller(norm, rho + s * zeta);
}

}  // namespace grpvss::certify

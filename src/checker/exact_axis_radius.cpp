#include "exact_axis_radius.hpp"

#include <algorithm>
#include <cmath>

#include "grpvss/geometry/rounded_bounds.hpp"

namespace grpvss::certify {
namespace {

using Rational = mpq_class;

Rational exact(double value) { return Rational(value); }
Rational smaller(const Rational& a, const Rational& b) { return a < b ? a : b; }

Rational exact_reach(const Joint& joint) {
  if (joint.type != JointType::kPrismatic) return abs(exact(joint.dh.d));
  const Rational low = abs(exact(joint.dh.d) + exact(joint.minimum));
  const Rational high = abs(exact(joint.dh.d) + exact(joint.maximum));
  return low > high ? low : high;
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
  // Frames link-1 .. joint: apply A_m = Rot_z Trans_z(d_m) Trans_x(a_m) Rot_x(alpha_m).
  for (int m = link; m > joint; --m) {
    const Joint& joint_m = robot.joints[m - 1];
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
  const Rational s = exact(geometry::trig_magnitude_upper(std::sin(joint_j.dh.alpha)));
  return abs(exact(joint_j.dh.a)) + smaller(norm, rho + s * zeta);
}

}  // namespace grpvss::certify

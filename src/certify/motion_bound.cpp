#include "grpvss/certify/motion_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "grpvss/common/next_double.hpp"
#include "grpvss/geometry/rounded_bounds.hpp"
#include "grpvss/geometry/directed_rounding.hpp"


namespace grpvss::certify {
namespace {

// Upper bound on |x + y| under an active upward scope.
double abs_sum_up(double x, double y) {
  namespace r = geometry::rounding;
  return std::max(r::add_up(x, y), r::add_up(-x, -y));
}

// d^max of joint m: |d| for a revolute joint, max |d + q| over the limits for a prismatic one.
double reach_up(const Joint& joint) {
  if (joint.type != JointType::kPrismatic) return std::abs(joint.dh.d);
  return std::max(abs_sum_up(joint.dh.d, joint.minimum), abs_sum_up(joint.dh.d, joint.maximum));
}

// Upper bound on |t|_2 of the exact translation of a stored frame: |t^|_1 + its error.
double translation_norm_up(const Eigen::Isometry3d& X, double translation_error) {
  namespace r = geometry::rounding;
  const Eigen::Vector3d t = X.translation();
  return r::add_up(r::add_up(r::add_up(std::abs(t.x()), std::abs(t.y())), std::abs(t.z())),
                   translation_error);
}

// Largest |q| a prismatic joint reaches within its limits (0 for a revolute one).
double prismatic_travel_up(const Joint& joint) {
  if (joint.type != JointType::kPrismatic) return 0.0;
  return std::max(std::abs(joint.minimum), std::abs(joint.maximum));
}

// The recursion state of proofs/motion-bound.md#lemma-axis-radius in frame m: bounds on the
// norm, the distance from the z axis and |z| of every hull point carried to frame m.
struct FrameExtent {
  double norm = 0.0;
  double rho = 0.0;
  double zeta = 0.0;
};

// Joint m with general frames (proofs/motion-bound.md#lemma-general-axis-radius): the axis
// radius is rho(t_JC) + |w|, and frame m-1 keeps only a norm bound.
double general_axis_radius_up(const JointFrames& frames, const FrameExtent& extent) {
  namespace r = geometry::rounding;
  const Eigen::Vector3d t = frames.X_JC.translation();
  const double radial_t =
      r::add_up(r::add_up(std::abs(t.x()), std::abs(t.y())), frames.X_JC_translation_error);
  return r::add_up(radial_t, extent.norm);
}

FrameExtent general_step_up(const Joint& joint, const FrameExtent& extent) {
  namespace r = geometry::rounding;
  const JointFrames& frames = *joint.frames;
  const double norm = r::add_up(
      r::add_up(translation_norm_up(frames.X_PJ, frames.X_PJ_translation_error),
                translation_norm_up(frames.X_JC, frames.X_JC_translation_error)),
      r::add_up(prismatic_travel_up(joint), extent.norm));
  return {norm, norm, norm};
}

// R_{jh} for every joint j <= link by the radial/axial recursion of
// proofs/motion-bound.md#lemma-axis-radius, every operation rounded up (all terms are
// non-negative, so each rounded result bounds the exact one from above).
std::vector<double> axis_radii_up(const RobotModel& robot, int link, const HullPoints& hull) {
  namespace r = geometry::rounding;
  const int joint_count = robot.joint_count();
  std::vector<double> per_joint(joint_count, 0.0);
  const double radial = geometry::radial_extent_upper(hull);
  // libm in the default rounding mode, before the upward scope.
  std::vector<double> sin_upper(joint_count), cos_upper(joint_count);
  for (int j = 0; j < joint_count; ++j) {
    sin_upper[j] = geometry::trig_magnitude_upper(std::sin(robot.joints[j].dh.alpha));
    cos_upper[j] = geometry::trig_magnitude_upper(std::cos(robot.joints[j].dh.alpha));
  }
  r::UpwardRoundingScope upward;
  double norm = 0.0;
  double zeta = 0.0;
  for (const auto& p : hull.points) {
    norm = std::max(norm, r::add_up(r::add_up(std::abs(p.x()), std::abs(p.y())), std::abs(p.z())));
    zeta = std::max(zeta, std::abs(p.z()));
  }
  double rho = std::min(radial, norm);
  // The exact points lie within hull_point_error of the stored ones (0 for thesis robots).
  // proof: proofs/cell-geometry.md#lemma-geometry-error
  if (robot.hull_point_error > 0.0) {
    norm = r::add_up(norm, robot.hull_point_error);
    rho = r::add_up(rho, robot.hull_point_error);
    zeta = r::add_up(zeta, robot.hull_point_error);
  }
  // Walk down from frame `link`; after applying A_m the point is in frame m-1, and axis m
  // is that frame's z axis.
  for (int m = link; m >= 1; --m) {
    const Joint& joint = robot.joints[m - 1];
    if (joint.frames) {
      // proof: proofs/motion-bound.md#lemma-general-axis-radius
      const FrameExtent extent{norm, rho, zeta};
      per_joint[m - 1] = general_axis_radius_up(*joint.frames, extent);
      const FrameExtent next = general_step_up(joint, extent);
      norm = next.norm;
      rho = next.rho;
      zeta = next.zeta;
      continue;
    }
    const double a = std::abs(joint.dh.a);
    if (m <= joint_count) {
      per_joint[m - 1] =
          r::add_up(a, std::min(norm, r::add_up(rho, r::mul_up(sin_upper[m - 1], zeta))));
    }
    const double reach = reach_up(joint);
    const double next_norm = r::add_up(r::add_up(a, reach), norm);
    const double next_rho =
        std::min(next_norm, r::add_up(r::add_up(a, rho), r::mul_up(sin_upper[m - 1], zeta)));
    const double next_zeta = std::min(
        next_norm, r::add_up(r::add_up(reach, r::mul_up(sin_upper[m - 1], rho)),
                             r::mul_up(cos_upper[m - 1], zeta)));
    norm = next_norm;
    rho = next_rho;
    zeta = next_zeta;
  }
  return per_joint;
}

// A sum of n non-negative doubles computed in round-to-nearest is within (n-1)u of the
// exact sum; inflating by 2n ulps and stepping up once makes it an upper bound.
double round_sum_upward(double computed_sum, int term_count) {
  const double inflated =
      computed_sum * (1.0 + 2.0 * term_count * std::numeric_limits<double>::epsilon());
  return next_up(inflated);
}

}  // namespace

HullRadiusTable::HullRadiusTable(const RobotModel& robot) {
  const int joint_count = robot.joint_count();
  joint_types_.reserve(joint_count);
  for (const Joint& joint : robot.joints) joint_types_.push_back(joint.type);
  radius_.resize(robot.links.size());
  // proof: proofs/motion-bound.md#lemma-axis-radius
  for (int link = 0; link < static_cast<int>(robot.links.size()); ++link) {
    for (const HullPoints& hull : robot.links[link].hulls) {
      radius_[link].push_back(axis_radii_up(robot, std::min(link, joint_count), hull));
    }
  }
}

double HullRadiusTable::radius(int link, int hull, int joint) const {
  if (joint < 1 || joint > link) throw std::logic_error("HullRadiusTable: joint outside 1..link");
  return radius_.at(link).at(hull).at(joint - 1);
}

double HullRadiusTable::motion_bound_weight(int link, int hull, int joint) const {
  if (joint > link) return 0.0;
  return joint_types_.at(joint - 1) == JointType::kRevolute ? radius(link, hull, joint) : 1.0;
}

double HullRadiusTable::hull_motion_bound(int link, int hull, const Eigen::VectorXd& dq) const {
  // proof: proofs/motion-bound.md#lemma-motion-bound
  double bound = 0.0;
  int terms = 0;
  for (int joint = 1; joint <= link; ++joint) {
    const double increment = std::abs(dq[joint - 1]);
    if (joint_types_[joint - 1] == JointType::kRevolute) {
      // Each product is rounded up by one ulp so the sum only needs the sum inflation.
      bound += next_up(increment * radius_[link][hull][joint - 1]);
    } else {
      bound += increment;
    }
    ++terms;
  }
  return terms == 0 ? 0.0 : round_sum_upward(bound, terms);
}

}  // namespace grpvss::certify

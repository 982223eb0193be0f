#include "grpvss/certify/motion_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

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
  // Walk down from frame `link`; after applying A_m the point is in frame m-1, and axis m
  // is that frame's z axis.
  for (int m = link; m >= 1; --m) {
    const Joint& joint = robot.joints[m - 1];
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
  return std::nextafter(inflated, std::numeric_limits<double>::infinity());
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
      bound += std::nextafter(increment * radius_[link][hull][joint - 1],
                              std::numeric_limits<double>::infinity());
    } else {
      bound += increment;
    }
    ++terms;
  }
  return terms == 0 ? 0.0 : round_sum_upward(bound, terms);
}

}  // namespace grpvss::certify

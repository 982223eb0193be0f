#include "grpvss/certify/motion_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gmpxx.h>

namespace grpvss::certify {
namespace {

using Rational = mpq_class;

// |a| + dmax of the transform A_m, the most it can move a point away from an earlier axis.
// For a prismatic joint d ranges over dh.d + [min, max]; for a revolute joint d is fixed.
double reach_of_joint_abs_sum(const Joint& joint) {
  if (joint.type == JointType::kPrismatic) {
    return std::abs(joint.dh.a) +
           std::max(std::abs(joint.dh.d + joint.minimum), std::abs(joint.dh.d + joint.maximum));
  }
  return std::abs(joint.dh.a) + std::abs(joint.dh.d);
}

double max_l1_norm(const HullPoints& hull) {
  double largest = 0.0;
  for (const auto& p_L : hull.points) {
    largest = std::max(largest, std::abs(p_L.x()) + std::abs(p_L.y()) + std::abs(p_L.z()));
  }
  return largest;
}

// A sum of n non-negative doubles computed in round-to-nearest is within (n-1)u of the
// exact sum; inflating by 2n ulps and stepping up once makes it an upper bound.
double round_sum_upward(double computed_sum, int term_count) {
  const double inflated =
      computed_sum * (1.0 + 2.0 * term_count * std::numeric_limits<double>::epsilon());
  return std::nextafter(inflated, std::numeric_limits<double>::infinity());
}

Rational exact(double value) { return Rational(value); }

}  // namespace

HullRadiusTable::HullRadiusTable(const RobotModel& robot) {
  const int joint_count = robot.joint_count();
  joint_types_.reserve(joint_count);
  for (const Joint& joint : robot.joints) joint_types_.push_back(joint.type);
  radius_.resize(robot.links.size());
  // proof: proofs/motion-bound.md#lemma-axis-radius
  for (int link = 0; link < static_cast<int>(robot.links.size()); ++link) {
    for (const HullPoints& hull : robot.links[link].hulls) {
      std::vector<double> per_joint(joint_count, 0.0);
      for (int joint = 1; joint <= std::min(link, joint_count); ++joint) {
        double sum = std::abs(robot.joints[joint - 1].dh.a);
        int terms = 1;
        for (int m = joint + 1; m <= link; ++m) {
          sum += reach_of_joint_abs_sum(robot.joints[m - 1]);
          ++terms;
        }
        sum += max_l1_norm(hull);
        per_joint[joint - 1] = round_sum_upward(sum, terms + 1);
      }
      radius_[link].push_back(std::move(per_joint));
    }
  }
}

double HullRadiusTable::radius(int link, int hull, int joint) const {
  if (joint < 1 || joint > link) throw std::logic_error("HullRadiusTable: joint outside 1..link");
  return radius_.at(link).at(hull).at(joint - 1);
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

double HullRadiusTable::link_motion_bound(int link, const Eigen::VectorXd& dq) const {
  double largest = 0.0;
  for (int hull = 0; hull < hull_count(link); ++hull) {
    largest = std::max(largest, hull_motion_bound(link, hull, dq));
  }
  return largest;
}

bool radius_bound_holds_exactly(const RobotModel& robot, int link, int hull, int joint,
                                double claimed) {
  if (joint < 1 || joint > link || link >= static_cast<int>(robot.links.size())) return false;
  if (hull < 0 || hull >= static_cast<int>(robot.links[link].hulls.size())) return false;
  Rational sum = abs(exact(robot.joints[joint - 1].dh.a));
  for (int m = joint + 1; m <= link; ++m) {
    const Joint& joint_m = robot.joints[m - 1];
    Rational reach_d = abs(exact(joint_m.dh.d));
    if (joint_m.type == JointType::kPrismatic) {
      const Rational low = abs(exact(joint_m.dh.d) + exact(joint_m.minimum));
      const Rational high = abs(exact(joint_m.dh.d) + exact(joint_m.maximum));
      reach_d = low > high ? low : high;
    }
    sum += abs(exact(joint_m.dh.a)) + reach_d;
  }
  Rational largest_l1 = 0;
  for (const auto& p_L : robot.links[link].hulls[hull].points) {
    const Rational l1 = abs(exact(p_L.x())) + abs(exact(p_L.y())) + abs(exact(p_L.z()));
    if (l1 > largest_l1) largest_l1 = l1;
  }
  return exact(claimed) >= sum + largest_l1;
}

}  // namespace grpvss::certify

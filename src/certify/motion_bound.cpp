#include "grpvss/certify/motion_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>


namespace grpvss::certify {
namespace {

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

}  // namespace grpvss::certify

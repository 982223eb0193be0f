#include "grpvss/certify/exact_axis_radius.hpp"

namespace grpvss::certify {

// proof: proofs/motion-bound.md#lemma-axis-radius
mpq_class exact_axis_radius(const RobotModel& robot, int link, const HullPoints& hull, int joint) {
  auto exact = [](double value) { return mpq_class(value); };
  using Rational = mpq_class;

  Rational sum = abs(exact(robot.joints[joint - 1].dh.a));
  for (int m = joint + 1; m <= link; ++m) {
    const Joint& joint_m = robot.joints[m - 1];
    Rational reach = abs(exact(joint_m.dh.d));
    if (joint_m.type == JointType::kPrismatic) {
      const Rational low = abs(exact(joint_m.dh.d) + exact(joint_m.minimum));
      const Rational high = abs(exact(joint_m.dh.d) + exact(joint_m.maximum));
      reach = low > high ? low : high;
    }
    sum += abs(exact(joint_m.dh.a)) + reach;
  }
  Rational largest = 0;
  for (const auto& p : hull.points) {
    const Rational l1 = abs(exact(p.x())) + abs(exact(p.y())) + abs(exact(p.z()));
    if (l1 > largest) largest = l1;
  }
  return sum + largest;
}

}  // namespace grpvss::certify

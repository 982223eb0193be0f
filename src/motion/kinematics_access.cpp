#include "grpvss/motion/kinematics_access.hpp"

namespace grpvss::motion {

int first_joint_outside_limits(const RobotModel& robot, const Eigen::VectorXd& q, double slack) {
  for (int j = 0; j < robot.joint_count(); ++j) {
    const Joint& joint = robot.joints[j];
    if (!(q[j] >= joint.minimum - slack && q[j] <= joint.maximum + slack)) return j;
  }
  return -1;
}

}  // namespace grpvss::motion

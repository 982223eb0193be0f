// cell::start_configuration and parse_start_list: the `--start` values in the inputs' units
// (degrees for thesis files, radians with a cell) turned into library units and checked
// against each joint's limits, with messages that name the joint.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/cell/start_configuration.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/units.hpp"

namespace {

using grpvss::cell::parse_start_list;
using grpvss::cell::start_configuration;

// A revolute joint limited to +-180 degrees (as a thesis reader stores it) and a prismatic one.
grpvss::RobotModel two_joint_robot(const std::string& first_name) {
  grpvss::RobotModel robot;
  robot.joints.resize(2);
  robot.joints[0].name = first_name;
  robot.joints[0].minimum = grpvss::io::degrees_to_radians(-180.0);
  robot.joints[0].maximum = grpvss::io::degrees_to_radians(180.0);
  robot.joints[1].type = grpvss::JointType::kPrismatic;
  robot.joints[1].minimum = 0.0;
  robot.joints[1].maximum = 9.8;
  return robot;
}

std::string message_of(const std::vector<double>& values, const grpvss::RobotModel& robot,
                       bool from_cell) {
  try {
    start_configuration(values, robot, from_cell);
  } catch (const grpvss::InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(StartConfiguration, ThesisDegreesBecomeRadiansWithTheReadersProductAndLimitsAreReachable) {
  const grpvss::RobotModel robot = two_joint_robot("");
  const Eigen::VectorXd q = start_configuration({180.0, 9.8}, robot, false);
  EXPECT_EQ(q[0], robot.joints[0].maximum);  // bit for bit: touching a limit is within it
  EXPECT_EQ(q[1], 9.8);                      // prismatic: unchanged
  EXPECT_EQ(start_configuration({90.0, 1.0}, robot, false)[0], 90.0 * grpvss::io::kRadiansPerDegree);
}

TEST(StartConfiguration, CellValuesAreRadiansAsGiven) {
  const grpvss::RobotModel robot = two_joint_robot("pan");
  const Eigen::VectorXd q = start_configuration({0.25, 2.0}, robot, true);
  EXPECT_EQ(q[0], 0.25);
  EXPECT_EQ(q[1], 2.0);
  EXPECT_EQ(message_of({3.5, 0.0}, robot, true),
            "--start:0: expected pan within its limits [-3.14159, 3.14159] rad, found 3.5");
}

TEST(StartConfiguration, WrongCountsAndValuesBeyondTheLimitsNameTheJoint) {
  const grpvss::RobotModel robot = two_joint_robot("");
  EXPECT_EQ(message_of({0.0}, robot, false),
            "--start:0: expected one value per joint (2 joints), found 1 values");
  EXPECT_EQ(message_of({181.0, 0.0}, robot, false),
            "--start:0: expected joint 1 within its limits [-180, 180] deg, found 181");
  EXPECT_EQ(message_of({0.0, -0.5}, robot, false),
            "--start:0: expected joint 2 within its limits [0, 9.8] length units, found -0.5");
}

TEST(StartConfiguration, TheListIsCommaSeparatedNumbers) {
  EXPECT_EQ(parse_start_list("0,-1.5708, 2e-1"), (std::vector<double>{0.0, -1.5708, 0.2}));
  EXPECT_THROW(parse_start_list("0,,1"), grpvss::InputError);
  EXPECT_THROW(parse_start_list("0,1x"), grpvss::InputError);
  EXPECT_THROW(parse_start_list(""), grpvss::InputError);
}

}  // namespace

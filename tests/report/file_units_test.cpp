#include "grpvss/report/file_units.hpp"
#include "support/angles.hpp"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>


namespace grpvss::report {
namespace {

using grpvss::test::kPi;

TEST(FileUnits, DegreesOfKnownAngles) {
  EXPECT_EQ(degrees(0.0), 0.0);
  EXPECT_EQ(degrees(kPi), 180.0);
  EXPECT_EQ(degrees(-kPi / 2), -90.0);
}

// The readers store degrees * (pi/180); the report gives the file's number back to within one
// unit in the last place, for every 2-decimal angle in [-360, 360] (exhaustive).
TEST(FileUnits, FileAnglesComeBackWithinOneUlp) {
  int exact = 0;
  for (int hundredths = -36000; hundredths <= 36000; ++hundredths) {
    const double file_value = hundredths / 100.0;
    const double back = degrees(file_value * (kPi / 180.0));
    const double ulp = std::nextafter(std::abs(file_value), 1e300) - std::abs(file_value);
    ASSERT_LE(std::abs(back - file_value), ulp) << file_value;
    exact += back == file_value ? 1 : 0;
  }
  EXPECT_GT(exact, 72001 * 9 / 10);  // most come back exactly (e.g. 50, 1.05, 171.06)
  EXPECT_EQ(degrees(50.0 * (kPi / 180.0)), 50.0);
  EXPECT_EQ(degrees(171.06 * (kPi / 180.0)), 171.06);
}

TEST(FileUnits, OnlyRevoluteJointsAreConverted) {
  EXPECT_EQ(joint_value_in_file_units(kPi, JointType::kRevolute), 180.0);
  EXPECT_EQ(joint_value_in_file_units(kPi, JointType::kPrismatic), kPi);
  const Eigen::Vector3d q(kPi / 4, 2.5, -kPi);
  EXPECT_EQ(joint_values_in_file_units(
                q, {JointType::kRevolute, JointType::kPrismatic, JointType::kRevolute}),
            (std::vector<double>{45.0, 2.5, -180.0}));
}

TEST(FileUnits, SizeMismatchIsALogicError) {
  EXPECT_THROW(joint_values_in_file_units(Eigen::Vector2d(0, 0), {JointType::kRevolute}),
               std::logic_error);
}

TEST(FileUnits, JointTypesOfARobot) {
  RobotModel robot;
  robot.joints.resize(2);
  robot.joints[1].type = JointType::kPrismatic;
  EXPECT_EQ(joint_types_of(robot),
            (std::vector<JointType>{JointType::kRevolute, JointType::kPrismatic}));
}

}  // namespace
}  // namespace grpvss::report

// Which IK a robot gets: the closed form of its family under --ik auto, the forced families
// with a clear error for other robots, and the IBM 7545 choice unchanged.
#include "grpvss/kinematics/automatic_ik.hpp"

#include <gtest/gtest.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "support/industrial_robots.hpp"
#include "support/sample_robots.hpp"

namespace grpvss::kinematics {
namespace {

// A 6R arm of neither family: no two consecutive axes parallel or perpendicular.
RobotModel generic_6r() {
  RobotModel model = test::make_puma560_model();
  const double alpha[6] = {0.4, -0.7, 1.1, 0.5, -0.9, 0.3};
  for (std::size_t i = 0; i < 6; ++i) model.joints[i].dh.alpha = alpha[i];
  return model;
}

TEST(AutomaticIk, PicksTheClosedFormOfTheFamily) {
  EXPECT_EQ(make_automatic_ik(test::make_ibm7545_model())->name(), "IBM 7545 closed form");
  EXPECT_EQ(make_automatic_ik(test::make_puma560_model())->name(), "OPW closed form");
  EXPECT_EQ(make_automatic_ik(test::ur5e_dh_model())->name(), "UR closed form");
  EXPECT_EQ(make_automatic_ik(generic_6r())->name(), "damped least squares");
}

TEST(AutomaticIk, ForcedFamiliesGiveTheReasonWhenTheRobotIsNotOne) {
  EXPECT_TRUE(make_opw_ik(test::make_puma560_model()).ik);
  EXPECT_TRUE(make_ur_ik(test::ur5e_dh_model()).ik);
  const FamilyIk not_ur = make_ur_ik(test::make_puma560_model());
  EXPECT_FALSE(not_ur.ik);
  EXPECT_EQ(not_ur.reason, "axes 2, 3 and 4 are not parallel");
}

TEST(AutomaticIk, SelectIkNamesOpwAndUr) {
  EXPECT_EQ(motion::select_ik({IkMethod::kAuto, {}}, test::make_puma560_model(), "puma.txt")->name(), "OPW closed form");
  EXPECT_EQ(motion::select_ik({IkMethod::kOpw, {}}, test::make_puma560_model(), "puma.txt")->name(), "OPW closed form");
  EXPECT_EQ(motion::select_ik({IkMethod::kUr, {}}, test::ur5e_dh_model(), "ur5e.txt")->name(), "UR closed form");
  EXPECT_EQ(motion::select_ik({IkMethod::kAuto, {}}, test::make_ibm7545_model(), "ibm.txt")->name(), "IBM 7545 closed form");
  EXPECT_EQ(motion::select_ik({IkMethod::kNumeric, {}}, test::make_puma560_model(), "puma.txt")->name(), "damped least squares");
}

TEST(AutomaticIk, SelectIkRefusesARobotOfAnotherFamily) {
  try {
    motion::select_ik({IkMethod::kOpw, {}}, test::make_ibm7545_model(), "robot.txt");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "robot.txt");
    EXPECT_EQ(e.line(), 0);
    EXPECT_EQ(e.expected(), "a robot of the OPW family for --ik opw");
    EXPECT_EQ(e.found(), "the chain has 4 joints, not 6");
  }
  try {
    motion::select_ik({IkMethod::kUr, {}}, test::make_puma560_model(), "puma.txt");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.expected(), "a robot of the UR family for --ik ur");
    EXPECT_EQ(e.found(), "axes 2, 3 and 4 are not parallel");
  }
}

}  // namespace
}  // namespace grpvss::kinematics

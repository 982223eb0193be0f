#include "grpvss/kinematics/inverse_kinematics.hpp"

#include <gtest/gtest.h>

#include "support/sample_robots.hpp"

namespace grpvss::kinematics {
namespace {

TEST(DefaultIk, ClosedFormForIbm7545NumericOtherwise) {
  EXPECT_EQ(make_default_ik(test::make_ibm7545_model())->name(), "IBM 7545 closed form");
  EXPECT_EQ(make_default_ik(test::make_puma560_model())->name(), "damped least squares");
}

}  // namespace
}  // namespace grpvss::kinematics

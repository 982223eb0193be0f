#include "grpvss/common/input_error.hpp"

#include <gtest/gtest.h>

namespace grpvss {
namespace {

TEST(InputError, MessageNamesFileLineAndExpectation) {
  const InputError error("robot.txt", 12, "3 numbers per hull point", "2");
  EXPECT_STREQ(error.what(), "robot.txt:12: expected 3 numbers per hull point, found 2");
  EXPECT_EQ(error.file(), "robot.txt");
  EXPECT_EQ(error.line(), 12);
}

TEST(InputError, MessageOmitsFoundWhenNothingWasFound) {
  const InputError error("path.txt", 0, "a readable file");
  EXPECT_STREQ(error.what(), "path.txt:0: expected a readable file");
}

}  // namespace
}  // namespace grpvss

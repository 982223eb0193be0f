#include "grpvss/io/srdf_file.hpp"

#include <string>

#include <gtest/gtest.h>

#include "grpvss/common/input_error.hpp"
#include "support/input_error_expectations.hpp"

namespace grpvss::io {
namespace {

const std::string kPandaSrdf =
    "<?xml version=\"1.0\"?>\n"                                                           // 1
    "<robot name=\"panda\">\n"                                                             // 2
    "  <group name=\"arm\"><chain base_link=\"panda_link0\" tip_link=\"panda_link8\"/></group>\n"  // 3
    "  <virtual_joint name=\"fixed\" type=\"fixed\" parent_frame=\"world\" child_link=\"panda_link0\"/>\n"  // 4
    "  <disable_collisions link1=\"panda_link0\" link2=\"panda_link1\" reason=\"Adjacent\"/>\n"  // 5
    "  <disable_collisions link1=\"panda_link1\" link2=\"panda_link2\" reason=\"Adjacent\"/>\n"  // 6
    "  <disable_collisions link1=\"panda_link2\" link2=\"panda_link1\" reason=\"Never\"/>\n"     // 7
    "  <disable_collisions link1=\"panda_link0\" link2=\"panda_link3\"/>\n"                     // 8
    "  <end_effector name=\"hand\" parent_link=\"panda_link8\" group=\"hand\"/>\n"               // 9
    "  <enable_collisions link1=\"panda_link3\" link2=\"panda_link0\"/>\n"                      // 10
    "</robot>\n";

TEST(SrdfFile, DisabledPairsAreReadAndEverythingElseIsAWarning) {
  const SrdfFile srdf = parse_srdf(kPandaSrdf, "panda.srdf");
  EXPECT_EQ(srdf.robot_name, "panda");
  ASSERT_EQ(srdf.disabled_collisions.size(), 2u);  // line 7 repeats line 6, line 10 re-enables line 8
  EXPECT_EQ(srdf.disabled_collisions[0].link1, "panda_link0");
  EXPECT_EQ(srdf.disabled_collisions[0].link2, "panda_link1");
  EXPECT_EQ(srdf.disabled_collisions[0].reason, "Adjacent");
  EXPECT_EQ(srdf.disabled_collisions[0].line, 5);
  EXPECT_EQ(srdf.disabled_collisions[1].link1, "panda_link1");
  EXPECT_EQ(srdf.disabled_collisions[1].line, 6);
  ASSERT_EQ(srdf.warnings.size(), 4u);
  EXPECT_EQ(srdf.warnings[0].line, 3);
  EXPECT_EQ(srdf.warnings[0].text, "ignored <group> (GRPVSS reads only <disable_collisions> and <enable_collisions>)");
  EXPECT_EQ(srdf.warnings[1].line, 4);
  EXPECT_EQ(srdf.warnings[1].text, "ignored <virtual_joint> (GRPVSS reads only <disable_collisions> and <enable_collisions>)");
  EXPECT_EQ(srdf.warnings[2].line, 7);
  EXPECT_EQ(srdf.warnings[2].text, "duplicate <disable_collisions> of 'panda_link2' and 'panda_link1'");
  EXPECT_EQ(srdf.warnings[3].line, 9);
  EXPECT_EQ(srdf.warnings[3].file, "panda.srdf");
}

TEST(SrdfFile, PairsNamingUnknownLinksAreReported) {
  const SrdfFile srdf = parse_srdf(kPandaSrdf, "panda.srdf");
  const auto warnings = srdf_links_not_in(srdf, "panda.srdf", {"panda_link0", "panda_link2"});
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].line, 5);
  EXPECT_EQ(warnings[0].text, "<disable_collisions> names link 'panda_link1', which the robot does not have");
  EXPECT_EQ(warnings[1].line, 6);
}

TEST(SrdfFile, DefectsAreInputErrorsWithTheLine) {
  testing::expect_input_error([] { parse_srdf("<robot name=\"r\">\n<disable_collisions link1=\"a\"/>\n</robot>\n", "r.srdf"); },
                              "r.srdf", 2, "r.srdf:2: expected <disable_collisions> with attributes link1 and link2, found no link2");
  testing::expect_input_error([] { parse_srdf("<robot>\n<enable_collisions link2=\"a\"/>\n</robot>\n", "r.srdf"); },
                              "r.srdf", 2, "r.srdf:2: expected <enable_collisions> with attributes link1 and link2, found no link1");
  testing::expect_input_error([] { parse_srdf("<srdf/>\n", "r.srdf"); }, "r.srdf", 1,
                              "r.srdf:1: expected a <robot> root element, found <srdf>");
  testing::expect_input_error([] { parse_srdf("", "r.srdf"); }, "r.srdf", 0,
                              "r.srdf:0: expected well-formed XML, found Error=XML_ERROR_EMPTY_DOCUMENT ErrorID=13 (0xd) Line number=0");
  testing::expect_input_error([] { (void)read_srdf_file("/nonexistent/robot.srdf"); }, "/nonexistent/robot.srdf", 0,
                              "/nonexistent/robot.srdf:0: expected a readable file, found No such file or directory");
}

}  // namespace
}  // namespace grpvss::io

#include "report/thesis_error_text.hpp"

#include <regex>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "support/text_files.hpp"

namespace grpvss::report {
namespace {

/// The paragraph under "Error <code>:" in the verbatim copy of Appendix A.4.
std::string thesis_paragraph(int code) {
  const auto lines = test::split_lines(test::read_text_file(
      std::string(GRPVSS_SOURCE_DIR) + "/tests/report/golden/thesis_a4_error_messages.txt"));
  const std::string heading = "Error " + std::to_string(code) + ":";
  for (std::size_t i = 0; i + 2 < lines.size(); ++i) {
    if (lines[i] == heading) return lines[i + 2];
  }
  ADD_FAILURE() << "no " << heading << " in A.4";
  return {};
}

TEST(ThesisErrorText, PathWideErrorsAreTheThesisWordsVerbatim) {
  for (int code : {1, 2}) {
    EXPECT_EQ(thesis_error_text(code, 0), thesis_paragraph(code)) << "error " << code;
    EXPECT_EQ(thesis_error_text(code, 9), thesis_paragraph(code)) << "segment ignored";
  }
}

TEST(ThesisErrorText, SegmentErrorsReplaceTheThesisPlaceholderI) {
  for (int code = 3; code <= 6; ++code) {
    for (int segment : {1, 4, 12}) {
      const std::string expected = std::regex_replace(
          thesis_paragraph(code), std::regex(" segment I "), " segment " + std::to_string(segment) + " ");
      EXPECT_NE(expected, thesis_paragraph(code)) << "A.4 error " << code << " names segment I";
      EXPECT_EQ(thesis_error_text(code, segment), expected) << "error " << code;
    }
  }
}

TEST(ThesisErrorText, SampleErrorOfAppendixA3) {
  EXPECT_EQ(thesis_error_text(3, 4),
            "The final position of the motion segment 4 in the path input file is out of "
            "workspace. This motion segment was not simulated. The simulation terminated when "
            "this motion segment was encountered.");
}

TEST(ThesisErrorText, OnlyCodesOneToSixAreThesisErrors) {
  EXPECT_FALSE(is_thesis_error_code(0));
  EXPECT_TRUE(is_thesis_error_code(1));
  EXPECT_TRUE(is_thesis_error_code(6));
  EXPECT_FALSE(is_thesis_error_code(7));
  EXPECT_THROW(thesis_error_text(0, 1), std::out_of_range);
  EXPECT_THROW(thesis_error_text(7, 1), std::out_of_range);
  EXPECT_THROW(thesis_error_text(3, 0), std::out_of_range);
  EXPECT_THROW(thesis_error_text(6, -1), std::out_of_range);
}

}  // namespace
}  // namespace grpvss::report

#pragma once
/// \file
/// \brief Test helpers for InputError: run a callable, require that it throws InputError,
/// and check file, line and the whole message. Also small text-editing helpers for building
/// defective copies of the sample files.

#include <string>

#include <gtest/gtest.h>

#include "grpvss/common/input_error.hpp"

namespace grpvss::testing {

/// Runs `action`; fails the test unless it throws InputError with exactly this file, line and
/// what() text.
template <typename Action>
void expect_input_error(Action&& action, const std::string& file, int line,
                        const std::string& message) {
  try {
    action();
    ADD_FAILURE() << "no InputError thrown; expected: " << message;
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file);
    EXPECT_EQ(error.line(), line);
    EXPECT_EQ(std::string(error.what()), message);
  }
}

/// The text of a file under the source tree (e.g. "data/ibm7545/robot.txt").
std::string source_file_text(const std::string& relative_path);

/// `text` with its 1-based line `line` replaced by `content` (no newline in `content`).
std::string with_line_replaced(const std::string& text, int line, const std::string& content);

/// The first `lines` lines of `text`, each ending in a newline.
std::string first_lines(const std::string& text, int lines);

}  // namespace grpvss::testing

/// Reproducers found by the robot-program fuzz targets (fuzz/urscript_fuzzer.cpp,
/// fuzz/krl_fuzzer.cpp, fuzz/rapid_fuzzer.cpp). Every file under tests/io/regressions/<target>/
/// goes through the target's harness and must end as the contract says: a RobotProgram or an
/// InputError, nothing else. The defects themselves are pinned with their messages in the
/// unit tests (program_lexer_test.cpp).

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/krl_file.hpp"
#include "grpvss/io/rapid_file.hpp"
#include "grpvss/io/urscript_file.hpp"
#include "support/text_files.hpp"

namespace grpvss::io {
namespace {

const std::string kRegressions = std::string(GRPVSS_SOURCE_DIR) + "/tests/io/regressions/";

/// As fuzz/krl_fuzzer.cpp: the .src, a NUL byte, the .dat.
void parse_krl_input(std::string_view input) {
  const std::size_t split = input.find('\0');
  std::vector<KrlDataText> data;
  if (split != std::string_view::npos) data.push_back({"fuzz.dat", std::string(input.substr(split + 1))});
  parse_krl(input.substr(0, split), "fuzz.src", data);
}

/// Runs every reproducer of `target`; returns how many there were.
int run_reproducers(const std::string& target, void (*parse)(std::string_view)) {
  int count = 0;
  // A target whose fuzzer never found anything has no folder (git keeps no empty folder).
  if (!std::filesystem::exists(kRegressions + target)) return 0;
  for (const auto& entry : std::filesystem::directory_iterator(kRegressions + target)) {
    const std::string text = test::read_text_file(entry.path().string());
    ++count;
    try {
      parse(text);
    } catch (const InputError&) {
    } catch (const std::exception& other) {
      ADD_FAILURE() << entry.path() << ": " << other.what();
    }
  }
  return count;
}

TEST(ProgramFuzzRegression, EveryReproducerEndsInAProgramOrAnInputError) {
  EXPECT_GE(run_reproducers("krl", parse_krl_input), 1);
  EXPECT_GE(run_reproducers("urscript", [](std::string_view text) { parse_urscript(text, "fuzz.script"); }), 1);
  EXPECT_GE(run_reproducers("rapid", [](std::string_view text) { parse_rapid(text, "fuzz.mod"); }), 1);
}

}  // namespace
}  // namespace grpvss::io

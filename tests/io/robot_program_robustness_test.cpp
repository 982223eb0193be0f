/// Mutated copies of the sample robot programs must either be read or be rejected with an
/// InputError naming one of the files and a line inside it (or one past its end): never
/// another exception, never a crash. (fuzz/ runs the same property with libFuzzer.)

#include <functional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/io/krl_file.hpp"
#include "grpvss/io/rapid_file.hpp"
#include "grpvss/io/urscript_file.hpp"
#include "support/input_error_expectations.hpp"

namespace grpvss::io {
namespace {

std::string mutate_program(std::string text, const std::string& alphabet, std::mt19937_64& random) {
  std::uniform_int_distribution<std::size_t> position(0, text.size() - 1);
  std::uniform_int_distribution<std::size_t> letter(0, alphabet.size() - 1);
  const std::size_t at = position(random);
  switch (random() % 4) {
    case 0: text[at] = alphabet[letter(random)]; break;
    case 1: text.insert(at, 1, alphabet[letter(random)]); break;
    case 2: text.erase(at, 1); break;
    default: text.resize(at); break;
  }
  return text;
}

int program_line_count(const std::string& text) {
  int lines = 0;
  for (const char c : text) lines += (c == '\n');
  return lines + ((!text.empty() && text.back() != '\n') ? 1 : 0);
}

/// Returns how many of 400 mutants were rejected; fails on any other outcome.
int check_program_mutants(const std::string& original, const std::string& alphabet, std::uint64_t seed,
                  const std::function<void(const std::string&)>& parse) {
  std::mt19937_64 random(seed);
  int rejected = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::string text = original;
    const int edits = 1 + static_cast<int>(random() % 3);
    for (int e = 0; e < edits && !text.empty(); ++e) text = mutate_program(text, alphabet, random);
    try {
      parse(text);
    } catch (const InputError& error) {
      ++rejected;
      EXPECT_EQ(error.file(), "mutant") << "trial " << trial << ": " << error.what();
      EXPECT_GE(error.line(), 1) << "trial " << trial << ": " << error.what();
      EXPECT_LE(error.line(), program_line_count(text) + 1) << "trial " << trial << ": " << error.what();
    } catch (const std::exception& other) {
      ADD_FAILURE() << "trial " << trial << ": unexpected " << other.what();
    }
  }
  return rejected;
}

TEST(RobotProgramRobustness, MutatedUrScriptIsReadOrRejected) {
  const std::string original = grpvss::testing::source_file_text("data/programs/ur5e_pick_and_place.script");
  const int rejected = check_program_mutants(original, "()[]=,.:#$'\"-+*/0123456789 \n\tpdefendifmovelj", 5,
                                     [](const std::string& text) { parse_urscript(text, "mutant"); });
  EXPECT_GT(rejected, 100);
}

TEST(RobotProgramRobustness, MutatedKrlIsReadOrRejected) {
  const std::string src = grpvss::testing::source_file_text("data/programs/kr_palletize.src");
  const std::string dat = grpvss::testing::source_file_text("data/programs/kr_palletize.dat");
  const std::string config = grpvss::testing::source_file_text("data/programs/$config.dat");
  const std::string alphabet = "(){}[]=,.:;#$&'\"-+*/0123456789 \n\tXYZABCSTDEFNLPIRC_";
  const int rejected = check_program_mutants(src, alphabet, 1988, [&](const std::string& text) {
    parse_krl(text, "mutant", {{"config", config}, {"dat", dat}});
  });
  EXPECT_GT(rejected, 100);
  // Mutated data files: errors name the data file.
  std::mt19937_64 random(7);
  for (int trial = 0; trial < 200; ++trial) {
    const std::string text = mutate_program(dat, alphabet, random);
    try {
      parse_krl(src, "kr.src", {{"config", config}, {"mutant.dat", text}});
    } catch (const InputError& error) {
      EXPECT_TRUE(error.file() == "mutant.dat" || error.file() == "kr.src") << error.what();
    } catch (const std::exception& other) {
      ADD_FAILURE() << "trial " << trial << ": unexpected " << other.what();
    }
  }
}

TEST(RobotProgramRobustness, MutatedRapidIsReadOrRejected) {
  const std::string original = grpvss::testing::source_file_text("data/programs/irb_glue.mod");
  const int rejected = check_program_mutants(original, "()[]{}=,.:;!%\\\"-+*/0123456789 \n\tEPROCMDULvz", 2026,
                                     [](const std::string& text) { parse_rapid(text, "mutant"); });
  EXPECT_GT(rejected, 100);
}

}  // namespace
}  // namespace grpvss::io

/// Mutated copies of the sample files must either parse or throw InputError naming the file
/// and a line inside it (or one past its end): never another exception, never a crash.

#include <functional>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "support/input_error_expectations.hpp"

namespace grpvss::io {
namespace {

/// One random edit: replace, insert or delete a byte, or cut the text at a random byte.
std::string mutate_reader_input(std::string text, std::mt19937_64& random) {
  static const std::string kAlphabet = "0123456789.,-+eE \n\r\t#xHULLnaif";
  std::uniform_int_distribution<std::size_t> position(0, text.size() - 1);
  std::uniform_int_distribution<std::size_t> letter(0, kAlphabet.size() - 1);
  const std::size_t at = position(random);
  switch (random() % 4) {
    case 0: text[at] = kAlphabet[letter(random)]; break;
    case 1: text.insert(at, 1, kAlphabet[letter(random)]); break;
    case 2: text.erase(at, 1); break;
    default: text.resize(at); break;
  }
  return text;
}

int reader_line_count(const std::string& text) {
  int lines = 0;
  for (const char c : text) lines += (c == '\n');
  return lines + ((!text.empty() && text.back() != '\n') ? 1 : 0);
}

/// Returns how many mutants were rejected; fails the test on any other outcome.
int check_reader_mutants(const std::string& original, std::uint64_t seed,
                  const std::function<void(const std::string&)>& parse) {
  std::mt19937_64 random(seed);
  int rejected = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::string text = original;
    const int edits = 1 + static_cast<int>(random() % 3);
    for (int e = 0; e < edits && !text.empty(); ++e) text = mutate_reader_input(text, random);
    try {
      parse(text);
    } catch (const InputError& error) {
      ++rejected;
      EXPECT_EQ(error.file(), "mutant.txt") << "trial " << trial;
      EXPECT_GE(error.line(), 1) << "trial " << trial;
      EXPECT_LE(error.line(), reader_line_count(text) + 1) << "trial " << trial;
    } catch (const std::exception& other) {
      ADD_FAILURE() << "trial " << trial << ": unexpected " << other.what();
    }
  }
  return rejected;
}

TEST(ReaderRobustness, MutatedRobotFilesParseOrThrowInputError) {
  const std::string original = grpvss::testing::source_file_text("data/ibm7545/robot.txt");
  const int rejected = check_reader_mutants(original, 7545, [](const std::string& text) {
    parse_robot_file(text, "mutant.txt");
  });
  EXPECT_GT(rejected, 100);  // most edits of a strict format are errors
}

TEST(ReaderRobustness, MutatedEnvironmentFilesParseOrThrowInputError) {
  const std::string original = grpvss::testing::source_file_text("data/ibm7545/environment.txt");
  const int rejected = check_reader_mutants(original, 1988, [](const std::string& text) {
    parse_environment_file(text, "mutant.txt");
  });
  EXPECT_GT(rejected, 100);
}

TEST(ReaderRobustness, MutatedPathFilesParseOrThrowInputError) {
  const RobotModel robot =
      read_robot_file(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/robot.txt");
  const std::string original =
      grpvss::testing::source_file_text("data/ibm7545/path-output-sample.txt");
  const int rejected = check_reader_mutants(original, 4341, [&](const std::string& text) {
    parse_path_file(text, "mutant.txt", robot);
  });
  EXPECT_GT(rejected, 100);
}

}  // namespace
}  // namespace grpvss::io

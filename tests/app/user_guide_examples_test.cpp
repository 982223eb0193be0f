// Every example command of docs/user-guide.md runs here: the ```sh blocks are extracted, the
// program name `grpvss` becomes the built binary (GRPVSS_CLI) and `data/` the repository's data
// folder, each block runs in a fresh temporary folder, and each command's exit code must be
// the one written next to it (`# exit N`).
#include <sys/wait.h>

#include <cstdlib>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/text_files.hpp"

namespace {

struct Example {
  std::string command;  ///< as written in the guide
  int expected_exit = -1;
  int line = 0;  ///< line in docs/user-guide.md
};

struct Block {
  int line = 0;
  std::vector<Example> examples;
};

/// The ```sh blocks of the guide; a command without `# exit N` fails the test.
std::vector<Block> extract_blocks(const std::string& text) {
  std::vector<Block> blocks;
  const std::vector<std::string> lines = grpvss::test::split_lines(text);
  const std::regex exit_comment(R"(^(.*\S)\s+#\s*exit\s+(\d+)\s*$)");
  bool inside = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (!inside) {
      if (line == "```sh") {
        inside = true;
        blocks.push_back(Block{static_cast<int>(i + 1), {}});
      }
      continue;
    }
    if (line == "```") {
      inside = false;
      continue;
    }
    if (line.empty() || line[0] == '#') continue;
    std::smatch match;
    Example example;
    example.line = static_cast<int>(i + 1);
    if (std::regex_match(line, match, exit_comment)) {
      example.command = match[1];
      example.expected_exit = std::stoi(match[2]);
    } else {
      example.command = line;
      ADD_FAILURE() << "docs/user-guide.md:" << i + 1 << ": no `# exit N` after the command";
    }
    blocks.back().examples.push_back(example);
  }
  EXPECT_FALSE(inside) << "an unterminated ```sh block";
  return blocks;
}

/// The command with the program and data paths of this build.
std::string substitute(const std::string& command) {
  const std::string cli = std::string("'") + GRPVSS_CLI + "'";
  const std::string data = std::string(GRPVSS_SOURCE_DIR) + "/data/";
  // `grpvss` as a command word: at the start, or after a pipe or a command separator.
  std::string text = std::regex_replace(command, std::regex(R"((^|[|;&]\s*)grpvss\b)"), "$1" + cli);
  // `data/` starting a word (an argument, or after '=' or '\n' inside printf text).
  text = std::regex_replace(text, std::regex(R"((^|[\s='n])data/)"), "$1" + data);
  return text;
}

int run_in(const std::string& dir, const std::string& command) {
  const std::string shell = "cd '" + dir + "' && { " + command + " ; } >/dev/null 2>&1";
  const int status = std::system(shell.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(UserGuideExamples, EveryExampleExitsAsDocumented) {
  const std::string guide =
      grpvss::test::read_text_file(std::string(GRPVSS_SOURCE_DIR) + "/docs/user-guide.md");
  const std::vector<Block> blocks = extract_blocks(guide);
  std::size_t commands = 0;
  for (const Block& block : blocks) {
    const std::string dir = grpvss::test::make_temporary_directory("user-guide");
    for (const Example& example : block.examples) {
      ++commands;
      if (example.expected_exit < 0) continue;
      EXPECT_EQ(run_in(dir, substitute(example.command)), example.expected_exit)
          << "docs/user-guide.md:" << example.line << ": " << example.command;
    }
  }
  // The guide documents every subcommand with examples (a guide without them tests nothing).
  EXPECT_GE(blocks.size(), 10u);
  for (const std::string subcommand :
       {"verify", "check-certificate", "trajectory", "expansion-audit", "interactive"}) {
    bool found = false;
    for (const Block& block : blocks) {
      for (const Example& example : block.examples) {
        found |= example.command.find("grpvss " + subcommand + " ") != std::string::npos;
      }
    }
    EXPECT_TRUE(found) << "no example of grpvss " << subcommand;
  }
  EXPECT_GE(commands, 30u);
}

TEST(UserGuideExamples, SubstitutionReplacesOnlyTheProgramAndDataPaths) {
  const std::string cli = std::string("'") + GRPVSS_CLI + "'";
  const std::string data = std::string(GRPVSS_SOURCE_DIR) + "/data/";
  EXPECT_EQ(substitute("grpvss verify --robot data/a.txt"), cli + " verify --robot " + data + "a.txt");
  EXPECT_EQ(substitute("printf '1\\ndata/x\\n' | grpvss interactive"),
            "printf '1\\n" + data + "x\\n' | " + cli + " interactive");
  EXPECT_EQ(substitute("grep -q grpvss-motion mydata/x"), "grep -q grpvss-motion mydata/x");
}

TEST(UserGuideExamples, ExtractionNeedsAnExitCodeOnEveryCommand) {
  const std::vector<Block> blocks =
      extract_blocks("text\n```sh\n# a comment\ngrpvss --version   # exit 0\n\nls  # exit 2\n```\n"
                     "```\nnot a shell block\n```\n");
  ASSERT_EQ(blocks.size(), 1u);
  ASSERT_EQ(blocks[0].examples.size(), 2u);
  EXPECT_EQ(blocks[0].examples[0].command, "grpvss --version");
  EXPECT_EQ(blocks[0].examples[0].expected_exit, 0);
  EXPECT_EQ(blocks[0].examples[1].expected_exit, 2);
  EXPECT_EQ(blocks[0].examples[1].line, 6);
}

}  // namespace

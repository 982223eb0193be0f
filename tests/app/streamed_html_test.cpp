// `grpvss verify --html` writes the page while the verification runs (the report in it was
// streamed, docs/reliability.md#resource-bounds); `grpvss animate` renders the page from the
// whole report document. Both must give the same bytes.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kIbm7545Data;

int run(const std::string& arguments) {
  const int status =
      std::system((std::string(GRPVSS_CLI) + " " + arguments + " > /dev/null").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(StreamedHtml, VerifyWritesThePageAnimateRendersFromTheWholeReport) {
  const std::string directory = grpvss::test::make_temporary_directory("streamed-html");
  const std::string inputs = "--robot " + kIbm7545Data + "robot.txt --env " + kIbm7545Data +
                             "environment.txt --path " + kIbm7545Data + "path.txt --tolerance 0.5";
  ASSERT_EQ(run("verify " + inputs + " --json " + directory + "/r.json --html " + directory +
                "/verify.html"),
            1);  // COLLISION
  ASSERT_EQ(run("animate " + directory + "/r.json --html " + directory + "/animate.html"), 0);
  const std::string streamed = grpvss::test::read_text_file(directory + "/verify.html");
  EXPECT_GT(streamed.size(), 10'000u);
  EXPECT_TRUE(streamed == grpvss::test::read_text_file(directory + "/animate.html"))
      << "the streamed page differs from the one rendered from the whole report";
  std::filesystem::remove_all(directory);
}

TEST(StreamedHtml, APageWithoutAReportFileIsTheSame) {
  const std::string directory = grpvss::test::make_temporary_directory("streamed-html");
  const std::string inputs = "--robot " + kIbm7545Data + "robot.txt --env " + kIbm7545Data +
                             "environment.txt --path " + kIbm7545Data + "path.txt --tolerance 0.5";
  ASSERT_EQ(run("verify " + inputs + " --html " + directory + "/only.html"), 1);
  ASSERT_EQ(run("verify " + inputs + " --json " + directory + "/r.json"), 1);
  ASSERT_EQ(run("animate " + directory + "/r.json --html " + directory + "/animate.html"), 0);
  // The two runs differ only in the report's generated_at (seconds): compare without it.
  const auto without_timestamp = [](std::string page) {
    const std::string key = "\"generated_at\":\"";
    const auto at = page.find(key);
    if (at != std::string::npos) page.erase(at + key.size(), page.find('"', at + key.size()) - at - key.size());
    return page;
  };
  EXPECT_TRUE(without_timestamp(grpvss::test::read_text_file(directory + "/only.html")) ==
              without_timestamp(grpvss::test::read_text_file(directory + "/animate.html")));
  EXPECT_EQ(grpvss::test::directory_entries(directory),
            (std::vector<std::string>{"animate.html", "only.html", "r.json"}));
  std::filesystem::remove_all(directory);
}

}  // namespace

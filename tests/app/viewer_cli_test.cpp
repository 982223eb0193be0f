// Runs the built `grpvss verify --html`, `animate` and `render` (GRPVSS_CLI) on the IBM 7545
// sample: one self-contained page, reports without a scene refused, no clobbering, and
// deterministic SVG.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

namespace fs = std::filesystem;
using grpvss::test::kIbm7545Data;

int run_viewer_cli(const std::string& arguments) {
  const std::string command = std::string(GRPVSS_CLI) + " " + arguments + " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class ViewerCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("grpvss-viewer-cli-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  int verify(const std::string& outputs) const {
    return run_viewer_cli("verify --robot " + kIbm7545Data + "robot.txt --env " + kIbm7545Data + "environment.txt --path " +
               kIbm7545Data + "path.txt --tolerance 0.5 --quiet " + outputs);
  }
  fs::path dir_;
};

TEST_F(ViewerCli, PipedVerificationPrintsNoProgressBar) {
  // stderr is a file here, not a terminal: the progress bar must stay silent.
  const std::string err = path("stderr.txt");
  const std::string command = std::string(GRPVSS_CLI) + " verify --robot " + kIbm7545Data +
                              "robot.txt --env " + kIbm7545Data + "environment.txt --path " + kIbm7545Data +
                              "path.txt --tolerance 0.5 >/dev/null 2>" + err;
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);  // COLLISION
  EXPECT_EQ(grpvss::test::read_text_file(err), "");
}

TEST_F(ViewerCli, VerificationOnATerminalDrawsAProgressBarAndErasesIt) {
  // util-linux `script` gives the command a pseudo-terminal; the typescript records stderr.
  const std::string typescript = path("typescript");
  const std::string inner = std::string(GRPVSS_CLI) + " verify --robot " + kIbm7545Data +
                            "robot.txt --env " + kIbm7545Data + "environment.txt --path " + kIbm7545Data +
                            "path.txt --tolerance 0.5 >/dev/null";
  const std::string command = "script -qec '" + inner + "' " + typescript + " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);  // COLLISION, passed through by script -e
  const std::string recorded = grpvss::test::read_text_file(typescript);
  EXPECT_NE(recorded.find("verifying ["), std::string::npos);
  EXPECT_NE(recorded.find("\r\x1b[K"), std::string::npos);  // erased at the end
}

TEST_F(ViewerCli, VerifyWritesOneSelfContainedPageHoldingTheReport) {
  ASSERT_EQ(verify("--json " + path("r.json") + " --html " + path("r.html")), 1);  // COLLISION
  const std::string html = grpvss::test::read_text_file(path("r.html"));
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(html.find("<link "), std::string::npos);
  EXPECT_EQ(html.find("@GRPVSS_"), std::string::npos);  // every placeholder filled
  const std::string open = "<script id=\"grpvss-report\" type=\"application/json\">";
  const auto begin = html.find(open);
  ASSERT_NE(begin, std::string::npos);
  const auto end = html.find("</script>", begin);
  const auto embedded = nlohmann::json::parse(html.substr(begin + open.size(), end - begin - open.size()));
  const auto written = nlohmann::json::parse(grpvss::test::read_text_file(path("r.json")));
  EXPECT_EQ(embedded, written);  // the page shows exactly the report of the same run
  EXPECT_EQ(written["scene"]["obstacles"].size(), 2u);
  EXPECT_EQ(written["scene"]["steps"].size(), written["steps"].size());
}

TEST_F(ViewerCli, AnimateReadsTheReportAndRefusesToClobber) {
  ASSERT_EQ(verify("--json " + path("r.json")), 1);
  EXPECT_EQ(run_viewer_cli("animate " + path("r.json") + " --html " + path("a.html")), 0);
  EXPECT_EQ(run_viewer_cli("animate " + path("r.json") + " --html " + path("a.html")), 2);  // exists
  EXPECT_EQ(run_viewer_cli("animate " + path("r.json") + " --html " + path("a.html") + " --force"), 0);
  // A report without a scene (or no report at all) is an input error.
  auto report = nlohmann::json::parse(grpvss::test::read_text_file(path("r.json")));
  report.erase("scene");
  std::ofstream(path("noscene.json")) << report.dump();
  EXPECT_EQ(run_viewer_cli("animate " + path("noscene.json") + " --html " + path("b.html")), 2);
  EXPECT_FALSE(fs::exists(path("b.html")));
  std::ofstream(path("text.json")) << "not json";
  EXPECT_EQ(run_viewer_cli("animate " + path("text.json") + " --html " + path("b.html")), 2);
}

TEST_F(ViewerCli, RenderIsDeterministicAndDrawsTheStepsStars) {
  ASSERT_EQ(verify("--json " + path("r.json")), 1);
  const auto report = nlohmann::json::parse(grpvss::test::read_text_file(path("r.json")));
  int step = 0;
  std::size_t points = 0;
  for (const auto& s : report["steps"]) {
    if (!s["interference_points"].empty()) {
      step = s["index"].get<int>();
      points = s["interference_points"].size();
      break;
    }
  }
  ASSERT_GT(step, 0);
  const std::string args = "render --report " + path("r.json") + " --step " + std::to_string(step);
  ASSERT_EQ(run_viewer_cli(args + " --svg " + path("a.svg")), 0);
  ASSERT_EQ(run_viewer_cli(args + " --svg " + path("b.svg")), 0);
  const std::string svg = grpvss::test::read_text_file(path("a.svg"));
  EXPECT_EQ(svg, grpvss::test::read_text_file(path("b.svg")));
  const std::regex star("<polygon class=\"star\"");
  EXPECT_EQ(static_cast<std::size_t>(std::distance(
                std::sregex_iterator(svg.begin(), svg.end(), star), std::sregex_iterator())),
            points);
  EXPECT_NE(svg.find("ANGLEX -75 ANGLEY 0 ANGLEZ 170 SCALE 1 SHIFT 0,0,0 WINDOW -50..50"), std::string::npos);
  EXPECT_EQ(run_viewer_cli(args + " --svg " + path("a.svg")), 2);  // exists, no --force
  EXPECT_EQ(run_viewer_cli("render --report " + path("r.json") + " --step 100000 --svg " + path("c.svg")), 2);
  // The report is positional like animate's; --report is an alias; one of them is required.
  EXPECT_EQ(run_viewer_cli("render " + path("r.json") + " --step 1 --svg " + path("p1.svg")), 0);
  EXPECT_EQ(run_viewer_cli("render --report " + path("r.json") + " --step 1 --svg " + path("p2.svg")), 0);
  EXPECT_EQ(grpvss::test::read_text_file(path("p1.svg")), grpvss::test::read_text_file(path("p2.svg")));
  EXPECT_EQ(run_viewer_cli("render --step 1 --svg " + path("p3.svg")), 2);
  EXPECT_EQ(run_viewer_cli(args + " --svg " + path("d.svg") + " --anglex 10 --window=-20,20 --scale 2"), 0);
  EXPECT_NE(grpvss::test::read_text_file(path("d.svg")).find("ANGLEX 10 ANGLEY 0 ANGLEZ 170 SCALE 2 SHIFT 0,0,0 WINDOW -20..20"), std::string::npos);
}

}  // namespace

// `grpvss check-certificate` reads the file one segment at a time (certificate_file.hpp): an
// untouched certificate is accepted, a tampered radius or a removed step is rejected, a
// truncated file is an input error.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/text_files.hpp"

namespace {

const std::string kData = std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/";
const std::string kInputs = "--robot " + kData + "robot.txt --env " + kData +
                            "environment.txt --path " + kData + "path.txt";

int run(const std::string& arguments) {
  const int status =
      std::system((std::string(GRPVSS_CLI) + " " + arguments + " > /dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class CheckCertificateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = grpvss::test::make_temporary_directory("check-certificate");
    ASSERT_EQ(run("verify " + kInputs + " --tolerance 0.5 --quiet --certificate " + path("c.json")), 1);
    document_ = nlohmann::json::parse(grpvss::test::read_text_file(path("c.json")));
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string path(const std::string& name) const { return directory_ + "/" + name; }
  int check(const nlohmann::json& document) const {
    std::ofstream(path("t.json")) << document.dump(1) << "\n";
    return run("check-certificate " + kInputs + " " + path("t.json"));
  }
  std::string directory_;
  nlohmann::json document_;
};

TEST_F(CheckCertificateCli, AcceptsTheCertificateVerifyWrote) {
  EXPECT_EQ(run("check-certificate " + kInputs + " " + path("c.json")), 0);
}

TEST_F(CheckCertificateCli, RejectsAnInflatedRadiusInTheLastSegment) {
  auto& hull = document_["segments"].back()["steps"][1]["hulls"][3];
  hull["radius"] = hull["radius"].get<double>() + 5.0;
  EXPECT_EQ(check(document_), 1);
}

TEST_F(CheckCertificateCli, RejectsARemovedStep) {
  auto& steps = document_["segments"][0]["steps"];
  ASSERT_GE(steps.size(), 3u);
  steps.erase(1);
  EXPECT_EQ(check(document_), 1);
}

TEST_F(CheckCertificateCli, ATruncatedFileIsAnInputError) {
  const std::string text = grpvss::test::read_text_file(path("c.json"));
  std::ofstream(path("t.json")) << text.substr(0, text.size() / 2);
  EXPECT_EQ(run("check-certificate " + kInputs + " " + path("t.json")), 2);
}

}  // namespace

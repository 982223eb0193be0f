// `grpvss check-certificate` reads the file one segment at a time (certificate_file.hpp): an
// untouched certificate is accepted, a tampered radius or a removed step is rejected, a
// truncated file is an input error. It prints the checker's decision and the motion model it
// checked, and refuses options that contradict the certificate.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kIbm7545Data;
const std::string kInputs = "--robot " + kIbm7545Data + "robot.txt --env " + kIbm7545Data +
                            "environment.txt --path " + kIbm7545Data + "path.txt";

int run_certificate_cli(const std::string& arguments) {
  const int status =
      std::system((std::string(GRPVSS_CLI) + " " + arguments + " > /dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Exit code and everything printed (stdout and stderr), through a file.
std::pair<int, std::string> run_capturing(const std::string& arguments, const std::string& log) {
  const int status =
      std::system((std::string(GRPVSS_CLI) + " " + arguments + " > " + log + " 2>&1").c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, grpvss::test::read_text_file(log)};
}

class CheckCertificateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = grpvss::test::make_temporary_directory("check-certificate");
    ASSERT_EQ(run_certificate_cli("verify " + kInputs + " --tolerance 0.5 --quiet --certificate " + path("c.json")), 1);
    document_ = nlohmann::json::parse(grpvss::test::read_text_file(path("c.json")));
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string path(const std::string& name) const { return directory_ + "/" + name; }
  int check(const nlohmann::json& document) const {
    std::ofstream(path("t.json")) << document.dump(1) << "\n";
    return run_certificate_cli("check-certificate " + kInputs + " " + path("t.json"));
  }
  std::string directory_;
  nlohmann::json document_;
};

TEST_F(CheckCertificateCli, AcceptsTheCertificateVerifyWrote) {
  EXPECT_EQ(run_certificate_cli("check-certificate " + kInputs + " " + path("c.json")), 0);
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
  EXPECT_EQ(run_certificate_cli("check-certificate " + kInputs + " " + path("t.json")), 2);
}

TEST_F(CheckCertificateCli, PrintsTheMotionModelItChecked) {
  const auto [code, text] = run_capturing("check-certificate " + kInputs + " " + path("c.json"),
                                          path("log.txt"));
  EXPECT_EQ(code, 0);
  EXPECT_NE(text.find("ACCEPTED: claim COLLISION"), std::string::npos) << text;
  EXPECT_NE(text.find("  motion model checked: independent PTP timing, CP speed 1 per s, IK IBM "
                      "7545 closed form\n"),
            std::string::npos)
      << text;
  const auto [json_code, json_text] = run_capturing(
      "check-certificate " + kInputs + " " + path("c.json") + " --json", path("log.json"));
  EXPECT_EQ(json_code, 0);
  const auto report = nlohmann::json::parse(json_text);
  EXPECT_EQ(report["motion_model"], (nlohmann::json{{"timing", "independent"},
                                                     {"cp_speed", 1.0},
                                                     {"ik", "IBM 7545 closed form"}}));
}

// An auditor who asks for synchronized timing must not get ACCEPTED for a certificate made
// with independent timing (it would be checked against a motion it does not describe).
TEST_F(CheckCertificateCli, RefusesATimingThatContradictsTheCertificate) {
  const auto [code, text] = run_capturing(
      "check-certificate " + kInputs + " --timing synchronized " + path("c.json"), path("log.txt"));
  EXPECT_EQ(code, 2);
  EXPECT_EQ(text,
            "grpvss: error: --timing:0: expected the timing the certificate was made with "
            "(independent); it certifies nothing about synchronized timing, found synchronized\n");
  EXPECT_EQ(run_certificate_cli("check-certificate " + kInputs + " --timing independent " + path("c.json")), 0);
}

// The claim (docs/certificate.md#claim): printed as checked; a contradicting --claim is refused;
// a certificate without the field (made before the claim existed) is checked as `steps`.
TEST_F(CheckCertificateCli, PrintsTheClaimItCheckedAndRefusesAnother) {
  EXPECT_EQ(document_["clear_claim"], "motion");
  const auto [code, text] =
      run_capturing("check-certificate " + kInputs + " " + path("c.json"), path("log.txt"));
  EXPECT_EQ(code, 0);
  EXPECT_NE(text.find("  claim checked: motion (CLEAR = robot + tolerance clear along the whole "
                      "motion)\n"),
            std::string::npos)
      << text;
  const auto [refused, refusal] = run_capturing(
      "check-certificate " + kInputs + " --claim steps " + path("c.json"), path("log2.txt"));
  EXPECT_EQ(refused, 2);
  EXPECT_EQ(refusal,
            "grpvss: error: --claim:0: expected the claim the certificate was made with "
            "(motion), found steps\n");
  EXPECT_EQ(run_certificate_cli("check-certificate " + kInputs + " --claim motion " + path("c.json")), 0);
  nlohmann::json old = document_;
  old.erase("clear_claim");
  std::ofstream(path("old.json")) << old.dump(1) << "\n";
  const auto [old_code, old_text] = run_capturing(
      "check-certificate " + kInputs + " --json " + path("old.json"), path("log3.json"));
  EXPECT_EQ(old_code, 0);
  EXPECT_EQ(nlohmann::json::parse(old_text)["clear_claim"], "steps");
}

TEST_F(CheckCertificateCli, RefusesAnIkThatIsNotTheCertificates) {
  const auto [code, text] = run_capturing(
      "check-certificate " + kInputs + " --ik numeric " + path("c.json"), path("log.txt"));
  EXPECT_EQ(code, 2);
  EXPECT_EQ(text,
            "grpvss: error: --ik:0: expected the IK the certificate was made with ('IBM 7545 "
            "closed form'), found 'numeric' (damped least squares)\n");
}

// The checker decides, the command only prints: a certificate claiming more segments than the
// path has is rejected by the checker itself (the command used to re-decide "accepted" from an
// empty failure list and accepted it).
TEST_F(CheckCertificateCli, RejectsMoreSegmentsThanThePathHas) {
  const std::size_t planned = document_["segments"].size();
  document_["segments"].push_back(document_["segments"].back());
  std::ofstream(path("more.json")) << document_.dump(1) << "\n";
  const auto [more_code, more_text] =
      run_capturing("check-certificate " + kInputs + " " + path("more.json"), path("log2.txt"));
  EXPECT_EQ(more_code, 1);
  EXPECT_NE(more_text.find("REJECTED"), std::string::npos) << more_text;
  EXPECT_NE(more_text.find("the certificate has " + std::to_string(planned + 1) +
                           " segments, the path's trajectory " + std::to_string(planned)),
            std::string::npos)
      << more_text;
}

}  // namespace

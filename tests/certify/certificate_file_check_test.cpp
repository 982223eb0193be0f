// check_certificate_file (the file read one segment at a time, as check-certificate and the
// Python module check it) against check_certificate() of the same document in memory: the same
// report for an accepted and for a tampered certificate; the header hook sees the header first
// and can refuse it.
#include "grpvss/checker/certificate_file_check.hpp"

#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/certify/verifier.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace grpvss::certify {
namespace {

using grpvss::test::ibm7545_file;

struct Sample {
  RobotModel robot = io::read_robot_file(ibm7545_file("robot.txt"));
  Environment environment = io::read_environment_file(ibm7545_file("environment.txt"));
  PathProgram program = io::read_path_file(ibm7545_file("path.txt"), robot);
  motion::KinematicsAccess kinematics =
      motion::make_kinematics_access(robot, motion::select_ik({}, robot, ibm7545_file("robot.txt")));

  nlohmann::json certificate_document() const {
    SetupRequest request;
    request.tolerance = 0.5;
    const VerificationRun run = verify(robot, environment, program, kinematics, resolve_setup(request));
    nlohmann::json document = certificate_to_json(run.certificate);
    document["inputs"] = {{"ik", "IBM 7545 closed form"}};
    return document;
  }
};

std::string write_document(const nlohmann::json& document, const std::string& name) {
  const std::string path = test::make_temporary_directory("certificate-file-check") + "/" + name;
  std::ofstream(path) << document.dump(1) << "\n";
  return path;
}

void expect_same_report(const CheckReport& from_file, const CheckReport& in_memory) {
  EXPECT_EQ(from_file.accepted, in_memory.accepted);
  EXPECT_EQ(from_file.claim, in_memory.claim);
  EXPECT_EQ(from_file.inequalities_checked, in_memory.inequalities_checked);
  EXPECT_EQ(from_file.failures, in_memory.failures);
  ASSERT_EQ(from_file.motion_clearances.size(), in_memory.motion_clearances.size());
  for (std::size_t i = 0; i < from_file.motion_clearances.size(); ++i) {
    EXPECT_EQ(from_file.motion_clearances[i].link, in_memory.motion_clearances[i].link);
    EXPECT_EQ(from_file.motion_clearances[i].lower_bound, in_memory.motion_clearances[i].lower_bound);
    EXPECT_EQ(from_file.motion_clearances[i].step, in_memory.motion_clearances[i].step);
  }
}

CheckReport check_in_memory(const Sample& s, const nlohmann::json& document) {
  return check_certificate(s.robot, s.environment, s.program, s.kinematics,
                           certificate_from_json(document, "memory"));
}

TEST(CertificateFileCheck, AcceptsTheSampleCertificateAsTheInMemoryCheckDoes) {
  const Sample sample;
  const nlohmann::json document = sample.certificate_document();
  const std::string path = write_document(document, "certificate.json");
  const CheckReport report = check_certificate_file(path, sample.robot, sample.environment,
                                                    sample.program, sample.kinematics, {});
  EXPECT_TRUE(report.accepted);
  EXPECT_EQ(report.claim, Verdict::kCollision);
  EXPECT_GT(report.inequalities_checked, 0);
  expect_same_report(report, check_in_memory(sample, document));
}

TEST(CertificateFileCheck, RejectsATamperedBoundAsTheInMemoryCheckDoes) {
  const Sample sample;
  nlohmann::json document = sample.certificate_document();
  document["segments"][0]["steps"][0]["hulls"][0]["evidence"][0]["lower_bound"] =
      document["segments"][0]["steps"][0]["hulls"][0]["evidence"][0]["lower_bound"].get<double>() * 10.0;
  const std::string path = write_document(document, "tampered.json");
  const CheckReport report = check_certificate_file(path, sample.robot, sample.environment,
                                                    sample.program, sample.kinematics, {});
  EXPECT_FALSE(report.accepted);
  EXPECT_FALSE(report.failures.empty());
  expect_same_report(report, check_in_memory(sample, document));
}

TEST(CertificateFileCheck, TheHeaderHookSeesTheHeaderAndCanRefuseIt) {
  const Sample sample;
  const std::string path = write_document(sample.certificate_document(), "certificate.json");
  int calls = 0;
  EXPECT_THROW(check_certificate_file(path, sample.robot, sample.environment, sample.program,
                                      sample.kinematics, {},
                                      [&](const Certificate& header) {
                                        ++calls;
                                        EXPECT_TRUE(header.segments.empty());
                                        EXPECT_EQ(header.inputs.at("ik"), "IBM 7545 closed form");
                                        EXPECT_EQ(header.tolerance, 0.5);
                                        throw std::runtime_error("refused");
                                      }),
               std::runtime_error);
  EXPECT_EQ(calls, 1);
}

}  // namespace
}  // namespace grpvss::certify

// Streamed outputs keep the atomic-output guarantees: a run that fails half-way leaves no file
// and no temporary, an existing output is refused and left byte-identical, pieces written to an
// AtomicOutputFile appear only at commit().
#include <filesystem>
#include <optional>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/certify/verifier.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/report/atomic_output.hpp"
#include "grpvss/report/certificate_output.hpp"
#include "grpvss/report/file_units.hpp"
#include "grpvss/report/json_report_stream.hpp"
#include "grpvss/report/spill_file.hpp"
#include "grpvss/report/thesis_output.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace grpvss::report {
namespace {

using grpvss::test::ibm7545_file;

/// Throws at the `limit`-th step, like a disk that fills up or a bug half-way.
class FailingObserver : public certify::VerificationObserver {
 public:
  explicit FailingObserver(int limit) : limit_(limit) {}
  void on_step(const certify::StepRecord& step) override {
    if (step.index >= limit_) throw std::runtime_error("stopped at step " + std::to_string(step.index));
  }

 private:
  int limit_;
};

class StreamFailure : public ::testing::Test {
 protected:
  void SetUp() override {
    robot_ = io::read_robot_file(ibm7545_file("robot.txt"));
    environment_ = io::read_environment_file(ibm7545_file("environment.txt"));
    program_ = io::read_path_file(ibm7545_file("path.txt"), robot_);
    kinematics_ = motion::make_kinematics_access(
        robot_, motion::select_ik({}, robot_, "robot.txt"));
    certify::SetupRequest request;
    request.tolerance = 0.5;
    setup_ = certify::resolve_setup(request);
    cell_.emplace(robot_, environment_, setup_.cell);
    hooks_.keep_steps = false;
    directory_ = test::make_temporary_directory("stream-failure");
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  RobotModel robot_;
  Environment environment_;
  PathProgram program_;
  motion::KinematicsAccess kinematics_;
  certify::VerificationSetup setup_;
  std::optional<certify::RobotCell> cell_;
  certify::RunHooks hooks_;
  std::string directory_;
};

TEST_F(StreamFailure, ARunThatThrowsHalfWayLeavesNoFileAndNoTemporary) {
  FailingObserver failing(5);
  {
    ThesisOutputStream thesis(directory_ + "/out.txt", false, joint_types_of(robot_));
    JsonReportStream json(robot_, {directory_ + "/report.json", false, directory_ + "/report.json", false});
    CertificateStream certificate(directory_ + "/certificate.json", false);
    // The failing observer comes last: the others have already written steps.
    hooks_.observers = {&thesis, &json, &certificate, &failing};
    EXPECT_THROW(certify::verify(*cell_, program_, kinematics_, setup_.run, hooks_),
                 std::runtime_error);
  }
  EXPECT_TRUE(test::directory_entries(directory_).empty());
}

TEST_F(StreamFailure, AnExistingOutputIsRefusedAtFinishAndLeftUntouched) {
  for (const char* name : {"out.txt", "report.json", "certificate.json"}) {
    std::ofstream(directory_ + "/" + name) << "the user's file\n";
  }
  ThesisOutputStream thesis(directory_ + "/out.txt", false, joint_types_of(robot_));
  JsonReportStream json(robot_, {directory_ + "/report.json", false, directory_ + "/report.json", false});
  CertificateStream certificate(directory_ + "/certificate.json", false);
  hooks_.observers = {&thesis, &json, &certificate};
  const certify::VerificationRun run =
      certify::verify(*cell_, program_, kinematics_, setup_.run, hooks_);
  EXPECT_THROW(thesis.finish(run.result), OutputExistsError);
  EXPECT_THROW(json.finish(run.result, *cell_, {}, "now"), OutputExistsError);
  EXPECT_THROW(certificate.finish(run.certificate, nlohmann::json::object()), OutputExistsError);
  for (const char* name : {"out.txt", "report.json", "certificate.json"}) {
    EXPECT_EQ(test::read_text_file(directory_ + "/" + name), "the user's file\n") << name;
  }
  EXPECT_EQ(test::directory_entries(directory_),
            (std::vector<std::string>{"certificate.json", "out.txt", "report.json"}));
}

TEST_F(StreamFailure, AMissingDirectoryIsRefusedBeforeTheRun) {
  try {
    ThesisOutputStream thesis(directory_ + "/missing/out.txt", false, joint_types_of(robot_));
    FAIL() << "a stream into a missing directory was created";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), directory_ + "/missing/out.txt");
    EXPECT_EQ(error.expected(), "a writable output location");
    EXPECT_EQ(error.found(), "creating a scratch file failed: No such file or directory");
  }
  EXPECT_TRUE(test::directory_entries(directory_).empty());
}

TEST(AtomicOutputFile, PiecesAppearOnlyAtCommit) {
  const std::string directory = test::make_temporary_directory("atomic-file");
  {
    AtomicOutputFile output(directory + "/out.txt", false);
    output.write("first ");
    output.write(std::string(3u << 20, 'x'));  // larger than the write buffer
    output.write(" last\n");
    EXPECT_EQ(test::directory_entries(directory).size(), 1u);  // only the temporary
    EXPECT_NE(test::directory_entries(directory).front(), "out.txt");
    output.commit();
  }
  EXPECT_EQ(test::read_text_file(directory + "/out.txt"),
            "first " + std::string(3u << 20, 'x') + " last\n");
  EXPECT_EQ(test::directory_entries(directory), std::vector<std::string>{"out.txt"});
  std::filesystem::remove_all(directory);
}

TEST(AtomicOutputFile, DestroyedWithoutCommitLeavesNothing) {
  const std::string directory = test::make_temporary_directory("atomic-file");
  {
    AtomicOutputFile output(directory + "/out.txt", false);
    output.write(std::string(2u << 20, 'y'));
  }
  EXPECT_TRUE(test::directory_entries(directory).empty());
  std::filesystem::remove_all(directory);
}

TEST(SpillFile, CopiesAnyRangeOfWhatWasAppendedAndHasNoName) {
  const std::string directory = test::make_temporary_directory("spill");
  std::string appended;
  {
    SpillFile spill(directory + "/out.txt");
    for (int i = 0; i < 50'000; ++i) {
      const std::string piece = std::to_string(i) + (i % 7 == 0 ? "\n" : ",");
      spill.append(piece);
      appended += piece;
    }
    EXPECT_EQ(spill.size(), appended.size());
    EXPECT_TRUE(test::directory_entries(directory).empty());  // no name, ever
    AtomicOutputFile output(directory + "/out.txt", false);
    spill.copy_to(output, 10, 200'000);
    spill.copy_to(output);
    EXPECT_THROW(spill.copy_to(output, 5, appended.size() + 1), std::logic_error);
    output.commit();
  }
  EXPECT_EQ(test::read_text_file(directory + "/out.txt"), appended.substr(10, 199'990) + appended);
  EXPECT_EQ(test::directory_entries(directory), std::vector<std::string>{"out.txt"});
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace grpvss::report

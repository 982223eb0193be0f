// Runs the built `grpvss trajectory` (GRPVSS_CLI) on the thesis sample data.
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/data_paths.hpp"

namespace {

using grpvss::test::kIbm7545Data;

struct TrajectoryRun {
  int exit_code = -1;
  std::string out;
};

TrajectoryRun run_trajectory(const std::string& arguments) {
  const std::string command = std::string(GRPVSS_CLI) + " trajectory " + arguments + " 2>/dev/null";
  TrajectoryRun result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string sample_args() {
  return "--robot " + kIbm7545Data + "robot.txt --path " + kIbm7545Data + "path-output-sample.txt";
}

TEST(TrajectoryCli, TextOutputOfTheThesisSample) {
  const TrajectoryRun r = run_trajectory(sample_args() + " --at 1.025,2.503,3.5,4.483");
  EXPECT_EQ(r.exit_code, 1);  // segment 4 is refused: a thesis error
  EXPECT_NE(r.out.find("ENDING JOINT VALUES     61.16    79.90     2.45   171.06"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ENDING JOINT VALUES    166.68    75.16     8.45   -58.16"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ENDING JOINT VALUES     50.00    50.00     5.00    50.00"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("SEGMENT 1       1.05     1.05     0.24     1.05"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("SEGMENT 1      11.20    11.20     1.28    11.20"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("THIS PATH IS NOT QUALIFIED.\nTHE ERROR IS TYPE 3 IN SEGMENT 4\n"
                       "The final position of the motion segment 4 in the path input file is out "
                       "of workspace. This motion segment was not simulated. The simulation "
                       "terminated when this motion segment was encountered."),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("FOR 3 SEGMENTS"), std::string::npos);
}

TEST(TrajectoryCli, JsonDocumentCarriesSegmentsSamplesAndErrors) {
  const TrajectoryRun r = run_trajectory(sample_args() + " --json --step 10 --timing synchronized");
  ASSERT_EQ(r.exit_code, 1);
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["format"], "grpvss-trajectory");
  EXPECT_EQ(doc["timing"], "synchronized");
  ASSERT_EQ(doc["segments"].size(), 3u);
  EXPECT_EQ(doc["segments"][1]["type"], "CP");
  EXPECT_NEAR(doc["segments"][0]["end_joints"][3].get<double>(), 171.06, 0.01);
  EXPECT_NEAR(doc["segments"][2]["end_joints"][2].get<double>(), 5.0, 1e-12);
  const double total = doc["total_cycle_time"];
  EXPECT_DOUBLE_EQ(total, doc["segments"][2]["end_time"].get<double>());
  // --step 10: 0, 10, 20, ... and the end time.
  const auto& samples = doc["samples"];
  ASSERT_EQ(samples.size(), static_cast<std::size_t>(std::floor(total / 10)) + 2);
  EXPECT_EQ(samples[1]["time"], 10.0);
  EXPECT_EQ(samples.back()["time"], total);
  ASSERT_EQ(doc["errors"].size(), 1u);
  EXPECT_EQ(doc["errors"][0]["code"], 3);
  EXPECT_EQ(doc["errors"][0]["segment"], 4);
  EXPECT_EQ(doc["qualified"], false);
}

TEST(TrajectoryCli, PathWithoutErrorsExitsZero) {
  const TrajectoryRun r = run_trajectory("--robot " + kIbm7545Data + "robot.txt --path " + kIbm7545Data + "path.txt --json");
  EXPECT_EQ(r.exit_code, 0);
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["qualified"], true);
  EXPECT_EQ(doc["segments"].size(), 3u);
}

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(TrajectoryCli, UnknownSegmentTypeIsAnInputError) {
  const std::string path = write_temp("grpvss_bad_ind_path.txt", "1\n7\n0.,20.,8.,0.,0.,-1.,30.\n");
  EXPECT_EQ(run_trajectory("--robot " + kIbm7545Data + "robot.txt --path " + path).exit_code, 2);
}

TEST(TrajectoryCli, ZeroLengthCpIsError4) {
  // Home puts the end effector at (25.6, 0, 10.45): a CP "to" that point does not move.
  const std::string path = write_temp("grpvss_zero_cp_path.txt", "1\n3\n25.6,0.,10.45,0.,0.,1.,0.\n");
  const TrajectoryRun r = run_trajectory("--robot " + kIbm7545Data + "robot.txt --path " + path);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("THE ERROR IS TYPE 4 IN SEGMENT 1\nThe movement of the end effector in the CP "
                       "operation of motion segment 1 in the input path file is zero."),
            std::string::npos)
      << r.out;
}

TEST(TrajectoryCli, BadProfileTableAndBadIkAreInputErrors) {
  const std::string table = write_temp("grpvss_bad_table.txt", "joints 4\n0 0 0 0 0 0 0 0 0\n");
  EXPECT_EQ(run_trajectory(sample_args() + " --profile-table " + table).exit_code, 2);
  EXPECT_EQ(run_trajectory(sample_args() + " --ik nonsense").exit_code, 2);
  EXPECT_EQ(run_trajectory(sample_args() + " --timing sometimes").exit_code, 2);
}

TEST(TrajectoryCli, EveryIkChoiceGivesTheSampleEndJoints) {
  for (const std::string& ik : {std::string("ibm7545"), std::string("numeric"),
                                std::string("plugin:") + GRPVSS_IK_PLUGIN_GOOD}) {
    const TrajectoryRun r = run_trajectory(sample_args() + " --json --ik " + ik);
    ASSERT_EQ(r.exit_code, 1) << ik;
    const nlohmann::json doc = nlohmann::json::parse(r.out);
    ASSERT_EQ(doc["segments"].size(), 3u) << ik;
    const double expected[3][4] = {{61.16, 79.90, 2.45, 171.06}, {166.68, 75.16, 8.45, -58.16}, {50, 50, 5, 50}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j)
        EXPECT_NEAR(doc["segments"][i]["end_joints"][j].get<double>(), expected[i][j], 0.01) << ik;
    EXPECT_EQ(doc["errors"][0]["code"], 3) << ik;
  }
  EXPECT_EQ(run_trajectory(sample_args() + " --ik plugin:" + GRPVSS_IK_PLUGIN_WRONG_ABI).exit_code, 2);
}

TEST(TrajectoryCli, BadTimesAreInputErrors) {
  EXPECT_EQ(run_trajectory(sample_args() + " --at 1,-2").exit_code, 2);
  EXPECT_EQ(run_trajectory(sample_args() + " --step 0").exit_code, 2);
  EXPECT_EQ(run_trajectory(sample_args() + " --step 1e-9").exit_code, 2);  // more than 10^6 samples
  EXPECT_EQ(run_trajectory(sample_args() + " --cp-speed 0").exit_code, 2);
  EXPECT_EQ(run_trajectory("--path " + kIbm7545Data + "path.txt").exit_code, 2);  // --robot missing
}

TEST(TrajectoryCli, ProfileTableChangesTheTiming) {
  const TrajectoryRun r = run_trajectory(sample_args() + " --json --profile-table " + std::string(GRPVSS_SOURCE_DIR) +
                    "/data/motion/example-table.txt");
  ASSERT_EQ(r.exit_code, 1);
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  // The example table moves every joint within 8 s, whatever the increment.
  EXPECT_EQ(doc["segments"][0]["cycle_time"], 8.0);
  EXPECT_EQ(doc["segments"][2]["cycle_time"], 8.0);
}

}  // namespace

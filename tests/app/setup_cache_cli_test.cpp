// `grpvss verify` with the set-up cache (docs/cache.md): a warm cache gives byte-identical
// outputs, cache trouble is a one-line note on standard error and never changes the result,
// --no-cache writes nothing, and processes sharing a directory leave one whole entry.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

namespace fs = std::filesystem;

using grpvss::test::kIbm7545Data;

struct CacheCliRun {
  int exit_code = -1;
  std::string err;
};

class SetupCacheCli : public ::testing::Test {
 protected:
  void SetUp() override { directory_ = grpvss::test::make_temporary_directory("cache-cli"); }
  void TearDown() override { fs::remove_all(directory_); }

  // `verify` of the thesis sample writing <tag>.json, <tag>.cert and <tag>.out; `environment`
  // is prepended (e.g. "HOME=... ").
  CacheCliRun verify(const std::string& tag, const std::string& options,
                const std::string& environment = "") const {
    const std::string err = directory_ + "/" + tag + ".stderr";
    const std::string command =
        "cd " + directory_ + " && " + environment + GRPVSS_CLI + " verify --robot " + kIbm7545Data +
        "robot.txt --env " + kIbm7545Data + "environment.txt --path " + kIbm7545Data +
        "path.txt --tolerance 0.5 --json " + tag + ".json --certificate " + tag +
        ".cert --out " + tag + ".out " + options + " > /dev/null 2> " + err;
    const int status = std::system(command.c_str());
    CacheCliRun run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.err = grpvss::test::read_text_file(err);
    return run;
  }
  // The JSON report with its timestamp blanked (the only field that differs between runs).
  std::string report(const std::string& tag) const {
    const std::string text = grpvss::test::read_text_file(directory_ + "/" + tag + ".json");
    return std::regex_replace(text, std::regex("\"generated_at\": \"[^\"]*\""),
                              "\"generated_at\": \"\"");
  }
  std::string file(const std::string& name) const {
    return grpvss::test::read_text_file(directory_ + "/" + name);
  }
  void expect_same_outputs(const std::string& expected, const std::string& actual) const {
    EXPECT_EQ(report(expected), report(actual));
    EXPECT_EQ(file(expected + ".cert"), file(actual + ".cert"));
    EXPECT_EQ(file(expected + ".out"), file(actual + ".out"));
  }
  std::vector<std::string> entries(const std::string& cache) const {
    std::vector<std::string> names;
    if (!fs::exists(cache)) return names;
    for (const auto& entry : fs::directory_iterator(cache)) {
      names.push_back(entry.path().filename().string());
    }
    return names;
  }

  std::string directory_;
};

TEST_F(SetupCacheCli, AWarmCacheGivesByteIdenticalOutputs) {
  const CacheCliRun uncached = verify("uncached", "--no-cache");
  const CacheCliRun cold = verify("cold", "--cache-dir cache");
  const CacheCliRun warm = verify("warm", "--cache-dir cache");
  EXPECT_EQ(uncached.exit_code, 1);  // the sample collides
  EXPECT_EQ(cold.exit_code, 1);
  EXPECT_EQ(warm.exit_code, 1);
  EXPECT_EQ(cold.err, "");
  EXPECT_EQ(warm.err, "");
  expect_same_outputs("uncached", "cold");
  expect_same_outputs("uncached", "warm");
  ASSERT_EQ(entries(directory_ + "/cache").size(), 1u);
  EXPECT_EQ(fs::path(entries(directory_ + "/cache")[0]).extension(), ".offsets");
}

TEST_F(SetupCacheCli, ACorruptEntryIsRebuiltWithANote) {
  verify("cold", "--cache-dir cache");
  const std::string entry = directory_ + "/cache/" + entries(directory_ + "/cache").at(0);
  std::string text = grpvss::test::read_text_file(entry);
  text[text.size() / 2] ^= 1;
  std::ofstream(entry, std::ios::binary | std::ios::trunc) << text;
  const CacheCliRun rebuilt = verify("rebuilt", "--cache-dir cache");
  EXPECT_EQ(rebuilt.exit_code, 1);
  EXPECT_EQ(rebuilt.err, "set-up cache: entry " + std::string("cache/") +
                             entries(directory_ + "/cache").at(0) +
                             " is corrupt (bad checksum); rebuilt\n");
  expect_same_outputs("cold", "rebuilt");
  const CacheCliRun again = verify("again", "--cache-dir cache");
  EXPECT_EQ(again.err, "");  // the rebuilt entry was written back
}

TEST_F(SetupCacheCli, NoCacheWritesNothingAndTheDefaultIsXdgCacheHome) {
  fs::create_directories(directory_ + "/xdg");
  fs::create_directories(directory_ + "/home");
  const std::string environment =
      "XDG_CACHE_HOME=" + directory_ + "/xdg HOME=" + directory_ + "/home ";
  verify("none", "--no-cache", environment);
  EXPECT_TRUE(entries(directory_ + "/xdg").empty());
  EXPECT_TRUE(entries(directory_ + "/home").empty());
  verify("default", "", environment);
  EXPECT_EQ(entries(directory_ + "/xdg/grpvss").size(), 1u);
  EXPECT_TRUE(entries(directory_ + "/home").empty());
  verify("home", "", "env -u XDG_CACHE_HOME HOME=" + directory_ + "/home ");
  EXPECT_EQ(entries(directory_ + "/home/.cache/grpvss").size(), 1u);
}

TEST_F(SetupCacheCli, ADirectoryThatCannotBeCreatedWarnsAndVerifiesAsUsual) {
  std::ofstream(directory_ + "/plain-file") << "x\n";
  verify("uncached", "--no-cache");
  const CacheCliRun run = verify("warned", "--cache-dir plain-file/cache");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err.rfind("set-up cache: cannot use the directory plain-file/cache (", 0), 0u)
      << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1);
  expect_same_outputs("uncached", "warned");
}

TEST_F(SetupCacheCli, ProcessesSharingAnEmptyDirectoryLeaveOneWholeEntry) {
  verify("uncached", "--no-cache");
  std::string command = "cd " + directory_ + " && (";
  for (int i = 0; i < 4; ++i) {
    command += std::string(GRPVSS_CLI) + " verify --robot " + kIbm7545Data + "robot.txt --env " + kIbm7545Data +
               "environment.txt --path " + kIbm7545Data + "path.txt --tolerance 0.5 --json p" +
               std::to_string(i) + ".json --cache-dir shared --quiet & ";
  }
  command += "wait)";
  ASSERT_EQ(std::system(command.c_str()), 0);
  ASSERT_EQ(entries(directory_ + "/shared").size(), 1u);  // no temporary file left
  for (int i = 0; i < 4; ++i) EXPECT_EQ(report("uncached"), report("p" + std::to_string(i)));
  const CacheCliRun warm = verify("warm", "--cache-dir shared");
  EXPECT_EQ(warm.err, "");
  expect_same_outputs("uncached", "warm");
}

}  // namespace

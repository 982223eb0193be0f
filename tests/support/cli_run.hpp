#pragma once
/// \file
/// \brief Runs the built `grpvss` (GRPVSS_CLI) in a folder, standard output and standard error
/// kept apart, for the CLI tests.

#include <string>

namespace grpvss::test {

struct CliRun {
  int exit_code = -1;  ///< -1 when the process did not exit normally
  std::string out;     ///< standard output
  std::string err;     ///< standard error
};

/// `grpvss <arguments>` run by the shell in `directory`; `environment` ("NAME=value ...", shell
/// words) is set for that run only.
CliRun run_cli(const std::string& directory, const std::string& arguments,
               const std::string& environment = "");

/// The N of `steps: N` in verify's summary, -1 when the summary has none.
int summary_steps(const std::string& summary);

}  // namespace grpvss::test

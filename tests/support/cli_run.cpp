#include "support/cli_run.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>

#include "support/text_files.hpp"

namespace grpvss::test {

CliRun run_cli(const std::string& directory, const std::string& arguments,
               const std::string& environment) {
  const std::string out = directory + "/.stdout";
  const std::string err = directory + "/.stderr";
  const std::string prefix = environment.empty() ? "" : environment + " ";
  const int status = std::system(("cd " + directory + " && " + prefix + GRPVSS_CLI + " " + arguments +
                                  " > " + out + " 2> " + err)
                                     .c_str());
  CliRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = read_text_file(out);
  run.err = read_text_file(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return run;
}

int summary_steps(const std::string& summary) {
  const auto at = summary.find("steps: ");
  return at == std::string::npos ? -1 : std::stoi(summary.substr(at + 7));
}

}  // namespace grpvss::test

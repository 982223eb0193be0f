// check_batch_outputs(): every report file of a batch is checked before any job runs.
#include <filesystem>
#include <string>
#include <system_error>
#include <unordered_map>
#include <unordered_set>

#include "grpvss/batch/batch_runner.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/robot_program_file.hpp"

namespace grpvss::batch {
namespace {

// The file a path names, for comparison: symlinks and `..` resolved as far as the path exists
// (as `grpvss verify` compares its outputs, app/output_paths.cpp).
std::string file_identity(const std::string& path) {
  const std::filesystem::path absolute = std::filesystem::absolute(path).lexically_normal();
  std::error_code error;
  std::filesystem::path resolved = std::filesystem::weakly_canonical(absolute, error);
  if (error) resolved = absolute;
  return resolved.string();
}

struct Claim {
  int line = 0;
  std::string key;
};

std::vector<WrittenOutput> outputs_of(const BatchJob& job) {
  std::vector<WrittenOutput> outputs;
  const JobOutputs& out = job.outputs;
  for (const WrittenOutput& output : {WrittenOutput{"output", out.thesis_output},
                                      WrittenOutput{"json", out.json},
                                      WrittenOutput{"html", out.html},
                                      WrittenOutput{"certificate", out.certificate}}) {
    if (!output.path.empty()) outputs.push_back(output);
  }
  return outputs;
}

std::unordered_set<std::string> input_identities(const BatchManifest& manifest) {
  std::unordered_set<std::string> inputs;
  for (const BatchJob& job : manifest.jobs) {
    const VerifyOptions& o = job.options;
    for (const std::string* file :
         {&o.robot_file, &o.environment_file, &o.cell_file, &o.path_file, &o.trajectory_file,
          &o.profile_table}) {
      if (!file->empty()) inputs.insert(file_identity(*file));
    }
    if (o.program_file.empty()) continue;
    for (const std::string& file : io::robot_program_files(o.program_file)) {
      inputs.insert(file_identity(file));
    }
  }
  return inputs;
}

}  // namespace

void check_batch_outputs(const BatchManifest& manifest, const BatchOptions& options) {
  const std::unordered_set<std::string> inputs = input_identities(manifest);
  std::unordered_map<std::string, Claim> claimed;
  for (const BatchJob& job : manifest.jobs) {
    for (const WrittenOutput& output : outputs_of(job)) {
      const std::string where = "`" + output.key + "`: ";
      if (output.key == "html" && !options.html_writer) {
        throw InputError(manifest.file, job.line, where + "a caller that can write the viewer page",
                         output.path);
      }
      const std::string identity = file_identity(output.path);
      const auto [other, inserted] = claimed.emplace(identity, Claim{job.line, output.key});
      if (!inserted) {
        throw InputError(manifest.file, job.line,
                         where + "a file no other output names (line " +
                             std::to_string(other->second.line) + " `" + other->second.key +
                             "` names it)",
                         output.path);
      }
      if (inputs.count(identity) != 0) {
        throw InputError(manifest.file, job.line, where + "a file that is not an input of the batch",
                         output.path);
      }
      if (!options.force && std::filesystem::exists(output.path)) {
        throw InputError(manifest.file, job.line, where + "a file that does not exist yet (or --force)",
                         output.path);
      }
    }
  }
}

}  // namespace grpvss::batch

// `grpvss batch MANIFEST`: many verifications on all cores (docs/batch.md). One JSON line per
// job on stdout in manifest order, a summary on stderr, exit code = the worst job's.
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <thread>

#include <fmt/core.h>

#include "commands.hpp"
#include "grpvss/batch/batch_manifest.hpp"
#include "grpvss/batch/batch_result_json.hpp"
#include "grpvss/batch/batch_runner.hpp"
#include "progress_bar.hpp"
#include "viewer_html_stream.hpp"

namespace grpvss::app {
namespace {

struct BatchArguments {
  std::string manifest;
  unsigned jobs = 0;  ///< 0: std::thread::hardware_concurrency()
  bool force = false;
  bool quiet = false;
};

/// Counts per verdict (and errors), for the summary.
struct BatchTally {
  std::map<std::string, std::size_t> counts;
  int exit_code = kExitOk;

  void add(const batch::JobResult& result) {
    ++counts[result.verdict ? certify::to_string(*result.verdict)
                            : (result.exit_code == kExitInputError ? "INPUT_ERROR" : "INTERNAL_ERROR")];
    exit_code = batch::worst_exit_code(exit_code, result.exit_code);
  }
};

void print_batch_summary(const BatchTally& tally, std::size_t jobs, double seconds) {
  std::string counts;
  for (const auto& [verdict, count] : tally.counts) {
    counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", count, verdict);
  }
  fmt::print(stderr, "batch: {} jobs in {:.1f} s: {}; exit code {}\n", jobs, seconds, counts,
             tally.exit_code);
}

bool needs_viewer(const batch::BatchManifest& manifest) {
  for (const batch::BatchJob& job : manifest.jobs) {
    if (!job.outputs.html.empty()) return true;
  }
  return false;
}

int run_batch_command(const BatchArguments& args) {
  const auto start = std::chrono::steady_clock::now();
  const batch::BatchManifest manifest = batch::read_batch_manifest(args.manifest);
  if (needs_viewer(manifest)) require_viewer_bundle(args.manifest);
  batch::BatchOptions options;
  options.threads = args.jobs > 0 ? args.jobs : std::max(1u, std::thread::hardware_concurrency());
  options.force = args.force;
  options.html_writer = write_viewer_html;
  BatchTally tally;
  {
    ProgressBar bar("batch", !args.quiet && stderr_is_terminal());
    batch::run_batch(
        manifest, options,
        [&](const batch::JobResult& result) {
          fmt::print(stdout, "{}\n", batch::job_result_json(result));
          std::fflush(stdout);  // a reader of the pipe sees each result when it is complete
          tally.add(result);
        },
        [&](std::size_t done, std::size_t total) {
          bar.update(static_cast<double>(done) / static_cast<double>(total));
        });
  }
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  if (!args.quiet) print_batch_summary(tally, manifest.jobs.size(), elapsed.count());
  return tally.exit_code;
}

}  // namespace

void register_batch_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<BatchArguments>();
  auto* command = app.add_subcommand("batch", "Verify many paths on all cores (docs/batch.md)");
  command->add_option("manifest", args->manifest, "Manifest: *.jsonl / *.json (JSON Lines) or *.yaml / *.yml")
      ->required();
  command->add_option("-j,--jobs", args->jobs, "Worker threads (default: the number of cores)")
      ->check(CLI::Range(1u, 1024u));
  command->add_flag("--force", args->force, "Overwrite existing report files");
  command->add_flag("--quiet", args->quiet, "No summary or progress bar on stderr");
  command->callback([args, &exit_code] { exit_code = run_batch_command(*args); });
}

}  // namespace grpvss::app

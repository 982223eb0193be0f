#pragma once
/// \file
/// \brief Runs a manifest's jobs on several threads (docs/batch.md). Each distinct robot
/// cell (robot and environment contents, tolerance, offset shape) is built once and shared
/// read-only between the threads; each robot, environment and profile-table file is read once.
/// Results reach the sink in manifest order, as soon as every earlier job has finished; a
/// job's reports are streamed to their files while it runs, never held in memory.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "grpvss/batch/batch_manifest.hpp"
#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/io/input_warning.hpp"
#include "grpvss/report/atomic_output.hpp"

namespace grpvss::batch {

/// Where a job's error was found: the input file and line (InputError), or the job's manifest
/// line with the message of an internal error.
struct JobError {
  std::string file;
  int line = 0;
  std::string message;  ///< InputError::what() ("FILE:LINE: expected ..."), or the exception's
};

/// The smallest certified clearance of the run, over every link and step.
struct SmallestClearance {
  double clearance = 0.0;  ///< length units; 0 when the expanded robot interferes
  int link = 0;            ///< 0..N
  int obstacle = -1;       ///< index in the environment; -1 when none was near
  int step = 0;
  std::string link_name;      ///< the link's name; empty for a thesis robot
  std::string obstacle_name;  ///< obstacle_label(); empty without names or obstacle
};

/// One written report file: its key in the manifest (`json`, ...) and its path.
struct WrittenOutput {
  std::string key;
  std::string path;
};

/// What one job produced: a verdict, or an error (then no verdict).
struct JobResult {
  std::size_t index = 0;
  int line = 0;
  std::string id;
  std::optional<certify::Verdict> verdict;
  int exit_code = 0;  ///< as `grpvss verify` would return (exit_codes.hpp); 2 bad input, 70 bug
  int steps = 0;
  std::optional<SmallestClearance> smallest_clearance;
  std::vector<WrittenOutput> outputs;
  std::optional<JobError> error;
  /// The inputs' warnings (a cell's: mesh hulls, units, ...), shown once per job.
  std::vector<io::InputWarning> warnings;
};

/// Writes the viewer page (the app's write_viewer_html): the batch stage has no viewer.
using HtmlWriter = std::function<void(const std::string& html_path, bool force,
                                      const std::string& robot_name,
                                      const std::function<void(report::AtomicOutputFile&)>& write_report)>;

struct BatchOptions {
  unsigned threads = 1;  ///< worker threads (>= 1)
  bool force = false;    ///< overwrite existing report files
  /// Needed by jobs with `html`; empty: such a manifest is refused by check_batch_outputs().
  HtmlWriter html_writer;
  /// Jobs started ahead of the oldest unfinished one, per thread: bounds the results held
  /// while a long job delays the printing of later ones.
  std::size_t window_per_thread = 64;
};

/// Called with each result in manifest order, from one thread at a time.
using ResultSink = std::function<void(const JobResult&)>;
/// Called after each job with (jobs done, jobs in total), from one thread at a time.
using ProgressSink = std::function<void(std::size_t done, std::size_t total)>;

/// What run_batch() shared: how many of each it read or built.
struct BatchStatistics {
  std::size_t cells_built = 0;         ///< certify::RobotCell constructions
  std::size_t robots_parsed = 0;       ///< robot files read and parsed
  std::size_t environments_parsed = 0; ///< environment files read and parsed
};

/// \brief Refuses, before any job runs, outputs that two jobs (or two keys of one job) name,
/// outputs that are an input of any job, existing outputs without `force`, and `html` without
/// a writer.
/// \throws InputError(manifest, line of the later job, expected, path).
void check_batch_outputs(const BatchManifest& manifest, const BatchOptions& options);

/// \brief Runs every job (check_batch_outputs() first). A job's bad input or failure becomes
/// its result's error; it never stops the other jobs. Exceptions thrown by the sinks end the
/// batch (after the running jobs finish) and reach the caller.
BatchStatistics run_batch(const BatchManifest& manifest, const BatchOptions& options,
                          const ResultSink& results, const ProgressSink& progress = {});

/// The batch's exit code: the worst of the jobs' by the order 70 > 2 > 1 > 4 > 5 > 3 > 0
/// (internal error, bad input, COLLISION, not qualified, UNDECIDED, WITHIN_TOLERANCE, CLEAR).
int worst_exit_code(int a, int b);

}  // namespace grpvss::batch

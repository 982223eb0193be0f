#include "grpvss/batch/batch_runner.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

#include "batch_job.hpp"
#include "shared_inputs.hpp"

namespace grpvss::batch {
namespace {

/// Hands out job indices to the workers and passes finished results to the sinks in manifest
/// order. A job starts only within `window` of the oldest unprinted one, so the results held
/// back by a long job stay bounded.
class OrderedScheduler {
 public:
  OrderedScheduler(std::size_t total, std::size_t window, const ResultSink& results,
                   const ProgressSink& progress)
      : total_(total), window_(std::max<std::size_t>(window, 1)), results_(results),
        progress_(progress) {}

  /// The next job to run, or nothing when all are taken or the batch stopped.
  std::optional<std::size_t> next_job() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return stopped_ || next_start_ >= total_ || next_start_ < next_emit_ + window_; });
    if (stopped_ || next_start_ >= total_) return std::nullopt;
    return next_start_++;
  }

  /// Stores a finished job and emits every result whose predecessors are all emitted. After
  /// a sink failed, nothing more is emitted (the running jobs just finish).
  void finish(JobResult result) {
    std::lock_guard<std::mutex> lock(mutex_);
    ++done_;
    if (!stopped_) {
      pending_.emplace(result.index, std::move(result));
      try {
        if (progress_) progress_(done_, total_);
        emit_ready();
      } catch (...) {
        error_ = std::current_exception();
        stopped_ = true;
        pending_.clear();
      }
    }
    changed_.notify_all();
  }

  void rethrow_sink_error() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  // Under the lock. A result leaves `pending_` before the sink sees it: a sink that throws
  // has been given each result at most once.
  void emit_ready() {
    for (auto first = pending_.begin(); first != pending_.end() && first->first == next_emit_;
         first = pending_.begin()) {
      const JobResult next = std::move(first->second);
      pending_.erase(first);
      ++next_emit_;
      results_(next);
    }
  }

  std::size_t total_;
  std::size_t window_;
  const ResultSink& results_;
  const ProgressSink& progress_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::size_t, JobResult> pending_;
  std::size_t next_start_ = 0;
  std::size_t next_emit_ = 0;
  std::size_t done_ = 0;
  bool stopped_ = false;
  std::exception_ptr error_;
};

int severity(int exit_code) {
  switch (exit_code) {
    case 0: return 0;   // CLEAR
    case 3: return 1;   // WITHIN_TOLERANCE
    case 5: return 2;   // UNDECIDED
    case 4: return 3;   // not qualified (thesis errors)
    case 1: return 4;   // COLLISION
    case 2: return 5;   // bad input
    default: return 6;  // 70: internal error (and anything unknown)
  }
}

}  // namespace

int worst_exit_code(int a, int b) { return severity(b) > severity(a) ? b : a; }

BatchStatistics run_batch(const BatchManifest& manifest, const BatchOptions& options,
                          const ResultSink& results, const ProgressSink& progress) {
  check_batch_outputs(manifest, options);
  SharedInputs shared;
  const unsigned threads = std::max(1u, options.threads);
  OrderedScheduler scheduler(manifest.jobs.size(), options.window_per_thread * threads, results,
                             progress);
  auto work = [&] {
    while (const std::optional<std::size_t> index = scheduler.next_job()) {
      JobResult result = run_job(manifest.jobs[*index], shared, options);
      if (result.error && result.error->file.empty()) {
        result.error->file = manifest.file;
        result.error->line = result.line;
      }
      scheduler.finish(std::move(result));
    }
  };
  std::vector<std::thread> workers;
  for (unsigned i = 1; i < threads; ++i) workers.emplace_back(work);
  work();
  for (std::thread& worker : workers) worker.join();
  scheduler.rethrow_sink_error();
  return {shared.cells_built(), shared.robots_parsed(), shared.environments_parsed()};
}

}  // namespace grpvss::batch

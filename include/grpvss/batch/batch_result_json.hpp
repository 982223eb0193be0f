#pragma once
/// \file
/// \brief One job's result as one line of JSON (docs/batch.md#results): no timing, so the
/// lines of a batch are the same whatever the number of threads.

#include <string>

#include "grpvss/batch/batch_runner.hpp"

namespace grpvss::batch {

/// The compact JSON object (no newline): index, line, id, verdict, exit_code, steps,
/// smallest_clearance, outputs, error; absent values are null.
std::string job_result_json(const JobResult& result);

}  // namespace grpvss::batch

#pragma once
// One job of a batch: `grpvss verify` on a shared cell, its reports streamed to their files.
#include "grpvss/batch/batch_manifest.hpp"
#include "grpvss/batch/batch_runner.hpp"
#include "shared_inputs.hpp"

namespace grpvss::batch {

/// The exit code `grpvss verify` returns for `verdict` (app/exit_codes.hpp; a test checks that
/// the two agree).
int verdict_exit_code(certify::Verdict verdict);

/// Runs one job; never throws: a bad input or a failure is the result's error.
JobResult run_job(const BatchJob& job, SharedInputs& shared, const BatchOptions& options);

}  // namespace grpvss::batch

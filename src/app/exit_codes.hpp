#pragma once
// The command-line tool's exit codes, and the one for each verdict of `verify`.
#include <stdexcept>

#include "grpvss/evidence/verification_result.hpp"

namespace grpvss::app {

/// Exit codes (docs/user-guide.md#exit-codes), one per verdict so a CI gate can tell them
/// apart: `verify` 0 CLEAR, 1 COLLISION, 2 bad input or usage, 3 WITHIN_TOLERANCE, 4 the path
/// is not qualified (ERROR: thesis errors 1-6, errors 7-9), 5 UNDECIDED; `check-certificate`
/// 0 accepted, 1 rejected, 2 bad input; `trajectory` 0 no error, 1 errors found. 70 (EX_SOFTWARE
/// of sysexits.h) is an internal error: a bug, never a verdict.
constexpr int kExitOk = 0;
constexpr int kExitFinding = 1;  ///< COLLISION, a rejected certificate, trajectory errors
constexpr int kExitInputError = 2;
constexpr int kExitWithinTolerance = 3;
constexpr int kExitNotQualified = 4;
constexpr int kExitUndecided = 5;
constexpr int kExitInternalError = 70;

/// The exit code of `verify` for a run's verdict.
inline int exit_code_of(certify::Verdict verdict) {
  switch (verdict) {
    case certify::Verdict::kClear: return kExitOk;
    case certify::Verdict::kCollision: return kExitFinding;
    case certify::Verdict::kWithinTolerance: return kExitWithinTolerance;
    case certify::Verdict::kError: return kExitNotQualified;
    case certify::Verdict::kUndecided: return kExitUndecided;
  }
  throw std::logic_error("exit_code_of: unknown verdict");
}

}  // namespace grpvss::app

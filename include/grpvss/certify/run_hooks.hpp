#pragma once
/// \file
/// \brief How a caller watches a run: never a choice that changes its result.

#include <functional>
#include <vector>

#include "grpvss/evidence/verification_observer.hpp"

namespace grpvss::certify {

struct RunHooks {
  /// Called with the fraction of the path done (0..1, non-decreasing) after each accepted
  /// step, e.g. for a progress bar.
  std::function<void(double fraction)> progress;
  /// Told every step and certificate step as the run produces them (in this order; not owned,
  /// must outlive verify()). Streaming writers use them (docs/reliability.md#resource-bounds).
  std::vector<VerificationObserver*> observers;
  /// true: VerificationResult::steps and the certificate's per-segment steps hold every step.
  /// false: both stay empty (the observers saw them) and memory does not grow with the number
  /// of steps; everything else in the result is the same.
  bool keep_steps = true;
};

}  // namespace grpvss::certify

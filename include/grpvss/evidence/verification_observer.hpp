#pragma once
/// \file
/// \brief Watching a verification step by step, so that outputs can be written while it runs
/// and a long path needs memory independent of its number of steps (docs/reliability.md#resource-bounds).
///
/// The verifier calls an observer in path order:
///
///     on_step(1), on_step(2), ...                       every accepted step (index >= 1)
///     on_certificate_segment_begin(segment k)           certified mode, each simulated segment
///     on_certificate_step(...) ...                      that segment's certificate steps, complete
///     on_certificate_segment_end()
///
/// interleaved as the run produces them: a step's certificate record is complete only when its
/// transition to the next step was judged, so on_certificate_step for step n comes after
/// on_step(n + 1) (or at the segment's end). The start configuration (step 0) is not passed to
/// on_step: it is in VerificationResult::start. Observers never change the result.

#include "grpvss/evidence/certificate.hpp"
#include "grpvss/evidence/verification_result.hpp"

namespace grpvss::certify {

/// Receives a verification run as it happens; every callback does nothing by default.
/// A callback may throw: the exception ends the verification and reaches verify()'s caller.
class VerificationObserver {
 public:
  virtual ~VerificationObserver() = default;

  /// An accepted step, with the same content as the element of VerificationResult::steps.
  virtual void on_step(const StepRecord& step) { (void)step; }

  /// A segment's certificate starts: `segment` holds number, kind and parameter_end; its
  /// `steps` are empty (they follow through on_certificate_step).
  virtual void on_certificate_segment_begin(const SegmentCertificate& segment) { (void)segment; }

  /// One complete step of the current segment's certificate (its `to_next` filled in, except
  /// for the segment's last step), as it appears in SegmentCertificate::steps.
  virtual void on_certificate_step(const StepCertificate& step) { (void)step; }

  /// The current segment's certificate has no more steps.
  virtual void on_certificate_segment_end() {}
};

}  // namespace grpvss::certify

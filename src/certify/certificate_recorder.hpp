#pragma once
// Writes the certificate of a certified run as the march accepts its steps: per segment the
// steps with every hull's radius and evidence, each completed by its transition to the next
// step (so a step's record is passed on only once that transition was judged).

#include <optional>

#include "accepted_step.hpp"
#include "grpvss/evidence/certificate.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/run_hooks.hpp"
#include "grpvss/evidence/setup.hpp"
#include "grpvss/motion/trajectory.hpp"

namespace grpvss::certify {

class CertificateRecorder {
 public:
  /// The header: what was certified, with which settings and bounds.
  CertificateRecorder(const RobotCell& cell, const RunSettings& settings, const RunHooks& hooks);

  /// A simulated segment starts at `start` (the previous segment's end), step `start_index`.
  void begin_segment(const motion::SegmentTrajectory& segment, double parameter_end,
                     const ProbeResult& start, int start_index);
  void record_step(const AcceptedStep& accepted, int index);
  void end_segment();
  /// The claim: the verdict the certificate supports, with the errors and the collision step.
  Certificate finish(const VerificationResult& result);

 private:
  StepCertificate certificate_step(const ProbeResult& probe, int index, double parameter) const;
  void flush_pending_step();

  const RobotCell& cell_;
  const RunHooks& hooks_;
  Certificate certificate_;
  SegmentCertificate* segment_ = nullptr;  ///< the segment being written
  /// The current segment's last step: complete (and passed on) only once the transition to its
  /// successor was judged, or when the segment ends.
  std::optional<StepCertificate> pending_;
};

}  // namespace grpvss::certify

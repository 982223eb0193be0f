#include "certificate_recorder.hpp"

#include <utility>
#include <vector>

namespace grpvss::certify {
CertificateRecorder::CertificateRecorder(const RobotCell& cell, const RunSettings& settings,
                                         const RunHooks& hooks)
    : cell_(cell), hooks_(hooks) {
  certificate_.mode = ResolutionMode::kCertified;
  certificate_.tolerance = cell.tolerance();
  certificate_.offset_shape = cell.offset_shape();
  certificate_.timing = settings.motion.timing;
  certificate_.cp_speed = settings.motion.cp_speed;
  certificate_.cp_deviation_fraction = settings.cp_model.deviation_fraction;
  certificate_.placement_error = cell.placement_error();
  certificate_.expansion_radius = cell.expansion_radius();
  certificate_.allowed_contacts = cell.allowed_contacts();
  certificate_.names = certificate_names(cell.robot(), cell.environment());
  certificate_.self_collision_pairs = cell.robot().self_collision_pairs;
  certificate_.trajectory_interpolation = settings.trajectory_interpolation;
  certificate_.start = settings.motion.start;
  certificate_.clear_claim = settings.claim;
}

StepCertificate CertificateRecorder::certificate_step(const ProbeResult& probe, int index,
                                                      double parameter) const {
  StepCertificate step;
  step.step = index;
  step.parameter = parameter;
  step.q = probe.q;
  std::vector<int> evidence_count(cell_.hulls().size(), 0);
  for (const PairEvidence& evidence : probe.evidence) ++evidence_count[evidence.hull_index];
  step.hulls.reserve(cell_.hulls().size());
  for (std::size_t i = 0; i < cell_.hulls().size(); ++i) {
    HullRecord hull;
    hull.link = cell_.hulls()[i].link;
    hull.hull = cell_.hulls()[i].hull;
    hull.radius = probe.hulls[i].radius;
    hull.broadphase_margin = probe.hulls[i].broadphase_margin;
    hull.evidence.reserve(static_cast<std::size_t>(evidence_count[i]));
    step.hulls.push_back(std::move(hull));
  }
  for (const PairEvidence& evidence : probe.evidence) {
    step.hulls[evidence.hull_index].evidence.push_back({evidence.obstacle, evidence.expanded,
                                                        evidence.separated, evidence.witness,
                                                        evidence.lower_bound});
  }
  step.self_pairs.reserve(probe.self_pairs.size());
  for (const SelfPairEvidence& pair : probe.self_pairs) {
    step.self_pairs.push_back({pair.separated, pair.witness, pair.lower_bound, pair.revolution_lower_bound});
  }
  return step;
}

void CertificateRecorder::begin_segment(const motion::SegmentTrajectory& segment,
                                        double parameter_end, const ProbeResult& start,
                                        int start_index) {
  SegmentCertificate segment_certificate;
  segment_certificate.number = segment.number;
  segment_certificate.kind = segment.kind;
  segment_certificate.parameter_end = parameter_end;
  for (VerificationObserver* observer : hooks_.observers) {
    observer->on_certificate_segment_begin(segment_certificate);
  }
  certificate_.segments.push_back(std::move(segment_certificate));
  segment_ = &certificate_.segments.back();
  // Every segment's certificate starts with its start configuration (the previous end).
  pending_ = certificate_step(start, start_index, 0.0);
}

void CertificateRecorder::record_step(const AcceptedStep& accepted, int index) {
  // The previous step's record is complete once its transition is known.
  if (pending_) pending_->to_next = accepted.transition;
  flush_pending_step();
  pending_ = certificate_step(accepted.to, index, accepted.parameter);
}

void CertificateRecorder::end_segment() {
  flush_pending_step();
  for (VerificationObserver* observer : hooks_.observers) observer->on_certificate_segment_end();
  segment_ = nullptr;
}

void CertificateRecorder::flush_pending_step() {
  if (!pending_) return;
  for (VerificationObserver* observer : hooks_.observers) observer->on_certificate_step(*pending_);
  if (hooks_.keep_steps) segment_->steps.push_back(std::move(*pending_));
  pending_.reset();
}

Certificate CertificateRecorder::finish(const VerificationResult& result) {
  certificate_.claim = result.verdict;
  certificate_.collision_step = result.collision_step.value_or(0);
  certificate_.errors = result.errors;
  return std::move(certificate_);
}

}  // namespace grpvss::certify

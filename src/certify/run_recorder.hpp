#pragma once
// Records a run as the march accepts its steps: the step records, the per-link clearance
// summaries, the interference episodes, the errors and, at the end, the verdict. Passes every
// step to the observers; keeps the steps only when asked (RunHooks::keep_steps).

#include <string>
#include <vector>

#include "accepted_step.hpp"
#include "interference_episodes.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/run_hooks.hpp"
#include "grpvss/evidence/setup.hpp"
#include "grpvss/evidence/verification_result.hpp"

namespace grpvss::certify {

class RunRecorder {
 public:
  RunRecorder(const RobotCell& cell, const RunSettings& settings, const RunHooks& hooks);

  /// Step 0: the start configuration, evaluated like every step, never passed to observers.
  void record_start(const ProbeResult& start);
  void record_step(const AcceptedStep& accepted);
  /// A thesis error or a new detection at the last step reached.
  void add_error(int code, int segment, std::string message);
  void add_segment(SegmentRecord segment) { result_.segments.push_back(std::move(segment)); }
  /// 0 before the first step.
  int last_step_index() const { return last_step_index_; }
  /// The last step's configuration (the start's before any step).
  const Eigen::VectorXd& last_q() const;
  /// A transition was accepted without proof (the verdict cannot be CLEAR).
  void note_uncertified() { any_uncertified_ = true; }
  const VerificationResult& result() const { return result_; }
  /// Decides the verdict and hands the result over.
  VerificationResult finish();

 private:
  StepRecord make_record(const ProbeResult& probe, int segment, double parameter,
                         double path_time) const;
  void add_transition(const AcceptedStep& accepted, StepRecord& step) const;
  void track_summaries(const StepRecord& step);
  /// Claim `motion`: keeps the first transition whose motion clearance g is below Delta.
  void note_tolerance_shortfall(const AcceptedStep& accepted, int step_index);
  /// The same for the self pairs' gaps (after the hulls of the transition).
  void note_self_pair_shortfall(const AcceptedStep& accepted, int step_index);

  const RobotCell& cell_;
  bool certified_;
  ClearClaim claim_;
  const RunHooks& hooks_;
  VerificationResult result_;
  // What the run needs of the steps so far, in memory independent of their number.
  int last_step_index_ = 0;
  Eigen::VectorXd last_q_;
  bool any_expanded_ = false;
  bool any_uncertified_ = false;
  std::vector<LinkClearanceSummary> clearances_;
  InterferenceEpisodeTracker episodes_;
  SelfCollisionEpisodeTracker self_episodes_;
};

}  // namespace grpvss::certify

#pragma once
// The march: walks each segment of the path from step to step, probing each proposed
// configuration and accepting or shrinking the step. Two labelled step rules
// (docs/verification.md):
//  - CertifiedMarch (default): between consecutive steps every point of every hull moves at
//    most r_k + r_{k+1}, the radii proven obstacle-free at both ends (two-ball cover), with the
//    CP model checked on CP lines; proof: proofs/two-ball-cover.md#corollary-step
//  - ThesisMarch: the thesis's rule at the link-frame origins (thesis_rule.hpp); reproduces
//    the thesis, never certified.
// What a march finds goes to a MarchListener (the verifier records it).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accepted_step.hpp"
#include "cp_model_check.hpp"
#include "cell_probe.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/evidence/setup.hpp"
#include "step_proposal.hpp"
#include "step_axis_radius.hpp"
#include "segment_path.hpp"
#include "thesis_rule.hpp"

namespace grpvss::certify {

/// Receives what a march finds, in path order.
class MarchListener {
 public:
  virtual ~MarchListener() = default;
  virtual void on_accepted_step(const AcceptedStep& step) = 0;
  /// A thesis error or a new detection: the path stops here.
  virtual void on_error(int code, int segment, std::string message) = 0;
  /// A stretch was accepted without proof and without a collision (the verdict cannot be CLEAR).
  virtual void on_uncertified_step() = 0;
  /// The fraction of the current segment done (0..1, non-decreasing).
  virtual void on_progress(int segment, double segment_fraction) = 0;
};

/// What both marches share: the probe, the current and the trial configuration, the budget.
class StepMarch {
 public:
  StepMarch(const RobotCell& cell, const RunSettings& settings, MarchListener& listener);
  virtual ~StepMarch() = default;

  /// Probes the start configuration (with its interference points).
  const ProbeResult& start(const Eigen::VectorXd& q);
  /// Marches one segment from the current configuration. False when the path must stop (the
  /// listener was told the error).
  virtual bool march_segment(const SegmentPath& path, int segment) = 0;
  /// The configuration reached (the last accepted step's probe).
  const ProbeResult& current() const { return current_; }

 protected:
  /// Reports error 9 and returns true once the configuration budget is spent.
  bool budget_exhausted(int segment);
  /// Probes the trial configuration q1 (without interference points: they are exact and costly).
  void probe_trial(const Eigen::VectorXd& q1);
  /// Hands the trial to the listener as the next step (adding its interference points first).
  void accept_trial(int segment, const SegmentPath& path, double s1,
                    const TransitionRecord& transition, bool refinement);
  /// The trial becomes the current configuration at parameter s1 of a segment ending at `end`.
  void advance(int segment, double s1, double end);

  const RobotCell& cell_;
  const RunSettings& settings_;
  MarchListener& listener_;
  CellProbe probe_;
  ProbeResult current_;
  ProbeResult trial_;
  long long probes_ = 0;
};

class CertifiedMarch : public StepMarch {
 public:
  CertifiedMarch(const RobotCell& cell, const RunSettings& settings, MarchListener& listener);
  bool march_segment(const SegmentPath& path, int segment) override;

 private:
  enum class Outcome { kAccept, kRetry, kStop };
  struct Trial {
    double s1 = 0.0;        ///< the trial's end parameter
    double proposed = 0.0;  ///< the proposed step
    bool first = false;     ///< the step's first trial (not a shrunk retry)
  };
  void begin_segment(const SegmentPath& path);
  Trial next_trial(const SegmentPath& path);
  /// `held`: aimed at g >= Delta (claim `motion`) rather than at the nominal rule.
  double predicted_ptp_step(const SegmentPath& path, double max_step, bool held) const;
  /// The PTP proposal of this march; gives up aiming at g >= Delta where it would creep.
  double proposed_ptp_step(const SegmentPath& path, double max_step);
  /// Tells the probe which terms `transition` (just accepted) left loose (step_proposal.hpp).
  void keep_loose_terms(const TransitionRecord& transition);
  Outcome check_cp_model(const SegmentPath& path, const Trial& trial, const Eigen::VectorXd& q1,
                         int segment, double& deviation);
  /// After the trial's transition was judged: the next step's size, or a retry.
  Outcome settle_step(const TransitionRecord& transition, const Trial& trial);
  /// Claim `motion`: the trial judged against g >= Delta (`held`) and the nominal rule.
  Outcome settle_held_step(const TransitionRecord& held, const TransitionRecord& nominal,
                           const Trial& trial);
  void grow_after_certified(const TransitionRecord& transition, double taken);
  Outcome shrink_or_pass_uncertified(const TransitionRecord& transition, const Trial& trial);
  void keep_trend(double taken);

  /// Claim `motion`: the steps aim at g >= Delta (proofs/two-ball-cover.md#lemma-tolerance-along-motion)
  /// until the run can no longer be CLEAR (a step met only the nominal rule at the step floor,
  /// or the expanded robot interferes, or a stretch is unproven); then the nominal rule, as
  /// claim `steps`. Only the steps' sizes depend on it: the recorder decides the verdict.
  bool aims_at_tolerance_ = false;

  CpModelCheck cp_check_;
  std::vector<double> proposal_weights_;  ///< [hull * joints + joint - 1]: M_h's coefficients
  /// The self pairs with a revolution route (hull a has a solid of revolution), in pair order: their
  /// proposal rows follow the pairs' (proofs/two-ball-cover.md#revolution-route).
  std::vector<std::size_t> revolution_pairs_;
  /// The configuration-dependent bound M'_h (proofs/motion-bound.md#lemma-axis-distance-along-step).
  StepAxisRadii step_radii_;
  // Per segment.
  double end_ = 0.0;
  double min_step_ = 0.0;
  double certify_floor_ = 0.0;  ///< below it a failing step stops shrinking (basic resolution)
  double s_ = 0.0;
  double step_ = 0.0;           ///< the next proposal
  bool retrying_ = false;       ///< the proposal is a shrunk retry of a rejected one
  bool basic_resolution_mode_ = false;  ///< after an uncertified step, until one certifies
  double previous_slack_ = 0.0;  ///< of the last accepted certified transition
  /// The radii of the step before current_ in this segment and the parameter step between
  /// them (the trend predicted_ptp_step extrapolates); empty at a segment start.
  std::vector<double> previous_radii_;
  double previous_step_ = 1.0;
  // The proposal's scratch, kept so that a proposal allocates nothing (contents are per call).
  mutable std::vector<ProposalHull> proposal_hulls_;
  mutable std::vector<double> proposal_axis_distances_;
  CpModelFailures model_failures_;  ///< the failed CP-model trials from the current step
  LooseTerms loose_;  ///< of the last accepted transition, for the probes after it
  std::vector<double> loose_hull_radii_;      ///< scratch of keep_loose_terms()
  std::vector<double> loose_pair_distances_;  ///< scratch of keep_loose_terms()
};

class ThesisMarch : public StepMarch {
 public:
  ThesisMarch(const RobotCell& cell, const RunSettings& settings, MarchListener& listener);
  bool march_segment(const SegmentPath& path, int segment) override;

 private:
  ThesisStepRule rule_;
};

}  // namespace grpvss::certify

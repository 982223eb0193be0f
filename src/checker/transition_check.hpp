#pragma once
// One certificate transition: every hull's recorded motion bound must be at least the exact
// joint-sum bound (or, on a CP step, the chord bound), its allowance at most r_k + r_{k+1}, and
// a certified transition's bound within its allowance. Also the motion clearance each link
// provably keeps. proof: proofs/motion-bound.md#lemma-motion-bound,
// proofs/two-ball-cover.md#corollary-step, proofs/two-ball-cover.md#corollary-motion-clearance

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "check_ledger.hpp"
#include "checked_cell.hpp"
#include "claim_facts.hpp"
#include "grpvss/evidence/certificate.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "self_pair_check.hpp"  // SelfPairBounds
#include "vertex_route_check.hpp"

namespace grpvss::certify {

/// Per link: the smallest exact clearance g over the transitions so far, and the step ending it.
using MotionClearances = std::vector<std::optional<std::pair<Rational, int>>>;

class TransitionCheck {
 public:
  TransitionCheck(const CheckedCell& cell, const Certificate& header, CheckLedger& ledger,
                  ClaimFacts& facts, MotionClearances& clearances);

  /// `joint_linear`: a CP step, where the chord bound may stand in for the joint-sum bound.
  void check(const StepCertificate& from, const StepCertificate& to,
             const std::vector<Rational>& radius_from, const std::vector<Rational>& radius_to,
             const std::vector<std::vector<Eigen::Vector3d>>& placed_from,
             const std::vector<std::vector<Eigen::Vector3d>>& placed_to, bool joint_linear,
             const std::string& where, const std::vector<Rational>& joint_variation = {});

  /// Per hull, the motion bound the last check() proved (>= every point's path length over
  /// the transition); nullopt where none was proven, empty when the record was unusable.
  const std::vector<std::optional<Rational>>& hull_bounds() const { return hull_bounds_; }
  /// Per self pair (CheckedCell::self_pairs() order), exact bounds over the last check()'s
  /// transition, by route; empty when the record was unusable:
  /// - relative: hull b's path in link a's frame, the smaller of the joint-sum bound over joints
  ///   a+1..b and M'_{b|a}, both with the joints' variations on a trajectory piece
  ///   (proofs/two-ball-cover.md#relative-frame, proofs/motion-bound.md#lemma-axis-distance-along-step);
  /// - revolution: for a pair whose hull a has a verified solid of revolution, hull b's bound
  ///   with joints 1..a+1 frozen (the same two forms; proofs/two-ball-cover.md#revolution-route);
  const SelfPairBounds& self_pair_bounds() const { return self_pair_bounds_; }
  /// M_v of pair p over the last check()'s transition, exactly, where hull b's own revolute
  /// joint is all that moves it relative to hull a's solid (proofs/two-ball-cover.md#revolution-vertex-bound);
  /// nullopt where the pair has none or a witness is unusable. `from`, `to` and the placed hulls
  /// are that check()'s (its frames and increments are reused); another transition's steps
  /// throw std::logic_error.
  std::optional<Rational> vertex_route_bound(std::size_t p, const StepCertificate& from, const StepCertificate& to,
                                             const std::vector<std::vector<Eigen::Vector3d>>& placed_from,
                                             const std::vector<std::vector<Eigen::Vector3d>>& placed_to);

 private:
  /// Hull b's exact bound with joints 1..frozen held still: the smaller of the joint sum over
  /// joints frozen+1..b and M'_b over the same joints (proofs/two-ball-cover.md#relative-frame,
  /// proofs/motion-bound.md#lemma-axis-distance-along-step).
  Rational frozen_bound(const CheckedHull& hull_b, const std::vector<Rational>& increments,
                        int frozen) const;
  /// The exact joint-sum bound M_h of the hull over the transition; with `joint_variation`
  /// (a joint trajectory's piece: the exact variation bound per joint) in place of |dq|.
  /// proof: proofs/joint-variation.md#theorem-variation-motion-bound
  Rational joint_sum_bound(const CheckedHull& hull, const StepCertificate& from,
                           const StepCertificate& to,
                           const std::vector<Rational>& joint_variation = {}) const;
  /// claimed >= max_v |placed_to[v] - placed_from[v]| + 2 placement_error + P_h / 3, exactly
  /// (proofs/motion-bound.md#lemma-joint-linear-chord).
  bool chord_bound_holds(const CheckedHull& hull, const StepCertificate& from,
                         const StepCertificate& to, const std::vector<Eigen::Vector3d>& placed_from,
                         const std::vector<Eigen::Vector3d>& placed_to, double claimed) const;
  /// The configuration-dependent bound M'_h exactly, from the frames of both ends
  /// (from_frames_, to_frames_) and the exact increments (or variations).
  /// proof: proofs/motion-bound.md#lemma-axis-distance-along-step
  Rational step_axis_bound(const CheckedHull& hull, const std::vector<Rational>& increments) const;
  /// D_jh at one end: |c - o - s z| + placement_error + r_h, exactly (rounded up to a double
  /// only at the root). proof: proofs/motion-bound.md#axis-distance-evaluation
  Rational axis_distance(const kinematics::Workspace& frames, const CheckedHull& hull, int joint) const;
  /// Records the clearance g the hull keeps throughout the transition and returns it.
  Rational keep_motion_clearance(const CheckedHull& hull, const Rational& radius_from,
                                 const Rational& radius_to, const Rational& bound, int to_step);
  /// A CLEAR certificate with claim `motion`: g >= Delta, else a failure naming the step, the
  /// link and the obstacle nearest at either end.
  /// proof: proofs/two-ball-cover.md#lemma-tolerance-along-motion
  void hold_to_tolerance(const Rational& kept, std::size_t hull, const StepCertificate& from,
                         const StepCertificate& to);

  const CheckedCell& cell_;
  const Certificate& header_;
  CheckLedger& ledger_;
  ClaimFacts& facts_;
  MotionClearances& clearances_;
  std::vector<std::optional<Rational>> hull_bounds_;
  SelfPairBounds self_pair_bounds_;
  std::vector<Rational> increments_;  ///< the last check()'s exact joint increments (or variations)
  int checked_from_step_ = -1, checked_to_step_ = -1;  ///< the last check()'s steps
  VertexRouteCheck vertex_route_;
  kinematics::Workspace from_frames_, to_frames_;  ///< this checker's own FK at both ends
};

}  // namespace grpvss::certify

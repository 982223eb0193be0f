#pragma once
/// \file
/// \brief How the certified march proposes its next step. Proposals are never decisions: the
/// probe at a proposal's end and judge_transition decide every step
/// (proofs/two-ball-cover.md#corollary-step); these functions only aim the trials well.

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "grpvss/evidence/certificate.hpp"
#include "loose_terms.hpp"

namespace grpvss::certify {

/// Smallest allowance / bound ratio over the hulls with a positive bound (>= 1 exactly when
/// every hull is certified; +inf when nothing moves).
double transition_slack(const TransitionRecord& transition);

/// How much more room than the limiting term a term must have had to count as loose.
constexpr double kLooseFactor = 1.5;

/// The next transition should pass a loose term with this much room over the last one's bound.
constexpr double kLooseRoom = 1.5;

/// The terms of `transition` far from limiting the step, for the march's next probes
/// (loose_terms.hpp), written into `out`. A hull or self pair is loose when its ratio
/// (allowance - held_margin) / bound is at least kLooseFactor times the smallest ratio (a term
/// that did not move, bound <= 0, always is); a pair held by its revolution route never is (its
/// allowance is not its distance). Its floor keeps the next transition passing it with room:
/// held_margin + kLooseRoom bound - its clearance at the transition's end (`hull_radii`,
/// `pair_distances`: HullState::radius, SelfPairEvidence::distance there).
void loose_terms(const TransitionRecord& transition, double held_margin, const std::vector<double>& hull_radii,
                 const std::vector<double>& pair_distances, LooseTerms& out);

/// The basic resolution next to a collision: every hull whose motion its clearances do not
/// cover moves at most 2 Delta (the thesis's resolution); the others are covered anyway.
/// Smallest max(allowance, 2 Delta) / bound ratio (>= 1 exactly when the rule is met).
double basic_resolution_slack(const TransitionRecord& transition, double two_delta);

/// What a PTP proposal needs to know of one hull at the current step.
struct ProposalHull {
  double radius = 0.0;               ///< r_k (HullState::radius)
  bool expanded_interferes = false;  ///< refining next to a contact: not used for the proposal
  double previous_radius = 0.0;      ///< r_{k-1}, used when the proposal has a trend
  /// Subtracted from r_k + r_far: 2 Delta for a hull the march holds to the claim `motion`
  /// (proofs/two-ball-cover.md#lemma-tolerance-along-motion), else 0.
  double held_margin = 0.0;
  /// Index of another entry that may stand in for this one (a self pair's revolution route,
  /// proofs/two-ball-cover.md#revolution-route): this entry passes when either fits. -1: none.
  int alternative = -1;
  /// Only a stand-in for another entry, never a limit of its own; it fits only with r_k > 0.
  bool alternative_only = false;
};

/// \brief A PTP proposal from the motion bounds alone (no probe): the largest step in
/// (0, max_step] whose bound M_h stays within 0.95 (r_k + r_far - held_margin) for every hull with r_k > 0
/// that is not refining, r_far the far-end radius extrapolated linearly from the previous
/// step (r_k + (r_k - r_{k-1}) step / previous_step) and never assumed below r_k - M_h (which
/// the clearance cannot fall below). Bounds grow with the step (every joint is monotone inside
/// a PTP segment), so a bisection (10 halvings) finds it from below.
/// \param joints_at the segment's joints at parameter s + step
/// \param weights [hull * joints + j]: M_h's coefficient of |dq_j| (R_jh, 1 or 0)
/// \param has_trend whether previous_radius / previous_step are meaningful
/// \param axis_distances when not empty, [hull * joints + j]: D_jh at q_now; the bound is then
///        M'_h's form, sum_j |dq_j| min(w_j, D_j + sum_{m>j} w_m |dq_m|)
///        (proofs/motion-bound.md#lemma-axis-distance-along-step)
double predicted_ptp_step(const std::function<Eigen::VectorXd(double)>& joints_at,
                          const Eigen::VectorXd& q_now, double max_step,
                          const std::vector<double>& weights,
                          const std::vector<ProposalHull>& hulls, bool has_trend,
                          double previous_step, const std::vector<double>& axis_distances = {});

/// \brief CP steps against the joint-path model (proofs/cp-joint-path.md#model): a smooth
/// joint-linear path strays from the line by about the square of the step. A trial that failed
/// the model by `deviation` (> 1, a multiple of the allowed deviation) is retried at this
/// fraction of its length: 0.9 / sqrt(deviation) just inside the model for deviation < 4,
/// halved above (a jump's deviation does not follow the square law), halved for NaN.
double cp_model_retry_fraction(double deviation);

/// \brief After an accepted CP step whose model deviation was `deviation` (<= 1), the next
/// proposal is at most this multiple of that step (>= 1; +inf for a zero deviation).
double cp_model_growth_cap(double deviation);

/// \brief The failed CP-model trials from one step start, to tell a joint jump from a step that
/// is merely too long: a shorter trial from the same start whose deviation did not drop below
/// half of the previous one's does not follow the square law.
class CpModelFailures {
 public:
  /// Forgets every failure (a new segment).
  void reset() { from_ = -1.0; }
  /// Records a failed trial [s, s + length] and returns whether it kept the deviation of the
  /// previous failed trial from s.
  bool record(double s, double length, double deviation);

 private:
  double from_ = -1.0;
  double length_ = 0.0;
  double deviation_ = 0.0;
};

}  // namespace grpvss::certify

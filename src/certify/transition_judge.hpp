#pragma once
// The certified step rule's decision on one transition between two probed configurations
// (proofs/two-ball-cover.md#corollary-step): every hull's motion bound against the allowance
// its radii at both ends give.

#include "cell_probe.hpp"
#include "step_axis_radius.hpp"
#include "grpvss/evidence/certificate.hpp"
#include "grpvss/certify/robot_cell.hpp"

namespace grpvss::certify {

/// r_k + r_{k+1} rounded down, so that "bound <= allowance" in double implies it exactly.
double allowance_down(double radius_k, double radius_k1);

/// \brief Every hull's motion bound M_h, allowance r_k + r_{k+1} and governing term, and whether
/// every bound is within its allowance.
/// `joint_linear`: the joints move along the straight line between the two configurations (a
/// certified CP step, proofs/cp-joint-path.md#model), so the chord bound may be used.
/// `joint_variation`: when not empty, per joint a bound of the joints' total variation over
/// the step (a trajectory piece, possibly non-monotone), used in M_h instead of |dq|
/// (proofs/joint-variation.md#theorem-variation-motion-bound).
/// `step_radii`: when given, M_h may be the configuration-dependent M'_h
/// (proofs/motion-bound.md#lemma-axis-distance-along-step).
TransitionRecord judge_transition(const RobotCell& cell, const ProbeResult& from,
                                  const ProbeResult& to, bool cut_by_segment_end,
                                  bool joint_linear,
                                  const Eigen::VectorXd& joint_variation = Eigen::VectorXd(),
                                  const StepAxisRadii* step_radii = nullptr);

/// \brief Appends to `record` (its hull bounds filled) every self pair's M_a + M_b and
/// d_k + d_{k+1}, and uncertifies it unless M_a + M_b < d_k + d_{k+1} for every pair.
/// proof: proofs/two-ball-cover.md#lemma-relative-motion
/// With `axis` (the step's axis distances at both ends), the relative bound may be M'_{b|a}
/// (proofs/motion-bound.md#lemma-axis-distance-along-step, joints 1..a frozen).
/// `dq`: per joint the step's increment, or on a trajectory piece a bound of its variation
/// (proofs/joint-variation.md#theorem-variation-motion-bound), as for the hulls' bounds.
void judge_self_pairs(const RobotCell& cell, const ProbeResult& from, const ProbeResult& to,
                      const Eigen::VectorXd& dq, TransitionRecord& record,
                      const StepAxisDistances* axis = nullptr);

/// \brief The revolution route's bound of pair `pair` (hull a with a solid of revolution about joint a+1):
/// hull b's motion with joints 1..a+1 frozen, rounded up.
/// proof: proofs/two-ball-cover.md#revolution-route
double revolution_motion_bound(const RobotCell& cell, const SelfPairHulls& pair,
                               const Eigen::VectorXd& dq, const StepAxisDistances* axis);
/// \brief The revolution route weighed vertex by vertex (pair index `pair`, with has_vertex_route): M_v
/// rounded up from both ends' terms, +inf when either end proves no route distance.
/// proof: proofs/two-ball-cover.md#revolution-vertex-bound
double vertex_route_motion_bound(const RobotCell& cell, std::size_t pair, const ProbeResult& from,
                                 const ProbeResult& to, const StepAxisDistances& axis);
/// Whether the record's bound and allowance of self pair `pair` are the revolution route's.
bool by_revolution(const TransitionRecord& record, std::size_t pair);
/// The pair's distance lower bound the route rests on: d, or the solid's d.
double route_distance(const SelfPairEvidence& evidence, bool revolution);
/// max(r_k + r_{k+1} - 2 Delta, max(r_k, r_{k+1}) - Delta), each side rounded down: a motion
/// bound at most this keeps g >= Delta. proof: proofs/two-ball-cover.md#lemma-tolerance-along-motion
double held_allowance_down(double radius_k, double radius_k1, double tolerance);

/// \brief Claim `motion` (docs/verification.md#claim): the transition as the step decision aims
/// at it. Every hull whose expanded hull is clear at both ends is held to g >= Delta, i.e. to
/// the allowance held_allowance_down(r_k, r_{k+1}, Delta), and every self pair to a gap of
/// Delta, i.e. its relative bound to held_allowance_down(d_k, d_{k+1}, Delta); the result
/// is certified when `nominal` is and every held bound is within. The allowances recorded in the
/// certificate stay r_k + r_{k+1}, d_k + d_{k+1} (`nominal`); the recorder and the checker decide
/// g >= Delta. proof: proofs/two-ball-cover.md#lemma-tolerance-along-motion,
/// proofs/two-ball-cover.md#corollary-self-tolerance-along-motion
TransitionRecord held_to_tolerance(const TransitionRecord& nominal, const ProbeResult& from,
                                   const ProbeResult& to, double tolerance);

/// \brief The transition as the step decision sees it inside a collision: a hull that collides
/// at an end of the step is held only against the obstacles it does not collide with
/// (radius_beside_collisions). The recorded allowances stay r_k + r_{k+1}, which the checker
/// verifies. docs/verification.md#steps-through-a-collision
TransitionRecord beside_collisions(const TransitionRecord& transition, const ProbeResult& from,
                                   const ProbeResult& to);

}  // namespace grpvss::certify

#include "step_march.hpp"

#include <algorithm>
#include <utility>

#include <fmt/core.h>

#include "grpvss/certify/verifier.hpp"
#include "grpvss/motion/thesis_error.hpp"
#include "transition_judge.hpp"

namespace grpvss::certify {

// ---- StepMarch: what both rules share ---------------------------------------------------

StepMarch::StepMarch(const RobotCell& cell, const RunSettings& settings, MarchListener& listener)
    : cell_(cell), settings_(settings), listener_(listener), probe_(cell) {}

const ProbeResult& StepMarch::start(const Eigen::VectorXd& q) {
  probe_.probe(q, /*with_points=*/true, current_);
  ++probes_;
  return current_;
}

bool StepMarch::budget_exhausted(int segment) {
  if (probes_ < settings_.limits.max_probes) return false;
  listener_.on_error(kErrorProbeLimit, segment,
                     "THE CONFIGURATION BUDGET WAS EXHAUSTED IN MOTION SEGMENT " +
                         std::to_string(segment));
  return true;
}

void StepMarch::probe_trial(const Eigen::VectorXd& q1) {
  ++probes_;
  probe_.probe(q1, /*with_points=*/false, trial_);
}

void StepMarch::accept_trial(int segment, const SegmentPath& path, double s1,
                             const TransitionRecord& transition, bool refinement) {
  // Only the points are added: the radii and evidence the transition was judged on stay.
  if (trial_.any_expanded_interference) probe_.add_interference_points(trial_);
  listener_.on_accepted_step({current_, trial_, transition, segment, s1, path.time_at(s1), refinement});
}

void StepMarch::advance(int segment, double s1, double end) {
  std::swap(current_, trial_);
  listener_.on_progress(segment, s1 / end);
}

// ---- CertifiedMarch ----------------------------------------------------------------------

CertifiedMarch::CertifiedMarch(const RobotCell& cell, const RunSettings& settings,
                               MarchListener& listener)
    : StepMarch(cell, settings, listener),
      aims_at_tolerance_(settings.claim == ClearClaim::kMotion),
      cp_check_(cell, settings.cp_model),
      step_radii_(cell) {
  const RobotModel& robot = cell.robot();
  for (const LinkHull& hull : cell.hulls()) {
    for (int joint = 1; joint <= robot.joint_count(); ++joint) {
      proposal_weights_.push_back(cell.radii().motion_bound_weight(hull.link, hull.hull, joint));
    }
  }
  // A self pair proposes like one more hull: its relative bound (hull b in link a's frame,
  // joints a+1..b; transition_judge.cpp), radius its distance d.
  const auto joints = static_cast<std::size_t>(robot.joint_count());
  for (const SelfPairHulls& pair : cell.self_pairs()) {
    const LinkHull& a = cell.hulls()[static_cast<std::size_t>(pair.a)];
    for (std::size_t j = 0; j < joints; ++j) {
      const bool moves_b_in_a = static_cast<int>(j) >= a.link;  // joint j + 1 > link a
      proposal_weights_.push_back(
          moves_b_in_a ? proposal_weights_[static_cast<std::size_t>(pair.b) * joints + j] : 0.0);
    }
  }
  // The revolution route of a pair: hull b with joints 1..a+1 frozen (transition_judge.cpp).
  for (std::size_t p = 0; p < cell.self_pairs().size(); ++p) {
    const SelfPairHulls& pair = cell.self_pairs()[p];
    const LinkHull& a = cell.hulls()[static_cast<std::size_t>(pair.a)];
    if (!a.revolution_L) continue;
    revolution_pairs_.push_back(p);
    for (std::size_t j = 0; j < joints; ++j) {
      const bool moves_b_about_the_solid = static_cast<int>(j) > a.link;  // joint j + 1 > a + 1
      proposal_weights_.push_back(moves_b_about_the_solid
                                      ? proposal_weights_[static_cast<std::size_t>(pair.b) * joints + j]
                                      : 0.0);
    }
  }
}

void CertifiedMarch::begin_segment(const SegmentPath& path) {
  end_ = path.parameter_end();
  min_step_ = std::max(end_ * settings_.limits.min_step_fraction, 1e-300);
  certify_floor_ = std::max(end_ * settings_.limits.certify_floor_fraction, min_step_);
  basic_resolution_mode_ = false;
  previous_radii_.clear();
  s_ = 0.0;
  step_ = end_;
  previous_slack_ = 0.0;
  model_failures_.reset();
  retrying_ = false;
}

// Returns false when the path must stop (the listener was told the error).
bool CertifiedMarch::march_segment(const SegmentPath& path, int segment) {
  begin_segment(path);
  while (s_ < end_) {
    if (budget_exhausted(segment)) return false;
    const Trial trial = next_trial(path);
    const std::optional<Eigen::VectorXd> q1 = path.q_at(trial.s1, current_.q);
    if (!q1 || (trial.first && path.is_cp() &&
                cp_check_.unreachable_next_to_a_limit(path, s_, current_.q))) {
      listener_.on_error(5, segment, motion::thesis_error_text(5, segment));
      return false;
    }
    double deviation = 0.0;  ///< of the CP model over this step
    if (path.is_cp()) {
      const Outcome cp = check_cp_model(path, trial, *q1, segment, deviation);
      if (cp == Outcome::kRetry) continue;
      if (cp == Outcome::kStop) return false;
    }
    // A retry is probed in full: a loose term short of its floor may be what failed the trial.
    if (!trial.first) probe_.set_loose_terms(LooseTerms{});
    probe_trial(*q1);
    step_radii_.keep(trial_);  // evaluated once per configuration: the proposal reuses them
    const TransitionRecord transition =
        judge_transition(cell_, current_, trial_, trial.s1 >= end_, path.is_cp(),
                         path.joint_variation(s_, trial.s1), &step_radii_);
    if (trial_.any_expanded_interference) aims_at_tolerance_ = false;  // CLEAR is out of reach
    const Outcome settled =
        aims_at_tolerance_
            ? settle_held_step(held_to_tolerance(transition, current_, trial_, cell_.tolerance()),
                               transition, trial)
            : settle_step(transition, trial);
    if (settled == Outcome::kRetry) continue;
    const double taken = trial.s1 - s_;
    // Nor should the next CP proposal outgrow the model (the square law again).
    step_ = std::min(step_, taken * cp_model_growth_cap(deviation));
    const bool refinement_region =
        trial_.any_expanded_interference || current_.any_expanded_interference;
    accept_trial(segment, path, trial.s1, transition, refinement_region);
    keep_loose_terms(transition);
    retrying_ = false;
    if (!transition.certified) previous_slack_ = 0.0;
    keep_trend(taken);
    s_ = trial.s1;
    advance(segment, trial.s1, end_);
  }
  return true;
}

// The terms the accepted transition left loose, for the probes of the next step; its end is the
// trial just accepted.
void CertifiedMarch::keep_loose_terms(const TransitionRecord& transition) {
  loose_hull_radii_.resize(trial_.hulls.size());
  for (std::size_t i = 0; i < trial_.hulls.size(); ++i) loose_hull_radii_[i] = trial_.hulls[i].radius;
  loose_pair_distances_.resize(trial_.self_pairs.size());
  for (std::size_t p = 0; p < trial_.self_pairs.size(); ++p) loose_pair_distances_[p] = trial_.self_pairs[p].distance;
  loose_terms(transition, aims_at_tolerance_ ? 2.0 * cell_.tolerance() : 0.0, loose_hull_radii_,
              loose_pair_distances_, loose_);
  probe_.set_loose_terms(loose_);
}

CertifiedMarch::Trial CertifiedMarch::next_trial(const SegmentPath& path) {
  // Floors are compared with the proposed step, not with s1 - s: rounding can make the
  // difference a hair larger than the step and a floor never reached.
  if (!path.is_cp() && !basic_resolution_mode_ && !retrying_) {
    // After a step with ample slack (receding from every obstacle) the growth rule's proposal
    // is kept: the linear extrapolation underestimates a growing clearance.
    const double predicted = proposed_ptp_step(path, std::min(step_, end_ - s_));
    step_ = std::max({predicted, previous_slack_ >= 1.5 ? step_ : 0.0,
                      std::min(certify_floor_, end_ - s_)});
  }
  Trial trial;
  trial.first = !retrying_;
  retrying_ = true;
  trial.proposed = step_;
  trial.s1 = std::min(end_, s_ + step_);
  // A sliver left before the segment's end would cost a probe of its own: take it now (the
  // transition still decides). Only on a first trial: a shrunk retry must not be stretched
  // back to the same rejected end.
  if (trial.first && end_ - trial.s1 < 0.25 * step_) trial.s1 = end_;
  return trial;
}

// Aiming at g >= Delta where a hull's clearance beyond Delta is a small fraction of its
// clearance would creep at a few percent of the nominal step (or converge on the place where
// the clearance drops below Delta): there the run gives up CLEAR with claim `motion` (at best
// WITHIN_TOLERANCE, decided by the recorder) and steps on the nominal rule.
double CertifiedMarch::proposed_ptp_step(const SegmentPath& path, double max_step) {
  if (!aims_at_tolerance_) return predicted_ptp_step(path, max_step, false);
  const double held = predicted_ptp_step(path, max_step, true);
  // The nominal step is at most max_step, so this is the test below without computing it.
  if (held >= max_step / 16.0) return held;
  const double nominal = predicted_ptp_step(path, max_step, false);
  if (held >= nominal / 16.0) return held;
  aims_at_tolerance_ = false;
  return nominal;
}

// The PTP proposal of step_proposal.hpp, from this march's state.
double CertifiedMarch::predicted_ptp_step(const SegmentPath& path, double max_step,
                                          bool held) const {
  const std::size_t hull_count = cell_.hulls().size();
  const std::size_t pair_count = current_.self_pairs.size();
  const bool has_trend = previous_radii_.size() == hull_count + pair_count + revolution_pairs_.size();
  std::vector<ProposalHull>& hulls = proposal_hulls_;
  hulls.assign(hull_count + pair_count + revolution_pairs_.size(), ProposalHull{});
  for (std::size_t i = 0; i < hull_count; ++i) {
    hulls[i].radius = current_.hulls[i].radius;
    hulls[i].expanded_interferes = current_.hulls[i].expanded_interferes;
    hulls[i].held_margin = held ? 2.0 * cell_.tolerance() : 0.0;
  }
  for (std::size_t p = 0; p < pair_count; ++p) {
    hulls[hull_count + p].radius = current_.self_pairs[p].distance;
    hulls[hull_count + p].held_margin = held ? 2.0 * cell_.tolerance() : 0.0;
  }
  for (std::size_t r = 0; r < revolution_pairs_.size(); ++r) {
    const std::size_t route = hull_count + pair_count + r;
    hulls[route].radius = current_.self_pairs[revolution_pairs_[r]].revolution_distance;
    hulls[route].held_margin = held ? 2.0 * cell_.tolerance() : 0.0;
    hulls[route].alternative_only = true;
    hulls[hull_count + revolution_pairs_[r]].alternative = static_cast<int>(route);
  }
  for (std::size_t i = 0; has_trend && i < hulls.size(); ++i) {
    hulls[i].previous_radius = previous_radii_[i];
  }
  const double s = s_;
  const Eigen::VectorXd& q = current_.q;
  // Weighted by where the hulls are now, not by the worst configuration (M'_h's form).
  std::vector<double>& distances = proposal_axis_distances_;
  step_radii_.proposal_axis_distances(current_, distances);
  // PTP: the profile; a trajectory piece: its interpolation (the transition still decides).
  return certify::predicted_ptp_step([&](double candidate) { return *path.q_at(s + candidate, q); },
                                     current_.q, max_step, proposal_weights_, hulls, has_trend,
                                     previous_step_, distances);
}

namespace {

// Which joint's branch flips: the one that changes most between the two close points.
std::string jumping_joint_text(const RobotModel& robot, const Eigen::VectorXd& q0,
                               const Eigen::VectorXd& q1, double s0, double s1) {
  Eigen::Index j = 0;
  (q1 - q0).cwiseAbs().maxCoeff(&j);
  const Joint& joint = robot.joints[static_cast<std::size_t>(j)];
  const bool revolute = joint.type == JointType::kRevolute;
  const double change = (q1[j] - q0[j]) * (revolute ? 180.0 / 3.14159265358979323846 : 1.0);
  return fmt::format(": JOINT {}{} CHANGES BY {:.2f} {} BETWEEN PATH PARAMETERS {:.6g} AND {:.6g}",
                     j + 1, joint.name.empty() ? "" : " (" + joint.name + ")", change,
                     revolute ? "DEG" : "LENGTH UNITS", s0, s1);
}

}  // namespace

// The CP model (proofs/cp-joint-path.md#model): a step that fails it is subdivided; a jump that
// survives subdivision is error 7; a singular end configuration is error 8.
CertifiedMarch::Outcome CertifiedMarch::check_cp_model(const SegmentPath& path, const Trial& trial,
                                                       const Eigen::VectorXd& q1, int segment,
                                                       double& deviation) {
  deviation = cp_check_.deviation(path, s_, current_.q, trial.s1, q1);
  if (!(deviation <= 1.0)) {
    if (trial.proposed > min_step_) {
      step_ = (trial.s1 - s_) * cp_model_retry_fraction(deviation);
      // A step far shorter than the last one this segment accepted failing too, or a
      // deviation that did not shrink with the step, points at a joint jump ahead: halving
      // and growing again would crowd the report with proven steps creeping up to it. Locate
      // it (IK and FK only, no probe) and aim just before. (previous_radii_ is empty until
      // this segment accepts a step; previous_step_ is that step's length.)
      const bool deviation_kept = model_failures_.record(s_, trial.s1 - s_, deviation);
      if (!previous_radii_.empty() && (trial.s1 - s_ < 0.25 * previous_step_ || deviation_kept)) {
        step_ = cp_check_.reach(path, s_, current_.q, trial.s1, min_step_);
        if (!(step_ > min_step_)) step_ = 0.0;  // fails at any step: the jump is here
      }
      if (step_ > 0.0) return Outcome::kRetry;
    }
    listener_.on_error(kErrorCpJointJump, segment,
                       "THE JOINTS JUMP (IK BRANCH CHANGE) BETWEEN TWO CLOSE POINTS OF THE CP LINE "
                       "IN MOTION SEGMENT " + std::to_string(segment) +
                           jumping_joint_text(cell_.robot(), current_.q, q1, s_, trial.s1));
    return Outcome::kStop;
  }
  if (cp_check_.near_singularity(q1)) {
    listener_.on_error(kErrorCpSingularity, segment,
                       "THE CP LINE PASSES A SINGULAR CONFIGURATION IN MOTION SEGMENT " +
                           std::to_string(segment));
    return Outcome::kStop;
  }
  return Outcome::kAccept;
}

CertifiedMarch::Outcome CertifiedMarch::settle_step(const TransitionRecord& transition,
                                                    const Trial& trial) {
  if (transition.certified) {
    grow_after_certified(transition, trial.s1 - s_);
    basic_resolution_mode_ = false;
    return Outcome::kAccept;
  }
  return shrink_or_pass_uncertified(transition, trial);
}

// Claim `motion`: a step meeting g >= Delta is accepted as a certified one; one meeting only
// the nominal rule is shrunk like a failing step down to the certified step floor, where it is
// accepted on the nominal rule (the run is then at best WITHIN_TOLERANCE, and the march stops
// aiming at g >= Delta). A step failing the nominal rule goes the nominal way.
CertifiedMarch::Outcome CertifiedMarch::settle_held_step(const TransitionRecord& held,
                                                         const TransitionRecord& nominal,
                                                         const Trial& trial) {
  if (held.certified) return settle_step(held, trial);
  if (!nominal.certified) return settle_step(nominal, trial);
  const double taken = trial.s1 - s_;
  if (!basic_resolution_mode_ && trial.proposed > certify_floor_) {
    step_ = std::max(certify_floor_, taken * std::clamp(0.9 * transition_slack(held), 0.05, 0.9));
    return Outcome::kRetry;
  }
  aims_at_tolerance_ = false;
  return settle_step(nominal, trial);
}

// Accepted: the next proposal grows with the slack this step left.
void CertifiedMarch::grow_after_certified(const TransitionRecord& transition, double taken) {
  previous_slack_ = transition_slack(transition);
  step_ = taken * std::clamp(0.9 * previous_slack_, 1.0, 4.0);
  if (trial_.any_expanded_interference) {
    // Refining next to a contact, the proven steps shrink geometrically towards the contact
    // time (Zeno: each allowance is the raw clearance left). The next trial aims at the basic
    // resolution instead (at most 4x this step): one past the contact finds the COLLISION at
    // once; one that is not proven is cut back as before.
    step_ = std::max(step_, taken * std::clamp(0.95 * basic_resolution_slack(
                                                          transition, 2.0 * cell_.tolerance()),
                                               1.0, 4.0));
  }
}

// Nothing to certify next to a collision, and near a first contact the proven steps shrink
// geometrically towards the contact time without ever passing it (Zeno). In both cases, and
// once the certified step floor is reached, move on at the thesis's basic resolution (every
// point at most 2D per step): the report covers the motion, a step past the contact finds the
// COLLISION, and a stretch that is neither proven nor colliding makes the verdict UNDECIDED.
// (Hulls whose clearances cover their motion are not held to 2D: basic_resolution_slack; a
// pair colliding at an end of the step is not held at all: beside_collisions.)
CertifiedMarch::Outcome CertifiedMarch::shrink_or_pass_uncertified(
    const TransitionRecord& transition, const Trial& trial) {
  const double taken = trial.s1 - s_;
  const bool collision_at_an_end = current_.any_collision || trial_.any_collision;
  const bool basic_mode =
      collision_at_an_end || basic_resolution_mode_ || trial.proposed <= certify_floor_;
  if (!basic_mode) {
    step_ = std::max(certify_floor_,
                     taken * std::clamp(0.9 * transition_slack(transition), 0.05, 0.9));
    return Outcome::kRetry;
  }
  const double basic_slack = basic_resolution_slack(
      collision_at_an_end ? beside_collisions(transition, current_, trial_) : transition,
      2.0 * cell_.tolerance());
  if (!(basic_slack >= 1.0) && trial.proposed > min_step_) {
    step_ = std::max(min_step_, taken * std::clamp(0.95 * basic_slack, 0.1, 0.9));
    return Outcome::kRetry;
  }
  if (!collision_at_an_end) listener_.on_uncertified_step();
  basic_resolution_mode_ = true;
  aims_at_tolerance_ = false;  // CLEAR is out of reach
  // The bounds are nearly linear in the step: aim just below the resolution.
  step_ = taken * std::clamp(0.95 * basic_slack, 1.0, 4.0);
  return Outcome::kAccept;
}

void CertifiedMarch::keep_trend(double taken) {
  previous_radii_.clear();
  for (const HullState& hull : current_.hulls) previous_radii_.push_back(hull.radius);
  for (const SelfPairEvidence& pair : current_.self_pairs) previous_radii_.push_back(pair.distance);
  for (const std::size_t p : revolution_pairs_) {
    previous_radii_.push_back(current_.self_pairs[p].revolution_distance);
  }
  previous_step_ = taken;
}

// ---- ThesisMarch -------------------------------------------------------------------------

ThesisMarch::ThesisMarch(const RobotCell& cell, const RunSettings& settings,
                         MarchListener& listener)
    : StepMarch(cell, settings, listener), rule_(cell, settings.limits.min_step_fraction) {}

// Thesis Eq. 4-13..4-16 (PTP) and Figure 16 (CP) at the link-frame origins; every step is
// accepted, none is certified.
bool ThesisMarch::march_segment(const SegmentPath& path, int segment) {
  const double end = path.parameter_end();
  double s = 0.0;
  double step = end;
  while (s < end) {
    if (budget_exhausted(segment)) return false;
    const double s1 = rule_.next_parameter(path, s, current_.q, step);
    const std::optional<Eigen::VectorXd> q1 = path.q_at(s1, current_.q);
    if (!q1) {
      listener_.on_error(5, segment, motion::thesis_error_text(5, segment));
      return false;
    }
    probe_trial(*q1);
    // Judged for the record only: the bounds and allowances are reported beside the rule.
    TransitionRecord transition = judge_transition(cell_, current_, trial_, s1 >= end, false);
    std::fill(transition.governing.begin(), transition.governing.end(), GoverningTerm::kThesisRule);
    transition.certified = false;
    accept_trial(segment, path, s1, transition, /*refinement=*/false);
    step = s1 - s;
    s = s1;
    advance(segment, s1, end);
  }
  return true;
}

}  // namespace grpvss::certify

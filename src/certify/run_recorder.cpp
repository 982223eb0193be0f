#include "run_recorder.hpp"

#include <algorithm>
#include <limits>

#include "motion_clearance.hpp"
#include "transition_judge.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"

namespace grpvss::certify {
namespace {

constexpr double kPlusInfinity = std::numeric_limits<double>::infinity();

}  // namespace

RunRecorder::RunRecorder(const RobotCell& cell, const RunSettings& settings, const RunHooks& hooks)
    : cell_(cell), certified_(settings.mode == ResolutionMode::kCertified), claim_(settings.claim),
      hooks_(hooks) {
  result_.tolerance = cell.tolerance();
  result_.claim = settings.claim;
  result_.mode = settings.mode;
  result_.path_file_label = settings.path_label;
  result_.motion_model = settings.motion_model;
  for (int link = 0; link < static_cast<int>(cell.robot().links.size()); ++link) {
    LinkClearanceSummary summary;
    summary.link = link;
    summary.min_clearance = kPlusInfinity;
    clearances_.push_back(summary);
  }
}

StepRecord RunRecorder::make_record(const ProbeResult& probe, int segment, double parameter,
                                    double path_time) const {
  StepRecord step;
  step.segment = segment;
  step.path_time = path_time;
  step.segment_parameter = parameter;
  step.q = probe.q;
  step.end_effector_W = kinematics::end_effector_pose(cell_.chain(), probe.q).translation();
  step.links.assign(cell_.robot().links.size(), LinkStepRecord{});
  for (int link = 0; link < static_cast<int>(cell_.robot().links.size()); ++link) {
    step.links[link].clearance = probe.link_radius(cell_, link);
    step.links[link].nearest_obstacle = probe.link_nearest_obstacle(cell_, link);
  }
  step.interference_points = probe.interference_points;
  step.contacts = interfering_pairs(cell_, probe);
  step.self_contacts = self_contacts(cell_, probe);
  step.expanded_interferes = probe.any_expanded_interference;
  step.unexpanded_collides = probe.any_collision;
  return step;
}

void RunRecorder::add_transition(const AcceptedStep& accepted, StepRecord& step) const {
  const TransitionRecord& incoming = accepted.transition;
  if (certified_) {
    // Per link: the smallest clearance its hulls keep throughout the transition.
    // proof: proofs/two-ball-cover.md#corollary-motion-clearance
    for (std::size_t i = 0; i < cell_.hulls().size(); ++i) {
      const double kept = std::max(
          0.0, motion_clearance_lower_bound(accepted.from.hulls[i].radius,
                                            accepted.to.hulls[i].radius,
                                            incoming.hull_motion_bounds[i]));
      std::optional<double>& link = step.links[cell_.hulls()[i].link].motion_clearance;
      link = link ? std::min(*link, kept) : kept;
    }
  }
  // Per link: the hull whose bound uses the largest share of its allowance governs.
  std::vector<double> worst_share(cell_.robot().links.size(), -1.0);
  for (std::size_t i = 0; i < cell_.hulls().size(); ++i) {
    const int link = cell_.hulls()[i].link;
    const double bound = incoming.hull_motion_bounds[i];
    const double allowance = incoming.hull_allowances[i];
    const double share = allowance > 0.0 ? bound / allowance : kPlusInfinity;
    if (share > worst_share[link]) {
      worst_share[link] = share;
      step.links[link].motion_bound = bound;
      step.links[link].allowance = allowance;
      step.links[link].governing = incoming.governing[i];
    }
  }
}

void RunRecorder::record_start(const ProbeResult& start) {
  StepRecord step = make_record(start, 1, 0.0, 0.0);
  step.index = 0;
  if (start.any_collision && !result_.collision_step) result_.collision_step = step.index;
  track_summaries(step);
  result_.start = std::move(step);
}

void RunRecorder::record_step(const AcceptedStep& accepted) {
  StepRecord step = make_record(accepted.to, accepted.segment, accepted.parameter,
                                accepted.path_time);
  step.index = last_step_index_ + 1;
  add_transition(accepted, step);
  if (certified_ && claim_ == ClearClaim::kMotion && !result_.tolerance_shortfall) {
    note_tolerance_shortfall(accepted, step.index);
  }
  step.refinement = accepted.refinement;
  if (accepted.to.any_collision && !result_.collision_step) result_.collision_step = step.index;
  track_summaries(step);
  last_step_index_ = step.index;
  last_q_ = step.q;
  for (VerificationObserver* observer : hooks_.observers) observer->on_step(step);
  if (hooks_.keep_steps) result_.steps.push_back(std::move(step));
}

// The claim `motion` needs g >= Delta for every hull and self pair in every transition, decided
// on the same rounded-down g the reports print (the checker decides it again exactly).
// proof: proofs/two-ball-cover.md#lemma-tolerance-along-motion
void RunRecorder::note_tolerance_shortfall(const AcceptedStep& accepted, int step_index) {
  for (std::size_t i = 0; i < cell_.hulls().size(); ++i) {
    const HullState& from = accepted.from.hulls[i];
    const HullState& to = accepted.to.hulls[i];
    const double kept = motion_clearance_lower_bound(
        from.radius, to.radius, accepted.transition.hull_motion_bounds[i]);
    if (kept >= cell_.tolerance()) continue;
    ToleranceShortfall shortfall;
    shortfall.step = step_index;
    shortfall.link = cell_.hulls()[i].link;
    shortfall.obstacle = from.radius <= to.radius ? from.nearest_obstacle : to.nearest_obstacle;
    shortfall.motion_clearance = std::max(0.0, kept);
    result_.tolerance_shortfall = shortfall;
    return;
  }
  note_self_pair_shortfall(accepted, step_index);
}

// Every self pair keeps a gap g >= Delta, the same rounded-down g from d_k, d_{k+1} and the
// relative bound. proof: proofs/two-ball-cover.md#corollary-self-tolerance-along-motion
void RunRecorder::note_self_pair_shortfall(const AcceptedStep& accepted, int step_index) {
  const std::vector<SelfPairHulls>& pairs = cell_.self_pairs();
  const TransitionRecord& transition = accepted.transition;
  for (std::size_t p = 0; p < pairs.size() && p < transition.self_pair_motion_bounds.size(); ++p) {
    const bool revolution = by_revolution(transition, p);
    const double kept = motion_clearance_lower_bound(route_distance(accepted.from.self_pairs[p], revolution),
                                                     route_distance(accepted.to.self_pairs[p], revolution),
                                                     transition.self_pair_motion_bounds[p]);
    if (kept >= cell_.tolerance()) continue;
    ToleranceShortfall shortfall;
    shortfall.step = step_index;
    shortfall.link = cell_.hulls()[static_cast<std::size_t>(pairs[p].a)].link;
    shortfall.other_link = cell_.hulls()[static_cast<std::size_t>(pairs[p].b)].link;
    shortfall.motion_clearance = std::max(0.0, kept);
    result_.tolerance_shortfall = shortfall;
    return;
  }
}

void RunRecorder::track_summaries(const StepRecord& step) {
  // Per-link minimum clearance and where it first occurs, in step order (start first).
  for (LinkClearanceSummary& summary : clearances_) {
    const LinkStepRecord& link = step.links[summary.link];
    if (link.clearance < summary.min_clearance) {
      summary.min_clearance = link.clearance;
      summary.step = step.index;
      summary.obstacle = link.nearest_obstacle;
    }
    if (link.motion_clearance &&
        (!summary.min_motion_clearance || *link.motion_clearance < *summary.min_motion_clearance)) {
      summary.min_motion_clearance = link.motion_clearance;
      summary.motion_step = step.index;
    }
  }
  any_expanded_ |= step.expanded_interferes;
  episodes_.add(step);
  self_episodes_.add(step);
}

void RunRecorder::add_error(int code, int segment, std::string message) {
  PathError error;
  error.code = code;
  error.segment = segment;
  error.step = last_step_index_;
  error.message = std::move(message);
  result_.errors.push_back(error);
}

const Eigen::VectorXd& RunRecorder::last_q() const {
  return last_step_index_ == 0 ? result_.start->q : last_q_;
}

VerificationResult RunRecorder::finish() {
  result_.link_clearances = clearances_;
  result_.interference_episodes = episodes_.episodes();
  result_.self_collision_episodes = self_episodes_.episodes();
  if (result_.collision_step) {
    result_.verdict = Verdict::kCollision;
  } else if (!result_.errors.empty()) {
    result_.verdict = Verdict::kError;
  } else if (any_uncertified_) {
    result_.verdict = Verdict::kUndecided;
  } else if (any_expanded_ || result_.tolerance_shortfall) {
    // Claim `motion`: a transition with g < Delta proves only the nominal robot clear there.
    result_.verdict = Verdict::kWithinTolerance;
  } else {
    result_.verdict = Verdict::kClear;
  }
  // The shortfall is reported only when it alone keeps the run from CLEAR.
  if (result_.verdict != Verdict::kWithinTolerance || any_expanded_) {
    result_.tolerance_shortfall.reset();
  }
  for (const SegmentRecord& segment : result_.segments) {
    if (segment.simulated) result_.total_cycle_time += segment.cycle_time;
  }
  return std::move(result_);
}

}  // namespace grpvss::certify

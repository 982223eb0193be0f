#include "grpvss/certify/verifier.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include <Eigen/SVD>

#include "grpvss/certify/cell_probe.hpp"
#include "grpvss/certify/interference_episodes.hpp"
#include "grpvss/certify/joint_linear_motion_bound.hpp"
#include "grpvss/certify/motion_clearance.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/step_proposal.hpp"
#include "grpvss/geometry/directed_rounding.hpp"
#include "grpvss/geometry/gjk.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/jacobian.hpp"
#include "grpvss/motion/cp_line.hpp"

namespace grpvss::certify {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

const char* segment_kind_name(motion::SegmentKind kind) {
  switch (kind) {
    case motion::SegmentKind::kPtpJoint: return "ptp-joint";
    case motion::SegmentKind::kPtpWorld: return "ptp-world";
    case motion::SegmentKind::kCpLine: return "cp-line";
  }
  return "?";
}

// r_k + r_{k+1} rounded down, so that "bound <= allowance" in double implies it exactly.
double allowance_down(double radius_k, double radius_k1) {
  namespace r = geometry::rounding;
  r::UpwardRoundingScope upward;
  return r::add_down(radius_k, radius_k1);
}

// Inside a collision the colliding pairs are not sampled (the verdict there is COLLISION,
// from the exact contact at the step's end): a hull that collides at an end of the step is
// held only against the obstacles it does not collide with, whose radii
// (radius_beside_collisions) cover its motion or keep it to the basic resolution. For the
// step decision only: the recorded allowances stay r_k + r_{k+1}, which the checker verifies.
// docs/verification.md#steps-through-a-collision
TransitionRecord beside_collisions(const TransitionRecord& transition, const ProbeResult& from,
                                   const ProbeResult& to) {
  TransitionRecord beside = transition;
  for (std::size_t i = 0; i < beside.hull_allowances.size(); ++i) {
    if (from.hulls[i].raw_collides || to.hulls[i].raw_collides) {
      beside.hull_allowances[i] = allowance_down(from.hulls[i].radius_beside_collisions,
                                                 to.hulls[i].radius_beside_collisions);
    }
  }
  return beside;
}

// One segment's configurations as a function of its parameter s: time for PTP, path length
// for CP (docs/verification.md#segment-parameter).
class SegmentPath {
 public:
  SegmentPath(const RobotModel& robot, const motion::KinematicsAccess& kinematics,
              const motion::SegmentTrajectory& segment)
      : robot_(&robot), kinematics_(&kinematics), segment_(&segment) {}

  bool is_cp() const { return segment_->kind == motion::SegmentKind::kCpLine; }
  double parameter_end() const { return is_cp() ? segment_->cp->length() : segment_->duration; }
  double time_at(double s) const {
    if (!is_cp()) return segment_->start_time + s;
    const double end = parameter_end();
    return segment_->start_time + (end > 0.0 ? segment_->duration * (s / end) : 0.0);
  }

  /// PTP: the profile. CP: IK of the line's pose nearest the previous step's joints; the end
  /// of the line is the motion stage's own end configuration (the next segment starts there).
  std::optional<Eigen::VectorXd> q_at(double s, const Eigen::VectorXd& q_previous) const {
    if (!is_cp()) return segment_->ptp->joints_at(s);
    if (s <= 0.0) return segment_->q_start;
    if (s >= parameter_end()) return segment_->q_end;
    return motion::solve_within_limits(*robot_, *kinematics_, segment_->cp->pose_at(s), q_previous);
  }

  Eigen::VectorXd joint_velocity_at(double s) const {
    if (is_cp()) return Eigen::VectorXd::Zero(robot_->joint_count());
    return segment_->ptp->velocities_at(s);
  }

  const motion::SegmentTrajectory& segment() const { return *segment_; }
  const motion::CpLine& line() const { return *segment_->cp; }

 private:
  const RobotModel* robot_;
  const motion::KinematicsAccess* kinematics_;
  const motion::SegmentTrajectory* segment_;
};

class PathVerifier {
 public:
  PathVerifier(const RobotCell& cell, const Environment& environment,
               const PathProgram& program, const motion::KinematicsAccess& kinematics,
               const VerifyOptions& options)
      : robot_(cell.robot()),
        environment_(environment),
        program_(program),
        kinematics_(kinematics),
        options_(options),
        cell_(cell),
        probe_(cell_),
        workspace_(cell.robot()) {
    const CellOptions expected = make_cell_options(options);
    if (cell.tolerance() != expected.tolerance || cell.offset_shape() != expected.offset_shape) {
      throw std::invalid_argument("verify: the robot cell was built for other options");
    }
    const RobotModel& robot = cell.robot();
    for (const LinkHull& hull : cell.hulls()) {
      for (int joint = 1; joint <= robot.joint_count(); ++joint) {
        proposal_weights_.push_back(cell.radii().motion_bound_weight(hull.link, hull.hull, joint));
      }
    }
    for (const HullPoints& hull : robot.links.back().hulls) {
      for (const auto& p_L : hull.points) end_link_reach_ = std::max(end_link_reach_, p_L.norm());
    }
  }

  VerificationRun run();

 private:
  bool certified() const { return options_.mode == ResolutionMode::kCertified; }

  void record_step(const ProbeResult& probe, int segment, double parameter, double path_time,
                   const TransitionRecord* incoming, bool refinement);
  StepCertificate certificate_step(const ProbeResult& probe, int index, double parameter) const;
  bool march_segment(const SegmentPath& path, int segment_number);
  double predicted_ptp_step(const SegmentPath& path, double s, double step) const;
  /// `joint_linear`: the joints move along the straight line between the two configurations
  /// (a CP step, proofs/cp-joint-path.md#model), so the chord bound may be used (certified
  /// mode only: the thesis mode's bounds are for comparison and cost no extra work).
  TransitionRecord judge_transition(const ProbeResult& from, const ProbeResult& to,
                                    bool cut_by_segment_end, bool joint_linear) const;
  bool cp_model_holds(const SegmentPath& path, double s0, const Eigen::VectorXd& q0, double s1,
                      const Eigen::VectorXd& q1) {
    return cp_model_deviation(path, s0, q0, s1, q1) <= 1.0;
  }
  /// How far the joint-linear motion strays from the commanded line, as a multiple of what
  /// the CP model allows (the largest of the position and orientation ratios at the sampled
  /// fractions): the model holds iff it is <= 1.
  double cp_model_deviation(const SegmentPath& path, double s0, const Eigen::VectorXd& q0,
                            double s1, const Eigen::VectorXd& q1);
  /// The longest step from s (to `resolution`) over which cp_model_holds, found by bisection
  /// below s_failing (where it fails); from current_.q. Proposals only: the march decides.
  double cp_model_reach(const SegmentPath& path, double s, double s_failing, double resolution);
  bool near_singularity(const Eigen::VectorXd& q);
  /// A joint at (within kLimitBand of) its limit at s, and the line unreachable just ahead:
  /// a stretch shorter than any step whose IK samples on both sides succeed
  /// (proofs/cp-joint-path.md#ik-failure; the long oracle run's case 1199).
  bool unreachable_next_to_a_limit(const SegmentPath& path, double s, const Eigen::VectorXd& q);
  double thesis_next_parameter(const SegmentPath& path, double s, const Eigen::VectorXd& q,
                               double previous_step);
  std::vector<double> thesis_allowed_displacements(const Eigen::VectorXd& q);
  void add_error(int code, int segment, std::string message);
  int last_step_index() const { return last_step_index_; }
  void track_summaries(const StepRecord& step);
  void flush_certificate_step();
  void finish();

  const RobotModel& robot_;
  const Environment& environment_;
  const PathProgram& program_;
  const motion::KinematicsAccess& kinematics_;
  VerifyOptions options_;
  const RobotCell& cell_;
  CellProbe probe_;
  kinematics::Workspace workspace_;
  ProbeResult current_;
  ProbeResult trial_;
  double end_link_reach_ = 1.0;
  /// The radii of the step before current_ in this segment and the parameter step between
  /// them (the trend predicted_ptp_step extrapolates); empty at a segment start.
  std::vector<double> previous_radii_;
  std::vector<double> proposal_weights_;  ///< [hull * joints + joint - 1]: M_h's coefficients
  double previous_step_ = 1.0;
  CpModelFailures model_failures_;  ///< the failed CP-model trials from the current step
  double previous_slack_ = 0.0;  ///< of the last accepted certified transition
  bool basic_resolution_mode_ = false;  ///< after an uncertified step, until one certifies  ///< max |p_L| over the last link's hulls (at least 1)
  long long probes_ = 0;
  bool any_uncertified_ = false;
  VerificationRun run_;
  SegmentCertificate* segment_certificate_ = nullptr;
  // Kept whether or not the steps are (VerifyOptions::keep_steps): what the run needs of the
  // steps so far, in memory independent of their number.
  int last_step_index_ = 0;  ///< 0 before the first step
  Eigen::VectorXd last_q_;   ///< the last step's configuration
  bool any_expanded_ = false;
  std::vector<LinkClearanceSummary> clearances_;
  InterferenceEpisodeTracker episodes_;
  /// The current segment's last certificate step: complete (and passed on) only once the
  /// transition to its successor was judged, or when the segment ends.
  std::optional<StepCertificate> pending_certificate_step_;
};

void PathVerifier::add_error(int code, int segment, std::string message) {
  PathError error;
  error.code = code;
  error.segment = segment;
  error.step = last_step_index();
  error.message = std::move(message);
  run_.result.errors.push_back(error);
}

StepCertificate PathVerifier::certificate_step(const ProbeResult& probe, int index,
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
  return step;
}

void PathVerifier::record_step(const ProbeResult& probe, int segment, double parameter,
                               double path_time, const TransitionRecord* incoming,
                               bool refinement) {
  StepRecord step;
  const bool is_start = incoming == nullptr && !run_.result.start;
  step.index = is_start ? 0 : last_step_index_ + 1;
  step.segment = segment;
  step.path_time = path_time;
  step.segment_parameter = parameter;
  step.q = probe.q;
  step.end_effector_W = kinematics::end_effector_pose(cell_.chain(), probe.q).translation();
  step.links.assign(robot_.links.size(), LinkStepRecord{});
  for (int link = 0; link < static_cast<int>(robot_.links.size()); ++link) {
    step.links[link].clearance = probe.link_radius(cell_, link);
    step.links[link].nearest_obstacle = probe.link_nearest_obstacle(cell_, link);
  }
  if (incoming != nullptr && certified()) {
    // Per link: the smallest clearance its hulls keep throughout the transition from current_
    // (the previous step's probe) to this one.
    // proof: proofs/two-ball-cover.md#corollary-motion-clearance
    for (std::size_t i = 0; i < cell_.hulls().size(); ++i) {
      const double kept = std::max(
          0.0, motion_clearance_lower_bound(current_.hulls[i].radius, probe.hulls[i].radius,
                                            incoming->hull_motion_bounds[i]));
      std::optional<double>& link = step.links[cell_.hulls()[i].link].motion_clearance;
      link = link ? std::min(*link, kept) : kept;
    }
  }
  if (incoming != nullptr) {
    // Per link: the hull whose bound uses the largest share of its allowance governs.
    std::vector<double> worst_share(robot_.links.size(), -1.0);
    for (std::size_t i = 0; i < cell_.hulls().size(); ++i) {
      const int link = cell_.hulls()[i].link;
      const double bound = incoming->hull_motion_bounds[i];
      const double allowance = incoming->hull_allowances[i];
      const double share = allowance > 0.0 ? bound / allowance : kInfinity;
      if (share > worst_share[link]) {
        worst_share[link] = share;
        step.links[link].motion_bound = bound;
        step.links[link].allowance = allowance;
        step.links[link].governing = incoming->governing[i];
      }
    }
  }
  step.interference_points = probe.interference_points;
  step.contacts = interfering_pairs(cell_, probe);
  step.expanded_interferes = probe.any_expanded_interference;
  step.unexpanded_collides = probe.any_collision;
  step.refinement = refinement;
  if (probe.any_collision && !run_.result.collision_step) run_.result.collision_step = step.index;
  track_summaries(step);
  if (is_start) {
    run_.result.start = std::move(step);
    return;
  }
  last_step_index_ = step.index;
  last_q_ = step.q;
  for (VerificationObserver* observer : options_.observers) observer->on_step(step);
  if (options_.keep_steps) run_.result.steps.push_back(std::move(step));

  if (segment_certificate_ != nullptr) {
    // The previous step's record is complete once its transition is known.
    if (incoming != nullptr && pending_certificate_step_) {
      pending_certificate_step_->to_next = *incoming;
    }
    flush_certificate_step();
    pending_certificate_step_ = certificate_step(probe, last_step_index_, parameter);
  }
}

void PathVerifier::track_summaries(const StepRecord& step) {
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
}

void PathVerifier::flush_certificate_step() {
  if (!pending_certificate_step_) return;
  for (VerificationObserver* observer : options_.observers) {
    observer->on_certificate_step(*pending_certificate_step_);
  }
  if (options_.keep_steps) {
    segment_certificate_->steps.push_back(std::move(*pending_certificate_step_));
  }
  pending_certificate_step_.reset();
}

// proof: proofs/two-ball-cover.md#corollary-step, proofs/motion-bound.md#lemma-motion-bound,
// proofs/motion-bound.md#lemma-joint-linear-chord
TransitionRecord PathVerifier::judge_transition(const ProbeResult& from, const ProbeResult& to,
                                                bool cut_by_segment_end, bool joint_linear) const {
  TransitionRecord record;
  record.certified = true;
  const Eigen::VectorXd dq = to.q - from.q;
  const double two_delta = 2.0 * cell_.tolerance();
  for (std::size_t i = 0; i < cell_.hulls().size(); ++i) {
    const LinkHull& hull = cell_.hulls()[i];
    double bound = cell_.radii().hull_motion_bound(hull.link, hull.hull, dq);
    if (joint_linear && bound > 0.0) {
      // Joints that undo each other's sweep (a roll joint keeping the tool's orientation on a
      // CP line) move the hull far less than the sum of their sweeps: the chord sees that.
      bound = std::min(bound, joint_linear_motion_bound(
                                  cell_.radii(), hull.link, hull.hull, hull.raw_L, from.q,
                                  from.X_WL[hull.link], to.q, to.X_WL[hull.link],
                                  cell_.placement_error()));
    }
    const double allowance = allowance_down(from.hulls[i].radius, to.hulls[i].radius);
    GoverningTerm governing = GoverningTerm::kClearance;
    if (from.hulls[i].expanded_interferes || to.hulls[i].expanded_interferes) {
      governing = GoverningTerm::kRawClearance;
    } else if (allowance <= two_delta * (1.0 + 1e-9)) {
      governing = GoverningTerm::kTolerance;
    } else if (cut_by_segment_end) {
      governing = GoverningTerm::kSegmentEnd;
    }
    if (!(bound <= allowance)) {
      record.certified = false;
      governing = GoverningTerm::kUncertified;
    }
    record.hull_motion_bounds.push_back(bound);
    record.hull_allowances.push_back(allowance);
    record.governing.push_back(governing);
  }
  return record;
}

bool PathVerifier::near_singularity(const Eigen::VectorXd& q) {
  kinematics::forward_kinematics(cell_.chain(), q, workspace_);
  const Eigen::MatrixXd jacobian = kinematics::point_jacobian(
      cell_.chain(), workspace_, robot_.joint_count(), Eigen::Vector3d::Zero());
  if (jacobian.cols() < 3) return false;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian);
  return svd.singularValues().minCoeff() < options_.cp_singular_value_threshold;
}

bool PathVerifier::unreachable_next_to_a_limit(const SegmentPath& path, double s,
                                               const Eigen::VectorXd& q) {
  // Joint values are clamped to their limits by PTP targets, so a CP segment may start with a
  // joint exactly at one; elsewhere a step landing on a limit is rare. Only then the line is
  // probed, at distances far below a step (IK only, no probe).
  constexpr double kLimitBand = 1e-6;
  bool at_limit = false;
  for (int j = 0; j < robot_.joint_count(); ++j) {
    const Joint& joint = robot_.joints[static_cast<std::size_t>(j)];
    at_limit |= std::abs(q[j] - joint.minimum) <= kLimitBand ||
                std::abs(q[j] - joint.maximum) <= kLimitBand;
  }
  if (!at_limit) return false;
  const double left = path.parameter_end() - s;
  for (const double ahead : {options_.tolerance / 64.0, options_.tolerance / 8.0}) {
    if (!(ahead < left)) break;
    if (!path.q_at(s + ahead, q)) return true;
  }
  return false;
}

double PathVerifier::cp_model_reach(const SegmentPath& path, double s, double s_failing,
                                    double resolution) {
  // Invariant: the model holds from s to s + low (trivially at 0) and fails to s_failing.
  double low = 0.0;
  double high = s_failing - s;
  while (high - low > resolution) {
    const double middle = 0.5 * (low + high);
    const std::optional<Eigen::VectorXd> q = path.q_at(s + middle, current_.q);
    (q && cp_model_holds(path, s, current_.q, s + middle, *q) ? low : high) = middle;
  }
  return low;
}

// The CP model (proofs/cp-joint-path.md#model): the joints move linearly between the two
// samples; the end effector of that motion must stay near the commanded line. A step that
// fails is subdivided by the caller; a jump that survives subdivision is error 7.
double PathVerifier::cp_model_deviation(const SegmentPath& path, double s0,
                                        const Eigen::VectorXd& q0, double s1,
                                        const Eigen::VectorXd& q1) {
  // Position: the tolerance (times a fraction). Orientation: the angle that moves the farthest
  // point of the last link's hulls by that much (a joint-4 wrap of 360 degrees moves no
  // origin but sweeps the whole tool).
  const double limit = options_.cp_deviation_fraction * options_.tolerance;
  const double angle_limit = limit / end_link_reach_;
  double deviation = 0.0;
  for (const double fraction : {0.25, 0.5, 0.75}) {
    const Eigen::VectorXd q_mid = q0 + fraction * (q1 - q0);
    const Eigen::Isometry3d X_WE_joint_linear = kinematics::end_effector_pose(cell_.chain(), q_mid);
    const Eigen::Isometry3d X_WE_line = path.line().pose_at(s0 + fraction * (s1 - s0));
    const Eigen::AngleAxisd rotation_error(X_WE_line.linear().transpose() *
                                           X_WE_joint_linear.linear());
    deviation = std::max({deviation,
                          (X_WE_joint_linear.translation() - X_WE_line.translation()).norm() / limit,
                          std::abs(rotation_error.angle()) / angle_limit});
    if (!(deviation <= 1.0)) return deviation;  // NaN too: the model fails
  }
  return deviation;
}

std::vector<double> PathVerifier::thesis_allowed_displacements(const Eigen::VectorXd& q) {
  // Eq. 3-3: delta_l_i = max{min[2D/cos(theta/2), 2D + L], Dmin_i} at the origin of frame i.
  const double delta = options_.tolerance;
  const double base = std::min(2.0 * delta / std::cos(environment_.smallest_angle / 2.0),
                               2.0 * delta + environment_.smallest_thickness);
  kinematics::forward_kinematics(cell_.chain(), q, workspace_);
  kinematics::place_hull_points(robot_, workspace_);
  std::vector<double> allowed(robot_.joint_count() + 1, base);
  for (int link = 1; link <= robot_.joint_count(); ++link) {
    double nearest = kInfinity;
    for (const auto& hull_W : workspace_.hull_points_W[link]) {
      for (const auto& obstacle_W : cell_.obstacles_W()) {
        nearest = std::min(nearest, geometry::gjk(hull_W, obstacle_W).distance);
      }
    }
    if (robot_.links[link].hulls.empty() || cell_.obstacles_W().empty()) nearest = 0.0;
    allowed[link] = std::max(base, nearest);
  }
  return allowed;
}

// Thesis Eq. 4-13..4-16 (PTP: delta_t_i <= delta_l_i / v_i) and Figure 16 (CP: the ratio
// iteration on the end effector's increment). Link-frame origins only: see
// proofs/thesis-rule.md for what this does and does not guarantee.
double PathVerifier::thesis_next_parameter(const SegmentPath& path, double s,
                                           const Eigen::VectorXd& q, double previous_step) {
  const double end = path.parameter_end();
  const std::vector<double> allowed = thesis_allowed_displacements(q);
  const int joints = robot_.joint_count();
  if (!path.is_cp()) {
    double step = previous_step > 0.0 ? previous_step : end / 16.0;
    for (int iteration = 0; iteration < 3; ++iteration) {
      const Eigen::VectorXd speed_now = path.joint_velocity_at(s).cwiseAbs();
      const Eigen::VectorXd speed_then = path.joint_velocity_at(std::min(end, s + step)).cwiseAbs();
      const Eigen::VectorXd joint_speed = speed_now.cwiseMax(speed_then);
      kinematics::forward_kinematics(cell_.chain(), q, workspace_);
      double candidate = end - s;
      for (int link = 1; link <= joints; ++link) {
        const Eigen::Vector3d velocity =
            kinematics::point_jacobian(cell_.chain(), workspace_, link, Eigen::Vector3d::Zero()) *
            joint_speed;
        const double speed = velocity.norm();
        if (speed > 0.0) candidate = std::min(candidate, allowed[link] / speed);
      }
      step = candidate;
    }
    return std::min(end, s + std::max(step, end * options_.min_step_fraction));
  }
  // CP: trial increment of the end effector, scaled by the smallest ratio until every
  // origin moves at most its allowance (Figure 16).
  double increment = *std::min_element(allowed.begin() + 1, allowed.end());
  kinematics::forward_kinematics(cell_.chain(), q, workspace_);
  std::vector<Eigen::Vector3d> origins_now(joints + 1);
  for (int link = 1; link <= joints; ++link) origins_now[link] = workspace_.X_WL[link].translation();
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double s1 = std::min(end, s + increment);
    const std::optional<Eigen::VectorXd> q1 = path.q_at(s1, q);
    if (!q1) return s1;  // the caller reports the unreachable point (error 5)
    kinematics::forward_kinematics(cell_.chain(), *q1, workspace_);
    double ratio = kInfinity;
    for (int link = 1; link <= joints; ++link) {
      const double moved = (workspace_.X_WL[link].translation() - origins_now[link]).norm();
      if (moved > 0.0) ratio = std::min(ratio, allowed[link] / moved);
    }
    if (ratio >= 1.0) return s1;
    increment = (s1 - s) * ratio * 0.999;
  }
  return std::min(end, s + increment);
}

// The PTP proposal of step_proposal.hpp, from this verifier's state.
double PathVerifier::predicted_ptp_step(const SegmentPath& path, double s, double step) const {
  const bool has_trend = previous_radii_.size() == cell_.hulls().size();
  std::vector<ProposalHull> hulls(cell_.hulls().size());
  for (std::size_t i = 0; i < hulls.size(); ++i) {
    hulls[i].radius = current_.hulls[i].radius;
    hulls[i].expanded_interferes = current_.hulls[i].expanded_interferes;
    if (has_trend) hulls[i].previous_radius = previous_radii_[i];
  }
  const motion::PtpMotion& ptp = *path.segment().ptp;
  return certify::predicted_ptp_step([&](double candidate) { return ptp.joints_at(s + candidate); },
                                     current_.q, step, proposal_weights_, hulls, has_trend,
                                     previous_step_);
}

// Returns false when the path must stop (an error was recorded).
bool PathVerifier::march_segment(const SegmentPath& path, int segment_number) {
  const double end = path.parameter_end();
  const double min_step = std::max(end * options_.min_step_fraction, 1e-300);
  // Below this a failing certified step stops shrinking and the basic resolution takes over.
  const double certify_floor = std::max(end * options_.certify_floor_fraction, min_step);
  basic_resolution_mode_ = false;
  previous_radii_.clear();
  double s = 0.0;
  double step = end;
  previous_slack_ = 0.0;
  model_failures_.reset();
  bool retrying = false;  ///< the proposal is a shrunk retry of a rejected one
  while (s < end) {
    if (probes_ >= options_.max_probes) {
      add_error(kErrorProbeLimit, segment_number,
                "THE CONFIGURATION BUDGET WAS EXHAUSTED IN MOTION SEGMENT " +
                    std::to_string(segment_number));
      return false;
    }
    // Floors are compared with the proposed step, not with s1 - s: rounding can make the
    // difference a hair larger than the step and a floor never reached.
    if (certified() && !path.is_cp() && !basic_resolution_mode_ && !retrying) {
      // After a step with ample slack (receding from every obstacle) the growth rule's
      // proposal is kept: the linear extrapolation underestimates a growing clearance.
      const double predicted = predicted_ptp_step(path, s, std::min(step, end - s));
      step = std::max({predicted, previous_slack_ >= 1.5 ? step : 0.0,
                       std::min(certify_floor, end - s)});
    }
    const bool first_trial = !retrying;  // of this step (not a shrunk retry)
    retrying = true;
    const double proposed = step;
    double s1 = 0.0;
    if (certified()) {
      s1 = std::min(end, s + step);
      // A sliver left before the segment's end would cost a probe of its own: take it now
      // (the transition still decides). Only on a first trial: a shrunk retry must not be
      // stretched back to the same rejected end.
      if (first_trial && end - s1 < 0.25 * step) s1 = end;
    } else {
      s1 = thesis_next_parameter(path, s, current_.q, step);
    }
    const std::optional<Eigen::VectorXd> q1 = path.q_at(s1, current_.q);
    if (!q1 || (first_trial && path.is_cp() && certified() &&
                unreachable_next_to_a_limit(path, s, current_.q))) {
      add_error(5, segment_number,
                motion::thesis_error_text(5, segment_number));
      return false;
    }
    double model_deviation = 0.0;  ///< of the CP model over this step (certified CP only)
    if (path.is_cp() && certified()) {
      model_deviation = cp_model_deviation(path, s, current_.q, s1, *q1);
      if (!(model_deviation <= 1.0)) {
        if (proposed > min_step) {
          step = (s1 - s) * cp_model_retry_fraction(model_deviation);
          // A step far shorter than the last one this segment accepted failing too, or a
          // deviation that did not shrink with the step, points at a joint jump ahead:
          // halving and growing again would crowd the report with proven steps creeping up
          // to it. Locate it (IK and FK only, no probe) and aim just before. (previous_radii_
          // is empty until this segment accepts a step; previous_step_ is that step's length.)
          const bool deviation_kept = model_failures_.record(s, s1 - s, model_deviation);
          if (!previous_radii_.empty() && (s1 - s < 0.25 * previous_step_ || deviation_kept)) {
            step = cp_model_reach(path, s, s1, min_step);
            if (!(step > min_step)) step = 0.0;  // fails at any step: the jump is here
          }
          if (step > 0.0) continue;
        }
        add_error(kErrorCpJointJump, segment_number,
                  "THE JOINTS JUMP (IK BRANCH CHANGE) BETWEEN TWO CLOSE POINTS OF THE CP LINE IN "
                  "MOTION SEGMENT " + std::to_string(segment_number));
        return false;
      }
      if (near_singularity(*q1)) {
        add_error(kErrorCpSingularity, segment_number,
                  "THE CP LINE PASSES A SINGULAR CONFIGURATION IN MOTION SEGMENT " +
                      std::to_string(segment_number));
        return false;
      }
    }
    ++probes_;
    // Trial configurations skip the (exact, costly) interference points; an accepted step
    // that interferes is evaluated again with them below.
    probe_.probe(*q1, /*with_points=*/false, trial_);
    const bool cut = s1 >= end;
    TransitionRecord transition = judge_transition(current_, trial_, cut, path.is_cp() && certified());
    const double taken = s1 - s;
    if (!certified()) {
      std::fill(transition.governing.begin(), transition.governing.end(),
                GoverningTerm::kThesisRule);
      transition.certified = false;
      step = taken;
    } else if (transition.certified) {
      // Accepted: the next proposal grows with the slack this step left.
      previous_slack_ = transition_slack(transition);
      step = taken * std::clamp(0.9 * previous_slack_, 1.0, 4.0);
      if (trial_.any_expanded_interference) {
        // Refining next to a contact, the proven steps shrink geometrically towards the
        // contact time (Zeno: each allowance is the raw clearance left). The next trial aims
        // at the basic resolution instead (at most 4x this step): one past the contact finds
        // the COLLISION at once; one that is not proven is cut back below as before.
        step = std::max(step, taken * std::clamp(0.95 * basic_resolution_slack(
                                                              transition, 2.0 * options_.tolerance),
                                                 1.0, 4.0));
      }
    } else {
      // Nothing to certify next to a collision, and near a first contact the proven steps
      // shrink geometrically towards the contact time without ever passing it (Zeno). In
      // both cases, and once the certified step floor is reached, move on at the thesis's
      // basic resolution (every point at most 2D per step): the report covers the motion, a
      // step past the contact finds the COLLISION, and a stretch that is neither proven nor
      // colliding makes the verdict UNDECIDED. (Hulls whose clearances cover their motion are
      // not held to 2D: basic_resolution_slack; a pair colliding at an end of the step is not
      // held at all: beside_collisions.)
      const bool collision_at_an_end = current_.any_collision || trial_.any_collision;
      const bool basic_mode = collision_at_an_end || basic_resolution_mode_ ||
                              proposed <= certify_floor;
      if (!basic_mode) {
        step = std::max(certify_floor,
                        taken * std::clamp(0.9 * transition_slack(transition), 0.05, 0.9));
        continue;
      }
      const double basic_slack = basic_resolution_slack(
          collision_at_an_end ? beside_collisions(transition, current_, trial_) : transition,
          2.0 * options_.tolerance);
      if (!(basic_slack >= 1.0) && proposed > min_step) {
        step = std::max(min_step, taken * std::clamp(0.95 * basic_slack, 0.1, 0.9));
        continue;
      }
      if (!collision_at_an_end) any_uncertified_ = true;
      basic_resolution_mode_ = true;
      // The bounds are nearly linear in the step: aim just below the resolution.
      step = taken * std::clamp(0.95 * basic_slack, 1.0, 4.0);
    }
    if (transition.certified) basic_resolution_mode_ = false;
    // Nor should the next CP proposal outgrow the model (the square law again).
    step = std::min(step, taken * cp_model_growth_cap(model_deviation));
    if (trial_.any_expanded_interference) {
      // Only the points are added: the radii and evidence the transition was judged on stay.
      probe_.add_interference_points(trial_);
    }
    const bool refinement_region =
        trial_.any_expanded_interference || current_.any_expanded_interference;
    record_step(trial_, segment_number, s1, path.time_at(s1), &transition,
                certified() && refinement_region);
    retrying = false;
    if (!transition.certified) previous_slack_ = 0.0;
    previous_radii_.clear();
    for (const HullState& hull : current_.hulls) previous_radii_.push_back(hull.radius);
    previous_step_ = taken;
    std::swap(current_, trial_);
    s = s1;
    if (options_.progress) {
      options_.progress((segment_number - 1 + s / end) /
                        static_cast<double>(program_.segments.size()));
    }
  }
  return true;
}

void PathVerifier::finish() {
  VerificationResult& result = run_.result;
  result.link_clearances = clearances_;
  result.interference_episodes = episodes_.episodes();
  const bool any_expanded = any_expanded_;
  if (result.collision_step) {
    result.verdict = Verdict::kCollision;
  } else if (!result.errors.empty()) {
    result.verdict = Verdict::kError;
  } else if (any_uncertified_) {
    result.verdict = Verdict::kUndecided;
  } else if (any_expanded) {
    result.verdict = Verdict::kWithinTolerance;
  } else {
    result.verdict = Verdict::kClear;
  }
  for (const SegmentRecord& segment : result.segments) {
    if (segment.simulated) result.total_cycle_time += segment.cycle_time;
  }
  if (certified()) {
    Certificate& certificate = run_.certificate;
    certificate.claim = to_string(result.verdict);
    certificate.collision_step = result.collision_step.value_or(0);
    certificate.errors = result.errors;
  }
}

VerificationRun PathVerifier::run() {
  VerificationResult& result = run_.result;
  result.tolerance = options_.tolerance;
  result.mode = options_.mode;
  result.path_file_label = options_.path_label;
  for (int link = 0; link < static_cast<int>(robot_.links.size()); ++link) {
    LinkClearanceSummary summary;
    summary.link = link;
    summary.min_clearance = kInfinity;
    clearances_.push_back(summary);
  }
  if (certified()) {
    Certificate& certificate = run_.certificate;
    certificate.mode = "certified";
    certificate.tolerance = options_.tolerance;
    certificate.offset_shape = cell_.offset_shape() == geometry::OffsetShape::kCube
                                   ? "cube"
                                   : "rhombicuboctahedron";
    certificate.timing =
        options_.trajectory.timing == motion::PtpTiming::kIndependent ? "independent"
                                                                      : "synchronized";
    certificate.cp_speed = options_.trajectory.cp_speed;
    certificate.cp_deviation_fraction = options_.cp_deviation_fraction;
    certificate.placement_error = cell_.placement_error();
    certificate.expansion_radius = cell_.expansion_radius();
  }
  const motion::Trajectory trajectory =
      motion::Trajectory::plan(robot_, program_, kinematics_, options_.trajectory);

  // Step 0: the start configuration (home), evaluated like every other step; it is never
  // printed in the thesis file, whose steps start at 1.
  probe_.probe(trajectory.home(), /*with_points=*/true, current_);
  ++probes_;
  record_step(current_, 1, 0.0, 0.0, nullptr, false);

  bool keep_going = true;
  for (const motion::SegmentTrajectory& segment : trajectory.segments()) {
    if (!keep_going) break;
    SegmentRecord record;
    record.number = segment.number;
    record.input = program_.segments[segment.number - 1];
    record.start_q = segment.q_start;
    record.end_q = segment.q_end;
    record.cycle_time = segment.duration;
    const SegmentPath path(robot_, kinematics_, segment);
    if (certified()) {
      SegmentCertificate segment_certificate;
      segment_certificate.number = segment.number;
      segment_certificate.kind = segment_kind_name(segment.kind);
      segment_certificate.parameter_end = path.parameter_end();
      for (VerificationObserver* observer : options_.observers) {
        observer->on_certificate_segment_begin(segment_certificate);
      }
      run_.certificate.segments.push_back(std::move(segment_certificate));
      segment_certificate_ = &run_.certificate.segments.back();
      // Every segment's certificate starts with its start configuration (the previous end).
      pending_certificate_step_ = certificate_step(current_, last_step_index(), 0.0);
    }
    const int first_step = last_step_index() + 1;
    keep_going = march_segment(path, segment.number);
    // Step indices of this segment (0, 0 when it produced none).
    record.last_step = last_step_index();
    record.first_step = record.last_step >= first_step ? first_step : 0;
    if (record.first_step == 0) record.last_step = 0;
    record.simulated = keep_going;
    result.segments.push_back(std::move(record));
    if (segment_certificate_ != nullptr) {
      flush_certificate_step();
      for (VerificationObserver* observer : options_.observers) {
        observer->on_certificate_segment_end();
      }
    }
    segment_certificate_ = nullptr;
  }
  // Segments the motion stage refused (thesis errors 3-6) stop the path there.
  for (const motion::ThesisError& error : trajectory.errors()) {
    if (keep_going) add_error(error.code, error.segment, error.message);
    if (error.segment > 0 && error.segment <= static_cast<int>(program_.segments.size())) {
      SegmentRecord refused;
      refused.number = error.segment;
      refused.input = program_.segments[error.segment - 1];
      refused.start_q = last_step_index_ == 0 ? result.start->q : last_q_;
      refused.simulated = false;
      result.segments.push_back(std::move(refused));
    }
  }
  finish();
  return std::move(run_);
}

}  // namespace

CellOptions make_cell_options(const VerifyOptions& options) {
  CellOptions cell_options;
  cell_options.tolerance = options.tolerance;
  cell_options.offset_shape = options.offset_shape.value_or(
      options.mode == ResolutionMode::kThesis ? geometry::OffsetShape::kCube
                                              : geometry::OffsetShape::kRhombicuboctahedron);
  return cell_options;
}

VerificationRun verify(const RobotCell& cell, const Environment& environment,
                       const PathProgram& program, const motion::KinematicsAccess& kinematics,
                       const VerifyOptions& options) {
  PathVerifier verifier(cell, environment, program, kinematics, options);
  return verifier.run();
}

VerificationRun verify(const RobotModel& robot, const Environment& environment,
                       const PathProgram& program, const motion::KinematicsAccess& kinematics,
                       const VerifyOptions& options) {
  const RobotCell cell(robot, environment, make_cell_options(options));
  return verify(cell, environment, program, kinematics, options);
}

}  // namespace grpvss::certify

#include "grpvss/checker/certificate_checker.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/core.h>

#include "check_ledger.hpp"
#include "checked_cell.hpp"
#include "claim_check.hpp"
#include "claim_facts.hpp"
#include "grpvss/motion/cp_line.hpp"
#include "grpvss/motion/exact_joint_variation.hpp"
#include "grpvss/motion/joint_limit_check.hpp"
#include "grpvss/motion/joint_trajectory_source.hpp"
#include "grpvss/motion/trajectory.hpp"
#include "self_pair_check.hpp"
#include "step_evidence_check.hpp"
#include "transition_check.hpp"

namespace grpvss::certify {
namespace {

// The check in three parts so that a certificate can be read one segment at a time:
// start() (header, the checker's own cell, the trajectory), add_segment() in order, finish()
// (the claim).
class Checker {
 public:
  /// `certificate`: its header is read (its `segments` are not: they come to add_segment(),
  /// `segment_count` of them).
  Checker(const RobotModel& robot, const Environment& environment, const PathProgram& program,
          const motion::KinematicsAccess& kinematics, const Certificate& certificate,
          std::size_t segment_count, const CheckOptions& options)
      : robot_(robot),
        environment_(environment),
        program_(program),
        kinematics_(kinematics),
        certificate_(certificate),
        segment_count_(segment_count),
        options_(options),
        ledger_(report_, options.max_failures) {}

  void start();
  void add_segment(const SegmentCertificate& segment);
  CheckReport finish();

 private:
  bool check_header();
  void check_segment(const SegmentCertificate& segment, const motion::SegmentTrajectory& planned);
  /// The configuration the trajectory has at step k of the segment (the checker's own).
  std::optional<Eigen::VectorXd> planned_configuration(const motion::SegmentTrajectory& planned,
                                                       std::size_t k, const StepCertificate& step,
                                                       const StepCertificate* previous) const;
  /// The certificate's start is the one the check is given (both unset: the robot's home; a
  /// decision only when either is set).
  void check_start();
  /// The joint trajectory of CheckOptions as the trajectory to check against.
  motion::Trajectory joint_trajectory_motion();
  /// A trajectory piece's exact joint variation bound over a transition; empty otherwise.
  std::vector<Rational> piece_variation(const motion::SegmentTrajectory& planned,
                                        const StepCertificate& from,
                                        const StepCertificate& to) const;
  /// The certificate names other input files than the ones checked: its digests first.
  void reject_other_inputs();

  const RobotModel& robot_;
  const Environment& environment_;
  const PathProgram& program_;
  const motion::KinematicsAccess& kinematics_;
  const Certificate& certificate_;
  std::size_t segment_count_;
  CheckOptions options_;
  CheckReport report_;
  CheckLedger ledger_;
  ClaimFacts facts_;
  MotionClearances motion_clearances_;
  std::optional<CheckedCell> cell_;
  std::optional<StepEvidenceCheck> steps_;
  std::optional<TransitionCheck> transitions_;
  std::optional<motion::Trajectory> trajectory_;
  int previous_step_index_ = -1;
  bool stopped_ = false;    ///< the header, hulls or segment order failed: no more checking
  bool concluded_ = false;  ///< stopped before the claim: the report stays as it is
  std::size_t segments_added_ = 0;
};

bool Checker::check_header() {
  bool ok = true;
  if (certificate_.mode != ResolutionMode::kCertified) {
    ledger_.fail("the certificate's mode is not 'certified'");
    ok = false;
  }
  if (!(certificate_.tolerance > 0.0)) {
    ledger_.fail("tolerance must be > 0");
    ok = false;
  }
  // The placement error must cover the FK rounding bound for every coordinate used: the
  // checker measures the largest coordinate of its own offsets (CheckedCell::build).
  if (!(exact(certificate_.expansion_radius) >=
        exact(certificate_.tolerance) + 2 * exact(certificate_.placement_error))) {
    ledger_.fail("expansion_radius < tolerance + 2 placement_error");
    ok = false;
  }
  ledger_.decided();
  return ok;
}

void Checker::start() {
  report_.claim = certificate_.claim;
  report_.clear_claim = certificate_.clear_claim;
  report_.timing = certificate_.timing;
  report_.cp_speed = certificate_.cp_speed;
  if (const auto ik = certificate_.inputs.find("ik"); ik != certificate_.inputs.end()) {
    report_.ik = ik->second;
  }
  motion_clearances_.assign(robot_.links.size(), std::nullopt);
  if (check_header()) cell_ = CheckedCell::build(robot_, environment_, certificate_, ledger_);
  if (!cell_) {
    stopped_ = concluded_ = true;
    return;
  }
  steps_.emplace(*cell_, certificate_, ledger_, facts_);
  transitions_.emplace(*cell_, certificate_, ledger_, facts_, motion_clearances_);
  check_start();  // a trajectory's start is its first waypoint: no start is recorded
  if (options_.joint_trajectory) {
    trajectory_ = joint_trajectory_motion();
  } else {
    if (!certificate_.trajectory_interpolation.empty()) {
      ledger_.fail("the certificate was made for a joint trajectory (" +
                   certificate_.trajectory_interpolation +
                   " interpolation), the check is given a path program");
    }
    motion::MotionModel model;
    model.timing = certificate_.timing;
    model.cp_speed = certificate_.cp_speed;
    model.table = options_.profile_table;
    model.start = options_.start;
    trajectory_ = motion::Trajectory::plan(robot_, program_, kinematics_, model);
  }
  if (segment_count_ != trajectory_->segments().size() || !trajectory_->errors().empty()) {
    facts_.coverage_complete = false;
  }
  // Step 0 is the robot's home configuration (the path's start), known from the inputs: a
  // collision there is re-decided even when no segment was simulated (the path stopped at its
  // first segment, e.g. error 5), where no segment certificate names step 0.
  if (certificate_.collision_step == 0) facts_.collision_step_q = trajectory_->home();
  if (segment_count_ > trajectory_->segments().size()) {
    ledger_.fail("the certificate has " + std::to_string(segment_count_) +
                 " segments, the path's trajectory " +
                 std::to_string(trajectory_->segments().size()));
    stopped_ = concluded_ = true;
  }
}

std::string start_text(const std::optional<Eigen::VectorXd>& start) {
  if (!start) return "the robot's home";
  std::string text;
  for (Eigen::Index j = 0; j < start->size(); ++j) {
    text += (j == 0 ? "" : ",") + fmt::format("{}", (*start)[j]);
  }
  return "start " + text;
}

void Checker::check_start() {
  // Both at the home: nothing to compare (counts unchanged for certificates without a start).
  if (!certificate_.start && !options_.start) return;
  const bool same = certificate_.start.has_value() == options_.start.has_value() &&
                    (!certificate_.start || (certificate_.start->size() == options_.start->size() &&
                                                   *certificate_.start == *options_.start));
  if (!same) {
    ledger_.fail("the certificate was made for a path from " + start_text(certificate_.start) +
                 ", the check is given a path from " + start_text(options_.start));
  }
  ledger_.decided();
}

// The joint trajectory's motion, re-derived: the interpolation must be the certificate's and
// the limits must hold along it (the axis radii assume them).
// proof: proofs/joint-variation.md#lemma-position-limits
motion::Trajectory Checker::joint_trajectory_motion() {
  const motion::JointTrajectoryMotion& motion = *options_.joint_trajectory;
  const std::string given = motion::to_string(motion.interpolation());
  if (certificate_.trajectory_interpolation != given) {
    ledger_.fail("the certificate was made for " +
                 (certificate_.trajectory_interpolation.empty()
                      ? std::string("a path program")
                      : "a joint trajectory with " + certificate_.trajectory_interpolation +
                            " interpolation") +
                 ", the check is given a joint trajectory with " + given + " interpolation");
  }
  ledger_.decided();
  if (const auto violation = motion::first_limit_violation(motion, motion::joint_limits_of(robot_))) {
    ledger_.fail("the joint trajectory leaves the robot's limits: " +
                 motion::describe(*violation, motion.trajectory()));
  }
  return motion::Trajectory::from_joint_motion(robot_, options_.joint_trajectory);
}

// A trajectory piece's step time: the piece's waypoint time + parameter, the next waypoint's
// time at (or past) the piece's end, as the verifier places it.
double piece_time(const motion::SegmentTrajectory& planned, double parameter) {
  const std::vector<double>& breaks = planned.joint_motion->piece_breaks();
  if (parameter >= planned.duration) return breaks[static_cast<std::size_t>(planned.number)];
  return std::max(planned.start_time + parameter, breaks[static_cast<std::size_t>(planned.number - 1)]);
}

std::optional<Eigen::VectorXd> Checker::planned_configuration(
    const motion::SegmentTrajectory& planned, std::size_t k, const StepCertificate& step,
    const StepCertificate* previous) const {
  const bool cp = planned.kind == motion::SegmentKind::kCpLine;
  const double parameter_end = cp ? planned.cp->length() : planned.duration;
  if (k == 0) return planned.q_start;
  if (step.parameter == parameter_end) return planned.q_end;
  if (planned.joint_motion) {
    return motion::step_configuration(*planned.joint_motion, robot_,
                                      piece_time(planned, step.parameter));
  }
  if (!cp) return planned.ptp->joints_at(step.parameter);
  return motion::solve_within_limits(robot_, kinematics_, planned.cp->pose_at(step.parameter),
                                     previous->q);
}

void Checker::check_segment(const SegmentCertificate& segment,
                            const motion::SegmentTrajectory& planned) {
  const std::string where_segment = "segment " + std::to_string(segment.number);
  const bool cp = planned.kind == motion::SegmentKind::kCpLine;
  const double parameter_end = cp ? planned.cp->length() : planned.duration;
  // One step (the segment's start) is what a path stopped at its segment's first proposal
  // writes (e.g. error 7 before any step): its start configuration is still checked, and the
  // coverage test marks the segment's motion as not covered.
  if (segment.steps.empty()) {
    ledger_.fail(where_segment + ": no step");
    return;
  }
  if (!(segment.parameter_end == parameter_end) || segment.steps.back().parameter != parameter_end ||
      segment.steps.front().parameter != 0.0) {
    facts_.coverage_complete = false;  // fine for a path stopped by an error; not for a safety claim
  }
  std::vector<Rational> previous_radius;
  SelfPairDistances previous_distance;
  std::vector<std::vector<Eigen::Vector3d>> previous_placed, placed;
  const StepCertificate* previous = nullptr;
  for (std::size_t k = 0; k < segment.steps.size(); ++k) {
    const StepCertificate& step = segment.steps[k];
    const std::string where = where_segment + " step " + std::to_string(step.step);
    // Consecutive global step numbers (a removed step is a gap); the first step of a segment
    // repeats the previous segment's last.
    const int expected_index = k == 0 ? (previous_step_index_ < 0 ? 0 : previous_step_index_)
                                      : previous->step + 1;
    if (step.step != expected_index) ledger_.fail(where + ": step numbers are not consecutive");
    if (previous != nullptr && !(step.parameter > previous->parameter)) {
      ledger_.fail(where + ": parameters must increase");
    }
    // The configuration must be the trajectory's own at this parameter.
    const std::optional<Eigen::VectorXd> expected = planned_configuration(planned, k, step, previous);
    ledger_.decided();
    if (!expected || expected->size() != step.q.size() || *expected != step.q) {
      ledger_.fail(where + ": the configuration is not the trajectory's at this parameter");
    }
    std::vector<Rational> radius = steps_->check(step, where, placed);
    SelfPairDistances distance = check_self_pair_evidence(*cell_, certificate_, step, placed,
                                                          steps_->link_poses(), ledger_, where);
    if (previous != nullptr) {
      const std::string where_transition = where_segment + " steps " +
                                           std::to_string(previous->step) + "-" +
                                           std::to_string(step.step);
      transitions_->check(*previous, step, previous_radius, radius, previous_placed, placed, cp,
                          where_transition, piece_variation(planned, *previous, step));
      const VertexRouteBound vertex_bound = [&](std::size_t p) {
        return transitions_->vertex_route_bound(p, *previous, step, previous_placed, placed);
      };
      check_self_pair_transition(*cell_, certificate_, *previous, step, previous->to_next,
                                 transitions_->hull_bounds(), transitions_->self_pair_bounds(),
                                 vertex_bound, previous_distance,
                                 distance, ledger_, facts_, where_transition);
    }
    previous_radius = std::move(radius);
    previous_distance = std::move(distance);
    std::swap(previous_placed, placed);
    previous = &step;
    if (step.step == certificate_.collision_step) facts_.collision_step_q = step.q;
  }
  previous_step_index_ = segment.steps.back().step;
}

// proof: proofs/joint-variation.md#corollary-sampled-ends
std::vector<Rational> Checker::piece_variation(const motion::SegmentTrajectory& planned,
                                               const StepCertificate& from,
                                               const StepCertificate& to) const {
  const int joints = robot_.joint_count();
  if (!planned.joint_motion || from.q.size() != joints || to.q.size() != joints) return {};
  return motion::exact_variation_bound_from_samples(*planned.joint_motion,
                                                    piece_time(planned, from.parameter), from.q,
                                                    piece_time(planned, to.parameter), to.q);
}

void Checker::add_segment(const SegmentCertificate& segment) {
  const std::size_t s = segments_added_++;
  if (stopped_) return;
  if (s >= segment_count_) throw std::logic_error("certificate check: more segments than announced");
  if (segment.number != trajectory_->segments()[s].number) {
    ledger_.fail("segment numbers out of order");
    stopped_ = true;
    return;
  }
  check_segment(segment, trajectory_->segments()[s]);
}

void Checker::reject_other_inputs() {
  if (certificate_.inputs.empty() || options_.input_digests.empty()) return;
  std::vector<std::string> differ;
  for (const char* name : {"robot", "environment", "path", "trajectory", "program"}) {
    const auto recorded = certificate_.inputs.find(name);
    const auto given = options_.input_digests.find(name);
    const std::string recorded_digest = recorded == certificate_.inputs.end() ? "" : recorded->second;
    if (given != options_.input_digests.end() && recorded_digest != given->second) {
      differ.push_back(std::string("the ") + name + " file differs from the one certified");
    }
  }
  report_.failures.insert(report_.failures.begin(), differ.begin(), differ.end());
}

CheckReport Checker::finish() {
  if (!concluded_) {
    if (segments_added_ != segment_count_) {
      throw std::logic_error("certificate check: fewer segments than announced");
    }
    check_claim(certificate_, facts_, *cell_, ledger_);
  }
  reject_other_inputs();
  report_.accepted = report_.failures.empty();
  if (!report_.accepted) return report_;  // a rejected certificate proves no clearance
  for (std::size_t link = 0; link < motion_clearances_.size(); ++link) {
    if (!motion_clearances_[link]) continue;
    // mpq_get_d truncates towards zero: rounds this non-negative value down.
    report_.motion_clearances.push_back({static_cast<int>(link),
                                         motion_clearances_[link]->first.get_d(),
                                         motion_clearances_[link]->second});
  }
  return report_;
}

}  // namespace

CheckReport check_certificate(const RobotModel& robot, const Environment& environment,
                              const PathProgram& program,
                              const motion::KinematicsAccess& kinematics,
                              const Certificate& certificate, const CheckOptions& options) {
  Checker checker(robot, environment, program, kinematics, certificate,
                  certificate.segments.size(), options);
  checker.start();
  for (const SegmentCertificate& segment : certificate.segments) checker.add_segment(segment);
  return checker.finish();
}

struct CertificateCheck::Impl {
  Impl(const RobotModel& robot, const Environment& environment, const PathProgram& program,
       const motion::KinematicsAccess& kinematics, Certificate certificate_header,
       std::size_t segment_count, const CheckOptions& options)
      : header(std::move(certificate_header)),
        checker(robot, environment, program, kinematics, header, segment_count, options) {}
  Certificate header;  // the checker refers to it: declared first
  Checker checker;
};

CertificateCheck::CertificateCheck(const RobotModel& robot, const Environment& environment,
                                   const PathProgram& program,
                                   const motion::KinematicsAccess& kinematics,
                                   Certificate header, std::size_t segment_count,
                                   const CheckOptions& options) {
  header.segments.clear();
  impl_ = std::make_unique<Impl>(robot, environment, program, kinematics, std::move(header),
                                 segment_count, options);
  impl_->checker.start();
}

CertificateCheck::~CertificateCheck() = default;

void CertificateCheck::add_segment(const SegmentCertificate& segment) {
  impl_->checker.add_segment(segment);
}

CheckReport CertificateCheck::finish() { return impl_->checker.finish(); }

}  // namespace grpvss::certify

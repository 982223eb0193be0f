#include "grpvss/certify/certificate_checker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <gmpxx.h>

#include "grpvss/certify/cell_probe.hpp"
#include "grpvss/certify/exact_axis_radius.hpp"  // place_points only: the shared placement expression
#include "grpvss/geometry/convex_polytope.hpp"
#include "grpvss/geometry/directed_rounding.hpp"
#include "grpvss/geometry/exact_contact.hpp"
#include "grpvss/geometry/minkowski_offset.hpp"
#include "grpvss/geometry/separation_witness.hpp"
#include "grpvss/kinematics/fk_error_bound.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/motion/cp_line.hpp"
#include "grpvss/motion/trajectory.hpp"

namespace grpvss::certify {
namespace {

using Rational = mpq_class;

Rational exact(double value) { return Rational(value); }

// The checker's own data per link hull: raw vertices, the offset it rebuilds and verifies,
// and the exact axis radii R_{jh} (proofs/motion-bound.md#lemma-axis-radius).
struct CheckedHull {
  int link = 0;
  int hull = 0;
  std::vector<Eigen::Vector3d> raw_L;
  std::vector<Eigen::Vector3d> expanded_L;
  std::vector<Rational> axis_radius;  ///< [joint-1], exact
};

// Axis-aligned box of a point set (min/max of doubles: exact).
struct Box {
  Eigen::Vector3d lo, hi;
};
Box box_of(const std::vector<Eigen::Vector3d>& points) {
  Box box{points.front(), points.front()};
  for (const auto& p : points) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  }
  return box;
}

// x > y + m for doubles x, y, m (m >= 0), decided exactly without big numbers: RD(y + m) and
// RU(y + m) are the doubles around the exact sum (equal when it is a double), so x exceeds it
// iff x > RU, or x == RU with RU != RD (proofs/fast-path.md#directed-rounding, TwoSum).
bool exceeds_sum(double x, double y, double m) {
  const double up = geometry::rounding::nearest_mode_add_up(y, m);
  const double down = geometry::rounding::nearest_mode_add_down(y, m);
  return x > up || (x == up && up != down);
}

// Exact box separation: some axis has a gap > margin between the two boxes.
bool boxes_farther_than(const Box& a, const Box& b, double margin) {
  for (int axis = 0; axis < 3; ++axis) {
    if (exceeds_sum(b.lo[axis], a.hi[axis], margin)) return true;
    if (exceeds_sum(a.lo[axis], b.hi[axis], margin)) return true;
  }
  return false;
}

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
        chain_(kinematics::make_chain(robot)),
        workspace_(robot) {}

  // The check in three parts so that a certificate can be read one segment at a time:
  // start() (header, hulls, trajectory), add_segment() in order, finish() (the claim).
  void start();
  void add_segment(const SegmentCertificate& segment);
  CheckReport finish();

 private:
  void fail(const std::string& message) {
    if (report_.failures.size() < options_.max_failures) report_.failures.push_back(message);
    else if (report_.failures.size() == options_.max_failures) report_.failures.push_back("...");
  }
  bool check_header();
  bool build_hulls();
  void check_segment(const SegmentCertificate& segment, const motion::SegmentTrajectory& planned);
  // Returns the exactly verified radius bound of every hull at this step (claimed radii that
  // exceed what the evidence proves are failures).
  // `placed_raw` receives each hull's raw vertices placed at the step (the chord bound's ends).
  std::vector<Rational> check_step(const StepCertificate& step, const std::string& where,
                                   std::vector<std::vector<Eigen::Vector3d>>& placed_raw);
  /// `joint_linear`: a CP step, where the chord bound may stand in for the joint-sum bound.
  void check_transition(const StepCertificate& from, const StepCertificate& to,
                        const std::vector<Rational>& radius_from,
                        const std::vector<Rational>& radius_to,
                        const std::vector<std::vector<Eigen::Vector3d>>& placed_from,
                        const std::vector<std::vector<Eigen::Vector3d>>& placed_to,
                        bool joint_linear, const std::string& where);
  /// claimed >= max_v |placed_to[v] - placed_from[v]| + 2 placement_error + P_h / 3, exactly
  /// (proofs/motion-bound.md#lemma-joint-linear-chord).
  bool chord_bound_holds(const CheckedHull& hull, const StepCertificate& from,
                         const StepCertificate& to, const std::vector<Eigen::Vector3d>& placed_from,
                         const std::vector<Eigen::Vector3d>& placed_to, double claimed) const;
  void check_claim();

  const RobotModel& robot_;
  const Environment& environment_;
  const PathProgram& program_;
  const motion::KinematicsAccess& kinematics_;
  const Certificate& certificate_;
  std::size_t segment_count_;
  CheckOptions options_;
  kinematics::KinematicChain chain_;
  kinematics::Workspace workspace_;
  std::vector<CheckedHull> hulls_;
  std::vector<std::vector<Eigen::Vector3d>> obstacles_;
  std::vector<Box> obstacle_boxes_;
  std::vector<Eigen::Vector3d> placed_;
  CheckReport report_;
  /// Per link: the smallest exact g over the transitions so far, and the step ending it.
  std::vector<std::optional<std::pair<Rational, int>>> motion_clearance_;
  bool all_transitions_certified_ = true;
  bool any_expanded_interference_ = false;
  bool any_raw_collision_ = false;
  bool coverage_complete_ = true;
  int previous_step_index_ = -1;
  /// The configuration of the last step numbered collision_step (checked by the claim).
  std::optional<Eigen::VectorXd> collision_step_q_;
  std::optional<motion::Trajectory> trajectory_;
  bool stopped_ = false;   ///< the header, hulls or segment order failed: no more checking
  bool concluded_ = false;  ///< stopped before the claim: the report stays as it is
  std::size_t segments_added_ = 0;
};

bool Checker::check_header() {
  bool ok = true;
  if (certificate_.mode != "certified") fail("the certificate's mode is not 'certified'"), ok = false;
  if (!(certificate_.tolerance > 0.0)) fail("tolerance must be > 0"), ok = false;
  // The placement error must cover the FK rounding bound for every coordinate used: the
  // checker measures the largest coordinate of its own offsets below and compares there.
  if (!(exact(certificate_.expansion_radius) >=
        exact(certificate_.tolerance) + 2 * exact(certificate_.placement_error))) {
    fail("expansion_radius < tolerance + 2 placement_error");
    ok = false;
  }
  ++report_.inequalities_checked;
  return ok;
}

bool Checker::build_hulls() {
  const geometry::OffsetShape shape = certificate_.offset_shape == "cube"
                                          ? geometry::OffsetShape::kCube
                                          : geometry::OffsetShape::kRhombicuboctahedron;
  if (certificate_.offset_shape != "cube" && certificate_.offset_shape != "rhombicuboctahedron") {
    fail("unknown offset shape '" + certificate_.offset_shape + "'");
    return false;
  }
  double largest_coordinate = 0.0;
  for (int link = 0; link < static_cast<int>(robot_.links.size()); ++link) {
    for (int hull = 0; hull < static_cast<int>(robot_.links[link].hulls.size()); ++hull) {
      const HullPoints& points = robot_.links[link].hulls[hull];
      const geometry::ConvexPolytope raw = geometry::ConvexPolytope::from_points(points.points);
      const geometry::ConvexPolytope expanded =
          geometry::minkowski_offset(raw, certificate_.expansion_radius, shape);
      // proof: proofs/offset-containment.md#rounded-placement
      ++report_.inequalities_checked;
      if (!geometry::contains_ball_sum_exactly(expanded, raw, certificate_.expansion_radius)) {
        fail("link " + std::to_string(link) + " hull " + std::to_string(hull) +
             ": the offset does not contain the ball sum");
        return false;
      }
      CheckedHull checked;
      checked.link = link;
      checked.hull = hull;
      checked.raw_L = raw.vertices();
      checked.expanded_L = expanded.vertices();
      for (int joint = 1; joint <= link; ++joint) {
        checked.axis_radius.push_back(exact_axis_radius(robot_, link, points, joint));
      }
      for (const auto& p : checked.expanded_L) largest_coordinate = std::max(largest_coordinate, p.cwiseAbs().maxCoeff());
      for (const auto& p : checked.raw_L) largest_coordinate = std::max(largest_coordinate, p.cwiseAbs().maxCoeff());
      hulls_.push_back(std::move(checked));
    }
  }
  // proof: proofs/fk-rounding.md#fk-rounding (the verifier doubles the bound: strictness)
  const double bound = kinematics::forward_kinematics_error_bound(chain_, largest_coordinate);
  ++report_.inequalities_checked;
  if (!(exact(certificate_.placement_error) >= 2 * exact(bound))) {
    fail("placement_error is smaller than twice the forward-kinematics rounding bound");
    return false;
  }
  for (const HullPoints& obstacle : environment_.obstacles) {
    obstacles_.push_back(geometry::ConvexPolytope::from_points(obstacle.points).vertices());
    obstacle_boxes_.push_back(box_of(obstacles_.back()));
  }
  return true;
}

std::vector<Rational> Checker::check_step(const StepCertificate& step, const std::string& where,
                                          std::vector<std::vector<Eigen::Vector3d>>& placed_raw_out) {
  std::vector<Rational> verified(hulls_.size(), Rational(0));
  placed_raw_out.assign(hulls_.size(), {});
  if (step.q.size() != robot_.joint_count()) {
    fail(where + ": wrong joint count");
    return verified;
  }
  if (step.hulls.size() != hulls_.size()) {
    fail(where + ": expected a record for each of the " + std::to_string(hulls_.size()) + " hulls");
    return verified;
  }
  kinematics::forward_kinematics(chain_, step.q, workspace_);
  const Rational delta = exact(certificate_.tolerance);
  const Rational eps = exact(certificate_.placement_error);
  const int obstacle_count = static_cast<int>(obstacles_.size());
  for (std::size_t i = 0; i < hulls_.size(); ++i) {
    const CheckedHull& hull = hulls_[i];
    const HullRecord& record = step.hulls[i];
    const std::string hull_where = where + " link " + std::to_string(hull.link) + " hull " +
                                   std::to_string(hull.hull);
    if (record.link != hull.link || record.hull != hull.hull) {
      fail(hull_where + ": hull records out of order");
      continue;
    }
    const Eigen::Isometry3d& X_WL = workspace_.X_WL[hull.link];
    std::vector<Eigen::Vector3d> placed_expanded, placed_raw;
    place_points(X_WL, hull.expanded_L, placed_expanded);
    place_points(X_WL, hull.raw_L, placed_raw);
    placed_raw_out[i] = placed_raw;
    const Box placed_box = box_of(placed_expanded);
    // Per obstacle: the radius its evidence proves (proofs/two-ball-cover.md#corollary-step).
    std::vector<std::optional<Rational>> expanded_radius(obstacle_count), raw_radius(obstacle_count);
    std::vector<char> expanded_interferes(obstacle_count, 0), raw_collides(obstacle_count, 0);
    bool bad_evidence = false;
    for (const EvidenceRecord& evidence : record.evidence) {
      if (evidence.obstacle < 0 || evidence.obstacle >= obstacle_count) {
        fail(hull_where + ": evidence names an obstacle that does not exist");
        bad_evidence = true;
        continue;
      }
      const auto& placed = evidence.expanded ? placed_expanded : placed_raw;
      if (evidence.separated) {
        ++report_.inequalities_checked;
        if (!geometry::check_witness_exactly(placed, obstacles_[evidence.obstacle], evidence.witness,
                                             evidence.lower_bound) ||
            !(evidence.lower_bound >= 0.0)) {
          fail(hull_where + " obstacle " + std::to_string(evidence.obstacle) +
               ": the separation witness does not hold");
          bad_evidence = true;
          continue;
        }
        if (evidence.expanded) {
          // proof: proofs/offset-containment.md#clearance-through-offset
          expanded_radius[evidence.obstacle] = delta + exact(evidence.lower_bound);
        } else {
          const Rational r = exact(evidence.lower_bound) - eps;
          raw_radius[evidence.obstacle] = r > 0 ? r : Rational(0);
        }
      } else if (evidence.expanded) {
        expanded_interferes[evidence.obstacle] = 1;
        any_expanded_interference_ = true;
      } else {
        raw_collides[evidence.obstacle] = 1;
        any_raw_collision_ = true;
      }
    }
    if (bad_evidence) continue;
    // Every obstacle must be accounted for.
    std::optional<Rational> radius;
    auto lower_to = [&radius](const Rational& r) {
      if (!radius || r < *radius) radius = r;
    };
    bool beyond_margin = false;  // some obstacle is accounted for by the broadphase margin
    for (int o = 0; o < obstacle_count; ++o) {
      if (expanded_radius[o]) {
        lower_to(*expanded_radius[o]);
      } else if (expanded_interferes[o]) {
        if (raw_radius[o]) lower_to(*raw_radius[o]);
        else lower_to(Rational(0));  // raw collision or no raw evidence: nothing proven
      } else if (std::isfinite(record.broadphase_margin) && record.broadphase_margin >= 0.0) {
        ++report_.inequalities_checked;
        if (!boxes_farther_than(placed_box, obstacle_boxes_[o], record.broadphase_margin)) {
          fail(hull_where + " obstacle " + std::to_string(o) +
               ": no evidence and not beyond the broadphase margin");
          lower_to(Rational(0));
        } else {
          beyond_margin = true;
        }
      } else {
        fail(hull_where + " obstacle " + std::to_string(o) + ": no evidence");
        lower_to(Rational(0));
      }
    }
    // No obstacle at all: nothing can be hit, any radius up to the probe's cap is vacuously true.
    // proof: proofs/two-ball-cover.md#corollary-step (obstacles beyond the margin are farther
    // than Delta + margin from every true point of the hull): one bound for all of them.
    if (beyond_margin) lower_to(delta + exact(record.broadphase_margin));
    if (!radius) radius = exact(kUnboundedRadius);
    ++report_.inequalities_checked;
    if (!(exact(record.radius) <= *radius) || record.radius < 0.0) {
      fail(hull_where + ": the claimed radius exceeds what the evidence proves");
      continue;
    }
    verified[i] = exact(record.radius);
  }
  return verified;
}

// proof: proofs/motion-bound.md#lemma-motion-bound, proofs/two-ball-cover.md#corollary-step
void Checker::check_transition(const StepCertificate& from, const StepCertificate& to,
                               const std::vector<Rational>& radius_from,
                               const std::vector<Rational>& radius_to,
                               const std::vector<std::vector<Eigen::Vector3d>>& placed_from,
                               const std::vector<std::vector<Eigen::Vector3d>>& placed_to,
                               bool joint_linear, const std::string& where) {
  const TransitionRecord& claimed = from.to_next;
  // A step with the wrong joint count was already rejected by check_step(); reading its q here
  // would run past the vector (found reviewing for the checker fuzz target, docs/reliability.md).
  if (from.q.size() != robot_.joint_count() || to.q.size() != robot_.joint_count()) {
    all_transitions_certified_ = false;
    return;
  }
  if (claimed.hull_motion_bounds.size() != hulls_.size() ||
      claimed.hull_allowances.size() != hulls_.size() || claimed.governing.size() != hulls_.size()) {
    fail(where + ": the transition record is incomplete");
    all_transitions_certified_ = false;
    return;
  }
  bool certified = true;
  for (std::size_t i = 0; i < hulls_.size(); ++i) {
    const CheckedHull& hull = hulls_[i];
    Rational bound = 0;
    for (int joint = 1; joint <= hull.link; ++joint) {
      const Rational increment = abs(exact(to.q[joint - 1]) - exact(from.q[joint - 1]));
      bound += robot_.joints[joint - 1].type == JointType::kRevolute
                   ? increment * hull.axis_radius[joint - 1]
                   : increment;
    }
    const Rational allowance = radius_from[i] + radius_to[i];
    report_.inequalities_checked += 3;
    const Rational recorded = exact(claimed.hull_motion_bounds[i]);
    if (!(recorded >= bound)) {
      // proof: proofs/motion-bound.md#lemma-joint-linear-chord
      ++report_.inequalities_checked;
      if (joint_linear && placed_from[i].size() == hull.raw_L.size() &&
          placed_to[i].size() == hull.raw_L.size() &&
          chord_bound_holds(hull, from, to, placed_from[i], placed_to[i],
                            claimed.hull_motion_bounds[i])) {
        bound = recorded;  // proven >= every point's path length
      } else {
        fail(where + " hull " + std::to_string(i) +
             (joint_linear ? ": the recorded motion bound is below both the exact bound and the chord bound"
                           : ": the recorded motion bound is below the exact bound"));
        certified = false;
      }
    }
    if (!(exact(claimed.hull_allowances[i]) <= allowance)) {
      fail(where + " hull " + std::to_string(i) + ": the recorded allowance exceeds r_k + r_k+1");
      certified = false;
    }
    if (!(bound <= allowance)) {
      if (claimed.certified) {
        fail(where + " hull " + std::to_string(i) + ": motion bound exceeds the allowance");
      }
      certified = false;
    }
    // proof: proofs/two-ball-cover.md#corollary-motion-clearance
    const Rational balanced = (allowance - bound) / 2;
    const Rational one_sided = std::max(radius_from[i], radius_to[i]) - bound;
    const Rational kept = std::max(Rational(0), std::max(balanced, one_sided));
    auto& smallest = motion_clearance_[static_cast<std::size_t>(hull.link)];
    if (!smallest || kept < smallest->first) smallest = std::make_pair(kept, to.step);
  }
  if (!certified) all_transitions_certified_ = false;
}

bool Checker::chord_bound_holds(const CheckedHull& hull, const StepCertificate& from,
                                const StepCertificate& to,
                                const std::vector<Eigen::Vector3d>& placed_from,
                                const std::vector<Eigen::Vector3d>& placed_to,
                                double claimed) const {
  if (!std::isfinite(claimed)) return false;
  // P_h exactly: sum_m w_m |dq_m| ([m rev] |dq_m| + 2 sum_{j<m rev} |dq_j|).
  Rational curvature = 0;
  Rational revolute_before = 0;
  for (int m = 1; m <= hull.link; ++m) {
    const Rational increment = abs(exact(to.q[m - 1]) - exact(from.q[m - 1]));
    const bool revolute = robot_.joints[m - 1].type == JointType::kRevolute;
    const Rational weight = revolute ? hull.axis_radius[m - 1] : Rational(1);
    curvature += weight * increment * (2 * revolute_before + (revolute ? increment : Rational(0)));
    if (revolute) revolute_before += increment;
  }
  // Each placed point is within placement_error of its exact place (proofs/fk-rounding.md).
  const Rational chord_allowed =
      exact(claimed) - 2 * exact(certificate_.placement_error) - curvature / 3;
  if (chord_allowed < 0) return false;
  const Rational chord_allowed_squared = chord_allowed * chord_allowed;
  for (std::size_t v = 0; v < placed_from.size(); ++v) {
    Rational square = 0;
    for (int k = 0; k < 3; ++k) {
      const Rational d = exact(placed_to[v][k]) - exact(placed_from[v][k]);
      square += d * d;
    }
    if (square > chord_allowed_squared) return false;
  }
  return true;
}

void Checker::check_segment(const SegmentCertificate& segment,
                            const motion::SegmentTrajectory& planned) {
  const std::string where_segment = "segment " + std::to_string(segment.number);
  const bool cp = planned.kind == motion::SegmentKind::kCpLine;
  const double parameter_end = cp ? planned.cp->length() : planned.duration;
  // One step (the segment's start) is what a path stopped at its segment's first proposal
  // writes (e.g. error 7 before any step): its start configuration is still checked, and the
  // coverage test below marks the segment's motion as not covered.
  if (segment.steps.empty()) {
    fail(where_segment + ": no step");
    return;
  }
  if (!(segment.parameter_end == parameter_end) || segment.steps.back().parameter != parameter_end ||
      segment.steps.front().parameter != 0.0) {
    coverage_complete_ = false;  // fine for a path stopped by an error; not for a safety claim
  }
  std::vector<Rational> previous_radius;
  std::vector<std::vector<Eigen::Vector3d>> previous_placed, placed;
  const StepCertificate* previous = nullptr;
  for (std::size_t k = 0; k < segment.steps.size(); ++k) {
    const StepCertificate& step = segment.steps[k];
    const std::string where = where_segment + " step " + std::to_string(step.step);
    // Consecutive global step numbers (a removed step is a gap); the first step of a segment
    // repeats the previous segment's last.
    const int expected_index = k == 0 ? (previous_step_index_ < 0 ? 0 : previous_step_index_)
                                      : previous->step + 1;
    if (step.step != expected_index) fail(where + ": step numbers are not consecutive");
    // The configuration must be the trajectory's own at this parameter.
    std::optional<Eigen::VectorXd> expected;
    if (k == 0) expected = planned.q_start;
    else if (step.parameter == parameter_end) expected = planned.q_end;
    else if (!cp) expected = planned.ptp->joints_at(step.parameter);
    else expected = motion::solve_within_limits(robot_, kinematics_, planned.cp->pose_at(step.parameter), previous->q);
    if (previous != nullptr && !(step.parameter > previous->parameter)) {
      fail(where + ": parameters must increase");
    }
    ++report_.inequalities_checked;
    if (!expected || expected->size() != step.q.size() || *expected != step.q) {
      fail(where + ": the configuration is not the trajectory's at this parameter");
    }
    std::vector<Rational> radius = check_step(step, where, placed);
    if (previous != nullptr) {
      check_transition(*previous, step, previous_radius, radius, previous_placed, placed, cp,
                       where_segment + " steps " + std::to_string(previous->step) + "-" +
                           std::to_string(step.step));
    }
    previous_radius = std::move(radius);
    std::swap(previous_placed, placed);
    previous = &step;
    if (step.step == certificate_.collision_step) collision_step_q_ = step.q;
  }
  previous_step_index_ = segment.steps.back().step;
}

void Checker::check_claim() {
  const std::string& claim = certificate_.claim;
  const bool safety_claim = claim == "CLEAR" || claim == "WITHIN_TOLERANCE";
  if (safety_claim && !coverage_complete_) fail("claim " + claim + ", but the steps do not cover the whole path");
  if (claim == "CLEAR") {
    if (!all_transitions_certified_) fail("claim CLEAR, but some transition is not certified");
    if (any_expanded_interference_) fail("claim CLEAR, but the expanded robot interferes");
    if (any_raw_collision_) fail("claim CLEAR, but the robot collides");
    if (!certificate_.errors.empty()) fail("claim CLEAR, but the path has errors");
  } else if (claim == "WITHIN_TOLERANCE") {
    if (!all_transitions_certified_) fail("claim WITHIN_TOLERANCE, but some transition is not certified");
    if (any_raw_collision_) fail("claim WITHIN_TOLERANCE, but the robot collides");
    if (!any_expanded_interference_) fail("claim WITHIN_TOLERANCE, but nothing interferes");
  } else if (claim == "COLLISION") {
    // The colliding configuration is re-decided exactly from scratch.
    bool proven = false;
    // A wrong joint count at that step was already rejected; it proves nothing here.
    if (collision_step_q_ && collision_step_q_->size() == robot_.joint_count()) {
      kinematics::forward_kinematics(chain_, *collision_step_q_, workspace_);
      for (const CheckedHull& hull : hulls_) {
        place_points(workspace_.X_WL[hull.link], hull.raw_L, placed_);
        for (const auto& obstacle : obstacles_) {
          ++report_.inequalities_checked;
          if (geometry::classify_exact(placed_, obstacle) != geometry::Contact::kSeparated) proven = true;
          if (proven) break;
        }
        if (proven) break;
      }
    }
    if (!proven) fail("claim COLLISION, but the robot at the named step touches no obstacle");
  } else if (claim != "UNDECIDED" && claim != "ERROR") {
    fail("unknown claim '" + claim + "'");
  }
}

void Checker::start() {
  report_.claim = certificate_.claim;
  motion_clearance_.assign(robot_.links.size(), std::nullopt);
  if (!check_header() || !build_hulls()) {
    stopped_ = concluded_ = true;
    return;
  }
  motion::TrajectoryOptions trajectory_options;
  trajectory_options.timing = certificate_.timing == "synchronized" ? motion::PtpTiming::kSynchronized
                                                                     : motion::PtpTiming::kIndependent;
  trajectory_options.cp_speed = certificate_.cp_speed;
  trajectory_options.table = options_.profile_table;
  trajectory_ = motion::Trajectory::plan(robot_, program_, kinematics_, trajectory_options);
  if (segment_count_ != trajectory_->segments().size() || !trajectory_->errors().empty()) {
    coverage_complete_ = false;
  }
  // Step 0 is the robot's home configuration (the path's start), known from the inputs: a
  // collision there is re-decided even when no segment was simulated (the path stopped at its
  // first segment, e.g. error 5), where no segment certificate names step 0.
  if (certificate_.collision_step == 0) collision_step_q_ = trajectory_->home();
  if (segment_count_ > trajectory_->segments().size()) stopped_ = concluded_ = true;
}

void Checker::add_segment(const SegmentCertificate& segment) {
  const std::size_t s = segments_added_++;
  if (stopped_) return;
  if (s >= segment_count_) throw std::logic_error("certificate check: more segments than announced");
  if (segment.number != trajectory_->segments()[s].number) {
    fail("segment numbers out of order");
    stopped_ = true;
    return;
  }
  check_segment(segment, trajectory_->segments()[s]);
}

CheckReport Checker::finish() {
  if (concluded_) return report_;
  if (segments_added_ != segment_count_) {
    throw std::logic_error("certificate check: fewer segments than announced");
  }
  check_claim();
  report_.accepted = report_.failures.empty();
  if (report_.accepted) {
    for (std::size_t link = 0; link < motion_clearance_.size(); ++link) {
      if (!motion_clearance_[link]) continue;
      // mpq_get_d truncates towards zero: rounds this non-negative value down.
      report_.motion_clearances.push_back({static_cast<int>(link),
                                           motion_clearance_[link]->first.get_d(),
                                           motion_clearance_[link]->second});
    }
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

#include "grpvss/motion/joint_limit_check.hpp"

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "enclosing_interval.hpp"
#include "exact_number_traits.hpp"
#include "quadratic_surd.hpp"

namespace grpvss::motion {
namespace {

using detail::ExactPiece;
using detail::PiecePolynomial;
using detail::QuadraticSurd;
using Polynomial = PiecePolynomial<mpq_class>;

/// A point of the piece where a limit is exceeded: its parameter s (for messages), the
/// value there and by how much it exceeds the limit (both rounded, for choosing the worst).
struct Excursion {
  LimitKind kind = LimitKind::kAboveUpper;
  double s = 0.0;
  double value = 0.0;
  double excess = 0.0;
  double limit = 0.0;
};

void keep_worst(std::optional<Excursion>& worst, const Excursion& candidate) {
  if (!worst || candidate.excess > worst->excess) worst = candidate;
}

/// Parameters in [0, 1] where q can be extreme: 0, 1 and the roots of dq/ds =
/// c1 + 2 c2 s + 3 c3 s^2 strictly inside (0, 1) where it changes sign.
/// proof: proofs/joint-variation.md#lemma-position-limits
std::vector<QuadraticSurd> extremum_candidates(const Polynomial& p) {
  mpq_class d = 0;  // stays 0 unless the roots are (possibly) irrational
  std::vector<QuadraticSurd> roots;
  if (sgn(p.c3) != 0) {
    const mpq_class discriminant = p.c2 * p.c2 - 3 * p.c1 * p.c3;
    if (sgn(discriminant) > 0) {
      d = discriminant;
      const mpq_class scale = 1 / (3 * p.c3);
      roots.push_back({-p.c2 * scale, scale, d});
      roots.push_back({-p.c2 * scale, -scale, d});
    }
  } else if (sgn(p.c2) != 0) {
    roots.push_back(QuadraticSurd::rational(-p.c1 / (2 * p.c2), d));
  }
  std::vector<QuadraticSurd> candidates = {QuadraticSurd::rational(0, d),
                                           QuadraticSurd::rational(1, d)};
  const QuadraticSurd one = QuadraticSurd::rational(1, d);
  for (const QuadraticSurd& r : roots) {
    if (sign(r) > 0 && sign(one - r) > 0) candidates.push_back(r);
  }
  return candidates;
}

QuadraticSurd value_at(const Polynomial& p, const QuadraticSurd& s) {
  const auto rational = [&s](const mpq_class& x) { return QuadraticSurd::rational(x, s.d); };
  QuadraticSurd v = rational(p.c3);
  v = v * s + rational(p.c2);
  v = v * s + rational(p.c1);
  return v * s + rational(p.c0);
}

std::optional<Excursion> position_excursion(const Polynomial& p, double lower, double upper) {
  std::optional<Excursion> worst;
  for (const QuadraticSurd& s : extremum_candidates(p)) {
    const QuadraticSurd q = value_at(p, s);
    const double value = q.approximate();
    if (sign(q - QuadraticSurd::rational(mpq_class(upper), s.d)) > 0) {
      keep_worst(worst, {LimitKind::kAboveUpper, s.approximate(), value, value - upper, upper});
    }
    if (sign(q - QuadraticSurd::rational(mpq_class(lower), s.d)) < 0) {
      keep_worst(worst, {LimitKind::kBelowLower, s.approximate(), value, lower - value, lower});
    }
  }
  return worst;
}

/// dq/dt = (c1 + 2 c2 s + 3 c3 s^2) / h is extreme at s = 0, 1 or the vertex -c2 / (3 c3).
/// proof: proofs/joint-variation.md#lemma-velocity-limits
std::optional<Excursion> speed_excursion(const Polynomial& p, const mpq_class& h, double max_speed) {
  if (std::isinf(max_speed)) return std::nullopt;
  std::vector<mpq_class> candidates = {0, 1};
  if (sgn(p.c3) != 0) {
    const mpq_class vertex = -p.c2 / (3 * p.c3);
    if (sgn(vertex) > 0 && vertex < 1) candidates.push_back(vertex);
  }
  std::optional<Excursion> worst;
  for (const mpq_class& s : candidates) {
    const mpq_class rate = p.slope(s) / h;
    if (abs(rate) > mpq_class(max_speed)) {
      const double value = detail::nearest_double(rate);
      keep_worst(worst, {LimitKind::kOverSpeed, detail::nearest_double(s), value, std::fabs(value) - max_speed, max_speed});
    }
  }
  return worst;
}

double time_at(const std::vector<double>& times, int k, double s) {
  if (s <= 0.0) return times[k];
  if (s >= 1.0) return times[k + 1];
  return times[k] + s * (times[k + 1] - times[k]);
}

void validate(const JointTrajectoryMotion& motion, const JointLimits& limits) {
  const Eigen::Index joints = motion.joint_count();
  if (limits.lower.size() != joints || limits.upper.size() != joints ||
      limits.max_speed.size() != joints) {
    throw std::invalid_argument("first_limit_violation: limits need one entry per joint");
  }
  for (Eigen::Index j = 0; j < joints; ++j) {
    if (!(limits.lower[j] <= limits.upper[j]) || !(limits.max_speed[j] >= 0.0)) {
      throw std::invalid_argument("first_limit_violation: lower <= upper and speed >= 0 per joint");
    }
  }
}

LimitViolation violation_of(const JointTrajectoryMotion& motion, int k, int j, const Excursion& e) {
  const std::vector<double>& times = motion.piece_breaks();
  return {j, motion.trajectory().joint_names[j], e.kind, k,
          k < 0 ? times[0] : time_at(times, k, e.s), e.value, e.limit};
}

/// True when the Bezier control points of piece k of joint j, rounded outwards, lie within the
/// position limits and their differences within the speed limit: q is a convex combination of
/// its control points and dq/dt of 3 d_i / h, so the piece is within the limits. A fast
/// sufficient test; when it fails the exact test decides. Needs round-to-nearest.
/// proof: proofs/joint-variation.md#lemma-position-limits (control-point hull)
bool control_points_within_limits(const JointTrajectory& trajectory, int k, int j,
                                  const JointLimits& limits) {
  using detail::Interval;
  const Interval h = detail::NumberTraits<Interval>::difference(trajectory.times[k + 1], trajectory.times[k]);
  const Interval p0 = Interval::point(trajectory.positions[k][j]);
  const Interval p1 = Interval::point(trajectory.positions[k + 1][j]);
  Interval b1 = p0 + detail::divided(p1 - p0, 3.0), b2 = p1 - detail::divided(p1 - p0, 3.0);
  if (trajectory.has_velocities()) {
    b1 = p0 + detail::divided(h * Interval::point(trajectory.velocities[k][j]), 3.0);
    b2 = p1 - detail::divided(h * Interval::point(trajectory.velocities[k + 1][j]), 3.0);
  }
  const Interval control[4] = {p0, b1, b2, p1};
  double largest_step = 0.0;
  for (int i = 0; i < 4; ++i) {
    if (control[i].lo < limits.lower[j] || control[i].hi > limits.upper[j]) return false;
    if (i > 0) largest_step = std::max(largest_step, detail::magnitude_up(control[i] - control[i - 1]));
  }
  if (std::isinf(limits.max_speed[j])) return true;
  const double speed_up = detail::next_up(detail::next_up(3.0 * largest_step) / h.lo);
  return speed_up <= limits.max_speed[j];
}

/// The earliest worst point among the joints' violations on piece k (nullopt if none).
std::optional<LimitViolation> piece_violation(const JointTrajectoryMotion& motion, int k,
                                              const JointLimits& limits) {
  std::optional<LimitViolation> first;
  const bool nearest = std::fegetround() == FE_TONEAREST;
  for (int j = 0; j < motion.joint_count(); ++j) {
    if (nearest && control_points_within_limits(motion.trajectory(), k, j, limits)) continue;
    const ExactPiece piece(motion.trajectory(), k, j);
    const mpq_class h = mpq_class(motion.piece_breaks()[k + 1]) - mpq_class(motion.piece_breaks()[k]);
    for (const auto& excursion :
         {position_excursion(piece.polynomial(), limits.lower[j], limits.upper[j]),
          speed_excursion(piece.polynomial(), h, limits.max_speed[j])}) {
      if (!excursion) continue;
      const LimitViolation violation = violation_of(motion, k, j, *excursion);
      if (!first || violation.time < first->time) first = violation;
    }
  }
  return first;
}

/// A trajectory of one waypoint: its positions and (given) velocities.
std::optional<LimitViolation> waypoint_violation(const JointTrajectoryMotion& motion,
                                                 const JointLimits& limits) {
  const JointTrajectory& trajectory = motion.trajectory();
  for (int j = 0; j < motion.joint_count(); ++j) {
    const double q = trajectory.positions[0][j];
    const double v = trajectory.has_velocities() ? trajectory.velocities[0][j] : 0.0;
    if (q > limits.upper[j]) return violation_of(motion, -1, j, {LimitKind::kAboveUpper, 0, q, 0, limits.upper[j]});
    if (q < limits.lower[j]) return violation_of(motion, -1, j, {LimitKind::kBelowLower, 0, q, 0, limits.lower[j]});
    if (std::fabs(v) > limits.max_speed[j]) {
      return violation_of(motion, -1, j, {LimitKind::kOverSpeed, 0, v, 0, limits.max_speed[j]});
    }
  }
  return std::nullopt;
}

const char* kind_text(LimitKind kind) {
  switch (kind) {
    case LimitKind::kBelowLower: return "below its lower position limit";
    case LimitKind::kAboveUpper: return "above its upper position limit";
    case LimitKind::kOverSpeed: return "faster than its speed limit";
  }
  return "";
}

}  // namespace

JointLimits position_limits_of(const RobotModel& robot) {
  const int joints = robot.joint_count();
  JointLimits limits{Eigen::VectorXd(joints), Eigen::VectorXd(joints),
                     Eigen::VectorXd::Constant(joints, std::numeric_limits<double>::infinity())};
  for (int j = 0; j < joints; ++j) {
    limits.lower[j] = robot.joints[j].minimum;
    limits.upper[j] = robot.joints[j].maximum;
  }
  return limits;
}

JointLimits joint_limits_of(const RobotModel& robot) {
  JointLimits limits = position_limits_of(robot);
  for (int j = 0; j < robot.joint_count(); ++j) limits.max_speed[j] = robot.joints[j].max_velocity;
  return limits;
}

std::optional<LimitViolation> first_limit_violation(const JointTrajectoryMotion& motion,
                                                    const JointLimits& limits) {
  validate(motion, limits);
  if (motion.piece_count() == 0) return waypoint_violation(motion, limits);
  for (int k = 0; k < motion.piece_count(); ++k) {
    if (auto violation = piece_violation(motion, k, limits)) return violation;
  }
  return std::nullopt;
}

std::string describe(const LimitViolation& violation, const JointTrajectory& trajectory) {
  std::string text = fmt::format("joint '{}' ({}) is {} {} at t = {} s: {}", violation.joint_name,
                                 violation.joint + 1, kind_text(violation.kind), violation.limit,
                                 violation.time, violation.value);
  if (violation.piece >= 0) {
    text += fmt::format(" (piece {}, between {} and {})", violation.piece + 1,
                        describe_waypoint(trajectory, violation.piece),
                        describe_waypoint(trajectory, violation.piece + 1));
  }
  return text;
}

}  // namespace grpvss::motion

#include "grpvss/motion/joint_trajectory_motion.hpp"

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <stdexcept>
#include <string>

#include "enclosing_interval.hpp"
#include "hermite_piece.hpp"
#include "joint_trajectory_pieces.hpp"
#include "variation_arithmetic.hpp"

namespace grpvss::motion {
namespace {

using detail::Interval;

/// The largest magnitude of a trajectory number (the readers' limit), which keeps every
/// interval computation far from overflow.
constexpr double kMaxMagnitude = 1e9;

bool is_bounded(double x) { return std::fabs(x) <= kMaxMagnitude; }

void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("JointTrajectoryMotion: " + message);
}

void validate_vectors(const std::vector<Eigen::VectorXd>& vectors, int joints, const char* what) {
  for (const Eigen::VectorXd& v : vectors) {
    require(v.size() == joints, std::string(what) + " with one value per joint");
    require(v.unaryExpr([](double x) { return is_bounded(x) ? 0.0 : 1.0; }).sum() == 0.0,
            std::string(what) + " finite and of magnitude at most 1e9");
  }
}

void validate_trajectory(const JointTrajectory& trajectory) {
  const int waypoints = trajectory.waypoint_count();
  require(waypoints >= 1, "at least one waypoint");
  require(trajectory.joint_count() >= 1, "at least one joint");
  require(static_cast<int>(trajectory.positions.size()) == waypoints, "positions for every waypoint");
  require(trajectory.velocities.empty() || static_cast<int>(trajectory.velocities.size()) == waypoints,
          "velocities for every waypoint or for none");
  for (int k = 0; k < waypoints; ++k) {
    const double t = trajectory.times[k];
    require(t >= 0.0 && is_bounded(t), "times >= 0 and at most 1e9");
    require(k == 0 || t > trajectory.times[k - 1], "strictly increasing times");
  }
  validate_vectors(trajectory.positions, trajectory.joint_count(), "positions");
  validate_vectors(trajectory.velocities, trajectory.joint_count(), "velocities");
}

/// Double evaluation of the Hermite basis (exact at s = 0 and s = 1).
double hermite_value(double s, double h, double p0, double p1, double m0, double m1) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * m0 + (-2 * s3 + 3 * s2) * p1 +
         (s3 - s2) * h * m1;
}
double hermite_rate(double s, double h, double p0, double p1, double m0, double m1) {
  return 6 * s * (s - 1) * (p0 - p1) / h + (3 * s * s - 4 * s + 1) * m0 + (3 * s * s - 2 * s) * m1;
}

void check_round_to_nearest() {
  if (std::fegetround() != FE_TONEAREST) {
    throw std::logic_error("JointTrajectoryMotion: evaluation needs the round-to-nearest mode");
  }
}

}  // namespace

JointTrajectoryMotion::JointTrajectoryMotion(JointTrajectory trajectory)
    : trajectory_(std::move(trajectory)) {
  validate_trajectory(trajectory_);
  interpolation_ = trajectory_.has_velocities() ? JointInterpolation::kCubicHermite
                                                : JointInterpolation::kLinear;
}

double JointTrajectoryMotion::velocity(int k, int j) const {
  return trajectory_.has_velocities() ? trajectory_.velocities[k][j] : 0.0;
}

void JointTrajectoryMotion::check_time(double t, const char* what) const {
  if (!(t >= start_time() && t <= end_time())) {
    throw std::out_of_range(std::string("JointTrajectoryMotion::") + what + ": time " +
                            std::to_string(t) + " s outside [" + std::to_string(start_time()) +
                            ", " + std::to_string(end_time()) + "]");
  }
}

int JointTrajectoryMotion::piece_at(double t) const {
  if (piece_count() == 0) return -1;
  const auto& times = trajectory_.times;
  const auto after = std::upper_bound(times.begin(), times.end(), t);
  const int k = static_cast<int>(after - times.begin()) - 1;
  return std::clamp(k, 0, piece_count() - 1);
}

Eigen::VectorXd JointTrajectoryMotion::q_at(double t) const {
  check_time(t, "q_at");
  const int k = piece_at(t);
  if (k < 0 || t == trajectory_.times[k]) return trajectory_.positions[std::max(k, 0)];
  if (t == trajectory_.times[k + 1]) return trajectory_.positions[k + 1];
  const double h = trajectory_.times[k + 1] - trajectory_.times[k];
  const double s = (t - trajectory_.times[k]) / h;
  Eigen::VectorXd q(joint_count());
  for (int j = 0; j < joint_count(); ++j) {
    const double p0 = position(k, j), p1 = position(k + 1, j);
    q[j] = interpolation_ == JointInterpolation::kLinear
               ? (1 - s) * p0 + s * p1
               : hermite_value(s, h, p0, p1, velocity(k, j), velocity(k + 1, j));
  }
  return q;
}

Eigen::VectorXd JointTrajectoryMotion::qdot_at(double t) const {
  check_time(t, "qdot_at");
  const int k = piece_at(t);
  if (k < 0) return trajectory_.has_velocities() ? trajectory_.velocities[0]
                                                 : Eigen::VectorXd::Zero(joint_count());
  const double h = trajectory_.times[k + 1] - trajectory_.times[k];
  const double s = std::clamp((t - trajectory_.times[k]) / h, 0.0, 1.0);
  Eigen::VectorXd rate(joint_count());
  for (int j = 0; j < joint_count(); ++j) {
    const double p0 = position(k, j), p1 = position(k + 1, j);
    rate[j] = interpolation_ == JointInterpolation::kLinear
                  ? (p1 - p0) / h
                  : hermite_rate(s, h, p0, p1, velocity(k, j), velocity(k + 1, j));
  }
  // Exactly the given velocities at the waypoints.
  if (trajectory_.has_velocities() && t == trajectory_.times[k]) return trajectory_.velocities[k];
  if (trajectory_.has_velocities() && t == trajectory_.times[k + 1]) return trajectory_.velocities[k + 1];
  return rate;
}

JointIntervals JointTrajectoryMotion::q_enclosure_at(double t) const {
  check_time(t, "q_enclosure_at");
  check_round_to_nearest();
  JointIntervals result{Eigen::VectorXd(joint_count()), Eigen::VectorXd(joint_count())};
  const int k = piece_at(t);
  for (int j = 0; j < joint_count(); ++j) {
    Interval q = Interval::point(trajectory_.positions[std::max(k, 0)][j]);
    if (k >= 0) {
      const detail::IntervalPiece piece(trajectory_, k, j);
      q = piece.end_at(t).q;
    }
    result.lower[j] = q.lo;
    result.upper[j] = q.hi;
  }
  return result;
}

Eigen::VectorXd JointTrajectoryMotion::variation_bound(double t0, double t1) const {
  check_time(t0, "variation_bound");
  check_time(t1, "variation_bound");
  if (t0 > t1) throw std::invalid_argument("JointTrajectoryMotion::variation_bound: t0 > t1");
  check_round_to_nearest();
  Eigen::VectorXd bound = Eigen::VectorXd::Zero(joint_count());
  if (piece_count() == 0) return bound;
  const auto& times = trajectory_.times;
  // proof: proofs/joint-variation.md#corollary-interval-variation
  for (int k = piece_at(t0); k < piece_count() && times[k] < t1; ++k) {
    const double a = std::max(t0, times[k]), b = std::min(t1, times[k + 1]);
    if (!(a < b)) continue;
    for (int j = 0; j < joint_count(); ++j) {
      const detail::IntervalPiece piece(trajectory_, k, j);
      const std::vector<double> breaks = detail::part_breaks(trajectory_, k, j, a, b);
      for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        const double part_bound = detail::piece_variation<detail::IntervalArithmetic>(
            piece.polynomial(), piece.end_at(breaks[i]), piece.end_at(breaks[i + 1]));
        bound[j] = detail::sum_up(bound[j], part_bound);
      }
    }
  }
  return bound;
}

Eigen::VectorXd JointTrajectoryMotion::variation_bound_from_samples(double t0, double t1) const {
  Eigen::VectorXd bound = variation_bound(t0, t1);
  // proof: proofs/joint-variation.md#corollary-sampled-ends
  for (const double t : {t0, t1}) {
    const Eigen::VectorXd sample = q_at(t);
    const JointIntervals exact = q_enclosure_at(t);
    for (int j = 0; j < joint_count(); ++j) {
      const Interval offset = Interval::point(sample[j]) - Interval{exact.lower[j], exact.upper[j]};
      bound[j] = detail::sum_up(bound[j], detail::magnitude_up(offset));
    }
  }
  return bound;
}

}  // namespace grpvss::motion

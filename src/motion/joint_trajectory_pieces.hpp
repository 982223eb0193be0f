#pragma once
// Piece k of joint j of a JointTrajectory as a PiecePolynomial over a number type, and its
// ends at given times. NumberTraits<Number> converts the stored doubles: exactly (mpq_class,
// defined in exact_joint_variation.cpp) or as enclosing intervals (Interval, below).
#include <algorithm>
#include <cmath>
#include <vector>

#include "enclosing_interval.hpp"
#include "grpvss/model/joint_trajectory.hpp"
#include "hermite_piece.hpp"

namespace grpvss::motion::detail {

template <class Number>
struct NumberTraits;

template <>
struct NumberTraits<Interval> {
  static Interval from(double x) { return Interval::point(x); }
  /// Encloses a - b.
  static Interval difference(double a, double b) { return {sum_down(a, -b), sum_up(a, -b)}; }
  /// Encloses n / d for 0 <= n <= d, d > 0 (a normalised parameter in [0, 1]).
  static Interval unit_ratio(const Interval& n, const Interval& d) {
    const double lo = n.lo <= 0.0 ? 0.0 : next_down(n.lo / d.hi);
    const double hi = next_up(n.hi / d.lo);
    return clamped_to_unit({lo, hi});
  }
};

template <class Number>
class TrajectoryPiece {
 public:
  using Traits = NumberTraits<Number>;

  TrajectoryPiece(const JointTrajectory& trajectory, int k, int j)
      : t_start_(trajectory.times[k]), t_end_(trajectory.times[k + 1]),
        h_(Traits::difference(t_end_, t_start_)) {
    const Number p0 = Traits::from(trajectory.positions[k][j]);
    const Number p1 = Traits::from(trajectory.positions[k + 1][j]);
    if (trajectory.has_velocities()) {
      const Number m0 = Traits::from(trajectory.velocities[k][j]);
      const Number m1 = Traits::from(trajectory.velocities[k + 1][j]);
      polynomial_ = hermite_polynomial(h_, p0, p1, m0, m1);
      slope_at_end_ = h_ * m1;
    } else {
      polynomial_ = linear_polynomial(p0, p1);
      slope_at_end_ = polynomial_.c1;
    }
    q_start_ = p0;
    q_end_ = p1;
  }

  const PiecePolynomial<Number>& polynomial() const { return polynomial_; }

  /// s, q and dq/ds at time t in [t_k, t_{k+1}]: the stored data at the waypoints, the
  /// polynomial in between.
  PieceEnd<Number> end_at(double t) const {
    if (t == t_start_) return {Traits::from(0.0), q_start_, polynomial_.c1};
    if (t == t_end_) return {Traits::from(1.0), q_end_, slope_at_end_};
    const Number s = Traits::unit_ratio(Traits::difference(t, t_start_), h_);
    return evaluate_end(polynomial_, s);
  }

 private:
  double t_start_, t_end_;
  Number h_;
  PiecePolynomial<Number> polynomial_;
  Number q_start_, q_end_, slope_at_end_;
};

using IntervalPiece = TrajectoryPiece<Interval>;

/// Times where joint j's piece k probably has an extremum: the roots of dq/ds computed in
/// double (a proposal; any split points are sound). The rounded and the exact bounds split at
/// exactly these doubles, so they stay comparable (proofs/joint-variation.md#rounded-evaluation).
inline std::vector<double> proposed_extremum_times(const JointTrajectory& trajectory, int k, int j) {
  if (!trajectory.has_velocities()) return {};
  const double t0 = trajectory.times[k], h = trajectory.times[k + 1] - t0;
  const double p0 = trajectory.positions[k][j], p1 = trajectory.positions[k + 1][j];
  const double c1 = h * trajectory.velocities[k][j], h_m1 = h * trajectory.velocities[k + 1][j];
  const double c2 = 3 * (p1 - p0) - 2 * c1 - h_m1, c3 = 2 * (p0 - p1) + c1 + h_m1;
  // dq/ds = c1 + 2 c2 s + 3 c3 s^2; the stable quadratic formula.
  std::vector<double> roots;
  if (c3 == 0.0) {
    if (c2 != 0.0) roots.push_back(-c1 / (2 * c2));
  } else {
    const double discriminant = c2 * c2 - 3 * c1 * c3;
    if (discriminant > 0.0) {
      const double q = -(c2 + std::copysign(std::sqrt(discriminant), c2));
      roots.push_back(q / (3 * c3));
      if (q != 0.0) roots.push_back(c1 / q);
    }
  }
  std::vector<double> times;
  for (const double s : roots) {
    if (std::isfinite(s) && s > 0.0 && s < 1.0) times.push_back(t0 + s * h);
  }
  std::sort(times.begin(), times.end());
  return times;
}

/// [a, b] cut at the proposed extremum times strictly inside it: a, (tau...), b.
/// proof: proofs/joint-variation.md#theorem-piece-variation
inline std::vector<double> part_breaks(const JointTrajectory& trajectory, int k, int j, double a, double b) {
  std::vector<double> breaks = {a};
  for (const double tau : proposed_extremum_times(trajectory, k, j)) {
    if (tau > breaks.back() && tau < b) breaks.push_back(tau);
  }
  breaks.push_back(b);
  return breaks;
}

}  // namespace grpvss::motion::detail

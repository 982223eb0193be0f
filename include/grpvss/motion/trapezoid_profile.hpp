#pragma once
/// \file
/// \brief The thesis's ideal per-joint PTP motion-time profile (Section 1.1.2.1.1,
/// Eq. 1-4..1-9): accelerate at a_m, cruise at v_m, decelerate at d_m; a triangle (no cruise)
/// when the increment is too short to reach v_m.

namespace grpvss::motion {

/// \brief Position and velocity of one joint at one instant (rad or length, per second).
struct JointState {
  double position = 0.0;
  double velocity = 0.0;
};

/// \brief Trapezoid (or triangle) profile of one joint from q_s to q_f, in either direction.
///
/// With \f$D = |q_f - q_s|\f$ the peak speed is
/// \f[ v = \min\Big(v_m,\ \sqrt{2D / (1/a_m + 1/d_m)}\Big), \f]
/// so the profile is a triangle exactly when \f$D < \tfrac{v_m^2}{2}(1/a_m + 1/d_m)\f$.
/// (The thesis prints this threshold as \f$\tfrac{v_m}{2}(\ldots)\f$, which is not even
/// dimensionally a length; its peak formula, used here, fixes the reading.)
/// Phases: \f$t_1 = v/a_m\f$, cruise \f$t_c = (D - v^2/2a_m - v^2/2d_m)/v\f$,
/// \f$t_2 = t_1 + t_c\f$, \f$t_f = t_2 + v/d_m\f$. A zero increment has duration 0.
/// The thesis writes d_m as a signed (negative) value in Eq. 1-4; here it is a magnitude.
class TrapezoidProfile {
 public:
  /// \pre v_m, a_m, d_m > 0 and finite (std::invalid_argument otherwise).
  static TrapezoidProfile plan(double q_s, double q_f, double v_m, double a_m, double d_m);

  /// Position and velocity at time t after the start; t is clamped to [0, duration()].
  JointState at(double t) const;
  /// Acceleration at time t (signed, in the direction of motion); 0 outside (0, duration()).
  double acceleration(double t) const;

  double duration() const { return t_f_; }
  double peak_speed() const { return v_; }   ///< |velocity| in the cruise (or at the apex)
  bool is_triangle() const { return t_2_ == t_1_; }
  double start() const { return q_s_; }
  double finish() const { return q_f_; }

 private:
  double q_s_ = 0.0, q_f_ = 0.0;
  double sign_ = 1.0;     // direction of motion
  double a_ = 1.0, d_ = 1.0, v_ = 0.0;
  double t_1_ = 0.0, t_2_ = 0.0, t_f_ = 0.0;
};

}  // namespace grpvss::motion

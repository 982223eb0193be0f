#include "grpvss/motion/trapezoid_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace grpvss::motion {
namespace {

bool positive_finite(double x) { return std::isfinite(x) && x > 0.0; }

}  // namespace

TrapezoidProfile TrapezoidProfile::plan(double q_s, double q_f, double v_m, double a_m,
                                        double d_m) {
  if (!positive_finite(v_m) || !positive_finite(a_m) || !positive_finite(d_m) ||
      !std::isfinite(q_s) || !std::isfinite(q_f)) {
    throw std::invalid_argument("TrapezoidProfile: v_m, a_m, d_m must be positive and finite");
  }
  TrapezoidProfile profile;
  profile.q_s_ = q_s;
  profile.q_f_ = q_f;
  profile.a_ = a_m;
  profile.d_ = d_m;
  const double distance = std::abs(q_f - q_s);
  if (distance == 0.0) return profile;  // duration 0: the joint does not move
  profile.sign_ = q_f >= q_s ? 1.0 : -1.0;
  // Peak speed (Eq. 1-7..1-9 for the triangle): D = v^2/(2a) + v^2/(2d) when no cruise.
  const double v_apex = std::sqrt(2.0 * distance / (1.0 / a_m + 1.0 / d_m));
  profile.v_ = std::min(v_m, v_apex);
  profile.t_1_ = profile.v_ / a_m;
  const double ramps = profile.v_ * profile.v_ * 0.5 * (1.0 / a_m + 1.0 / d_m);
  const double cruise = profile.v_ < v_m ? 0.0 : std::max(0.0, (distance - ramps) / profile.v_);
  profile.t_2_ = profile.t_1_ + cruise;
  profile.t_f_ = profile.t_2_ + profile.v_ / d_m;
  return profile;
}

JointState TrapezoidProfile::at(double t) const {
  if (t_f_ == 0.0) return {q_s_, 0.0};
  if (t >= t_f_) return {q_f_, 0.0};
  t = std::max(t, 0.0);
  double travelled = 0.0;
  double speed = 0.0;
  if (t <= t_1_) {  // Eq. 1-4 first line
    travelled = 0.5 * a_ * t * t;
    speed = a_ * t;
  } else if (t <= t_2_) {  // cruise
    travelled = 0.5 * a_ * t_1_ * t_1_ + v_ * (t - t_1_);
    speed = v_;
  } else {  // deceleration, written from the end so that q(t_f) = q_f exactly
    const double remaining = t_f_ - t;
    travelled = std::abs(q_f_ - q_s_) - 0.5 * d_ * remaining * remaining;
    speed = d_ * remaining;
  }
  return {q_s_ + sign_ * travelled, sign_ * speed};
}

double TrapezoidProfile::acceleration(double t) const {
  if (t <= 0.0 || t >= t_f_) return 0.0;
  if (t < t_1_) return sign_ * a_;
  if (t <= t_2_) return 0.0;
  return -sign_ * d_;
}

}  // namespace grpvss::motion

#include "grpvss/motion/ptp_motion.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <fmt/core.h>

#include "grpvss/common/input_error.hpp"

namespace grpvss::motion {

JointMotion JointMotion::trapezoid(const TrapezoidProfile& profile) {
  JointMotion motion;
  motion.trapezoid_ = profile;
  motion.q_s_ = profile.start();
  motion.q_f_ = profile.finish();
  motion.natural_duration_ = motion.duration_ = profile.duration();
  return motion;
}

JointMotion JointMotion::table(std::shared_ptr<const ProfileTable> table, int joint, double q_s,
                               double q_f) {
  JointMotion motion;
  motion.q_s_ = q_s;
  motion.q_f_ = q_f;
  motion.column_ = joint;
  motion.natural_duration_ = motion.duration_ = q_s == q_f ? 0.0 : table->duration(joint);
  motion.table_ = std::move(table);
  return motion;
}

void JointMotion::stretch_to(double total) {
  if (!(total >= natural_duration_)) throw std::logic_error("JointMotion: cannot shrink a motion");
  // A motion that does not move stays put, whatever its length.
  duration_ = natural_duration_ == 0.0 ? 0.0 : total;
}

JointState JointMotion::natural_at(double t) const {
  if (!table_) return trapezoid_.at(t);
  if (natural_duration_ == 0.0) return {q_s_, 0.0};
  if (t >= natural_duration_) return {q_f_, 0.0};  // exact end value
  const JointState s = table_->progress(column_, t);
  return {q_s_ + (q_f_ - q_s_) * s.position, (q_f_ - q_s_) * s.velocity};
}

JointState JointMotion::at(double t) const {
  if (duration_ == natural_duration_) return natural_at(t);
  // Time stretch: q~(t) = q(k t), dq~/dt = k q'(k t), k = T_natural / T <= 1.
  const double k = natural_duration_ / duration_;
  const JointState state = natural_at(t * k);
  return {state.position, k * state.velocity};
}

PtpMotion PtpMotion::plan(const RobotModel& robot, const Eigen::VectorXd& q_start,
                          const Eigen::VectorXd& q_end, const Eigen::VectorXd& velocity,
                          PtpTiming timing, std::shared_ptr<const ProfileTable> table) {
  const int n = robot.joint_count();
  if (q_start.size() != n || q_end.size() != n || velocity.size() != n)
    throw std::invalid_argument("PtpMotion::plan: joint vectors must have the robot's size");
  if (table && table->joint_count() != n)
    throw InputError(table->file_name(), table->header_line(),
                     fmt::format("'joints {}' (the robot's joint count)", n),
                     fmt::format("'joints {}'", table->joint_count()));
  PtpMotion motion;
  for (int j = 0; j < n; ++j) {
    const Joint& joint = robot.joints[j];
    motion.joints_.push_back(
        table ? JointMotion::table(table, j, q_start[j], q_end[j])
              : JointMotion::trapezoid(TrapezoidProfile::plan(q_start[j], q_end[j], velocity[j],
                                                              joint.acceleration,
                                                              joint.deceleration)));
    motion.duration_ = std::max(motion.duration_, motion.joints_.back().natural_duration());
  }
  if (timing == PtpTiming::kSynchronized)
    for (JointMotion& joint : motion.joints_) joint.stretch_to(motion.duration_);
  return motion;
}

Eigen::VectorXd PtpMotion::joints_at(double t) const {
  Eigen::VectorXd q(static_cast<Eigen::Index>(joints_.size()));
  for (std::size_t j = 0; j < joints_.size(); ++j) q[j] = joints_[j].at(t).position;
  return q;
}

Eigen::VectorXd PtpMotion::velocities_at(double t) const {
  Eigen::VectorXd v(static_cast<Eigen::Index>(joints_.size()));
  for (std::size_t j = 0; j < joints_.size(); ++j) v[j] = joints_[j].at(t).velocity;
  return v;
}

}  // namespace grpvss::motion

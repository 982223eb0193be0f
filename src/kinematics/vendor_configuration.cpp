#include "grpvss/kinematics/vendor_configuration.hpp"

#include <cmath>
#include <stdexcept>

#include "elementary_rotations.hpp"

namespace grpvss::kinematics {
namespace {

OpwArmSides sides_of(const OpwChainModel& model, const Eigen::VectorXd& q) {
  if (q.size() != 6) throw std::logic_error("vendor configuration: q must have 6 values");
  return opw_arm_sides(model.parameters, model.placement.to_model(q));
}

}  // namespace

bool operator==(const KukaStatusTurn& a, const KukaStatusTurn& b) {
  return a.status == b.status && a.turn == b.turn;
}

bool operator==(const AbbConfdata& a, const AbbConfdata& b) {
  return a.cf1 == b.cf1 && a.cf4 == b.cf4 && a.cf6 == b.cf6 && a.cfx == b.cfx;
}

KukaStatusTurn kuka_status_turn(const OpwChainModel& model, const Eigen::VectorXd& q) {
  const OpwArmSides sides = sides_of(model, q);
  KukaStatusTurn bits;
  if (sides.wrist_ahead_of_axis1 < 0) bits.status |= 1;
  if (sides.wrist_ahead_of_lower_arm >= 0) bits.status |= 2;
  if (q[4] < 0) bits.status |= 4;
  for (int i = 0; i < 6; ++i) {
    if (q[i] < 0) bits.turn |= 1 << i;
  }
  return bits;
}

AbbConfdata abb_confdata(const OpwChainModel& model, const Eigen::VectorXd& q) {
  const OpwArmSides sides = sides_of(model, q);
  AbbConfdata conf;
  conf.cf1 = abb_quadrant(q[0]);
  conf.cf4 = abb_quadrant(q[3]);
  conf.cf6 = abb_quadrant(q[5]);
  conf.cfx = (sides.wrist_ahead_of_axis1 < 0 ? 4 : 0) +
             (sides.wrist_ahead_of_lower_arm < 0 ? 2 : 0) + (q[4] < 0 ? 1 : 0);
  return conf;
}

int abb_quadrant(double angle) {
  return static_cast<int>(std::floor(angle / (detail::kPi / 2)));
}

}  // namespace grpvss::kinematics

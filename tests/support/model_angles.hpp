#pragma once
// Random six-axis model angles and the distance between two angles, for the closed-form IK
// tests (UR, OPW), defined once so that the tests' unity batches hold one definition.

#include <cmath>
#include <random>

#include "grpvss/kinematics/opw_kinematics.hpp"
#include "support/angles.hpp"

namespace grpvss::test {

/// Six angles uniform in [-pi, pi).
inline kinematics::ModelAngles random_angles(std::mt19937_64& generator) {
  std::uniform_real_distribution<double> uniform(-kPi, kPi);
  kinematics::ModelAngles t;
  for (double& value : t) value = uniform(generator);
  return t;
}

/// |a - b| modulo 2 pi, in [0, pi].
inline double angle_difference(double a, double b) { return std::abs(std::remainder(a - b, 2 * kPi)); }

}  // namespace grpvss::test

#pragma once
/// \file
/// \brief Numeric IK for any chain: damped least squares (Levenberg-Marquardt) on the 6-D pose
/// error, joint limits enforced by projection, several deterministic seeds.

#include <cstdint>
#include <memory>

#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::kinematics {

struct NumericIkOptions {
  double position_tolerance = 1e-9;     ///< |p - p_target| (length units) to accept
  double orientation_tolerance = 1e-9;  ///< rotation angle of R_target R^T (rad) to accept
  double position_weight = 1.0;         ///< weight of the position error rows
  double orientation_weight = 10.0;     ///< weight of the orientation error rows (length/rad)
  int max_iterations = 200;             ///< per seed
  int random_seeds = 24;                ///< seeds after q_near and home
  std::uint64_t generator_seed = 7545;  ///< fixed seed of the pseudo-random seed generator
};

/// \brief Seeds are q_near (clamped to limits), home, then `random_seeds` uniform draws within
/// the limits from a std::mt19937_64 seeded with generator_seed (same every call). Every seed is
/// tried; among converged solutions the one nearest to q_near is returned.
std::unique_ptr<InverseKinematics> make_numeric_ik(const RobotModel& model,
                                                   NumericIkOptions options = {});

}  // namespace grpvss::kinematics

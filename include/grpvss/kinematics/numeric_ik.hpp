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
  int random_seeds = 64;                ///< seeds after q_near and home
  /// true: try every seed and return the converged solution nearest to q_near. false: return
  /// the first converged seed's solution (q_near is tried first, so small moves such as CP
  /// tracking keep their branch) - much faster when q_near is already close.
  bool exhaustive = true;
  std::uint64_t generator_seed = 7545;  ///< fixed seed of the pseudo-random seed generator
};

/// \brief Seeds are q_near (clamped to limits), home, then `random_seeds` uniform draws within
/// the limits from a std::mt19937_64 seeded with generator_seed (same every call). With
/// options.exhaustive every seed is tried and the converged solution nearest to q_near is
/// returned; otherwise the first converged one. kOutOfWorkspace when no seed converges.
std::unique_ptr<InverseKinematics> make_numeric_ik(const RobotModel& model,
                                                   NumericIkOptions options = {});

}  // namespace grpvss::kinematics

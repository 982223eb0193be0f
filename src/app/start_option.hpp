#pragma once
// `--start q1,q2,...` on verify, trajectory and check-certificate: where the path starts
// (docs/user-guide.md#start-configuration).
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <Eigen/Core>

#include "grpvss/motion/joint_trajectory_motion.hpp"
#include "model_inputs.hpp"

namespace grpvss::app {

/// Adds `--start` (the text, parsed later against the model) to `command`.
void add_start_option(CLI::App& command, std::string& start);

/// \brief The path's start from `--start`, library units; nullopt when not given.
/// \throws InputError("--start", 0, ...) naming the joint (cell::start_configuration).
std::optional<Eigen::VectorXd> start_of(const std::string& start, const ModelInputs& model);

/// Largest difference (library units) `--start` may have from a trajectory's first waypoint.
inline constexpr double kTrajectoryStartTolerance = 1e-9;

/// \brief A trajectory starts at its first waypoint: `--start`, when given, must equal it
/// within kTrajectoryStartTolerance per joint. \throws InputError("--start", 0, ...) naming
/// the first joint that differs.
void check_trajectory_start(const std::string& start, const ModelInputs& model,
                            const motion::JointTrajectoryMotion& motion);

}  // namespace grpvss::app

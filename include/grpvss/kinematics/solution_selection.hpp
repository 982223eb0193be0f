#pragma once
/// \file
/// \brief Choosing one IK solution: by the configuration a program names (KUKA Status/Turn,
/// ABB confdata, or the arm configuration), or the one nearest the current joints.
///
/// A named configuration is a requirement: when no solution has it the answer is none (the
/// robot would otherwise move in a configuration the program did not ask for). Several
/// solutions with it (turns the bits do not tell apart) -> the one nearest q_near.

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "grpvss/kinematics/analytic_ik.hpp"
#include "grpvss/kinematics/vendor_configuration.hpp"

namespace grpvss::kinematics {

/// \brief The solution nearest to q_near (Euclidean in joint space); none when empty.
std::optional<Eigen::VectorXd> nearest_solution(const std::vector<ConfiguredSolution>& solutions,
                                                const Eigen::VectorXd& q_near);

/// \brief The solution for X_WT with KUKA Status `status` (bits 0-2 compared) and, when
/// given, Turn `turn`. Throws std::invalid_argument for a UR solver.
std::optional<Eigen::VectorXd> solution_with_status_turn(const AnalyticIk& ik,
                                                         const Eigen::Isometry3d& X_WT, int status,
                                                         std::optional<int> turn,
                                                         const Eigen::VectorXd& q_near);

/// \brief The solution for X_WT with ABB confdata `conf`. Throws std::invalid_argument for a UR
/// solver.
std::optional<Eigen::VectorXd> solution_with_confdata(const AnalyticIk& ik,
                                                      const Eigen::Isometry3d& X_WT,
                                                      const AbbConfdata& conf,
                                                      const Eigen::VectorXd& q_near);

/// \brief The solution for X_WT in arm configuration `configuration`.
std::optional<Eigen::VectorXd> solution_with_configuration(const AnalyticIk& ik,
                                                           const Eigen::Isometry3d& X_WT,
                                                           const ArmConfiguration& configuration,
                                                           const Eigen::VectorXd& q_near);

}  // namespace grpvss::kinematics

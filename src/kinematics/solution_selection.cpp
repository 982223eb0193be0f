#include "grpvss/kinematics/solution_selection.hpp"

#include <limits>
#include <stdexcept>

namespace grpvss::kinematics {
namespace {

template <class Keep>
std::optional<Eigen::VectorXd> nearest_kept(const std::vector<ConfiguredSolution>& solutions,
                                            const Eigen::VectorXd& q_near, Keep keep) {
  std::optional<Eigen::VectorXd> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const ConfiguredSolution& solution : solutions) {
    if (!keep(solution)) continue;
    const double distance = (solution.q - q_near).norm();
    if (distance < best_distance) {
      best_distance = distance;
      best = solution.q;
    }
  }
  return best;
}

const OpwChainModel& opw_model_of(const AnalyticIk& ik) {
  if (!ik.opw()) throw std::invalid_argument("KUKA and ABB configurations need an OPW solver");
  return *ik.opw();
}

}  // namespace

std::optional<Eigen::VectorXd> nearest_solution(const std::vector<ConfiguredSolution>& solutions,
                                                const Eigen::VectorXd& q_near) {
  return nearest_kept(solutions, q_near, [](const ConfiguredSolution&) { return true; });
}

std::optional<Eigen::VectorXd> solution_with_status_turn(const AnalyticIk& ik,
                                                         const Eigen::Isometry3d& X_WT, int status,
                                                         std::optional<int> turn,
                                                         const Eigen::VectorXd& q_near) {
  const OpwChainModel& model = opw_model_of(ik);
  return nearest_kept(ik.solutions(X_WT, q_near), q_near, [&](const ConfiguredSolution& s) {
    const KukaStatusTurn bits = kuka_status_turn(model, s.q);
    return (bits.status & 7) == (status & 7) && (!turn || bits.turn == (*turn & 63));
  });
}

std::optional<Eigen::VectorXd> solution_with_confdata(const AnalyticIk& ik,
                                                      const Eigen::Isometry3d& X_WT,
                                                      const AbbConfdata& conf,
                                                      const Eigen::VectorXd& q_near) {
  const OpwChainModel& model = opw_model_of(ik);
  return nearest_kept(ik.solutions(X_WT, q_near), q_near, [&](const ConfiguredSolution& s) {
    return abb_confdata(model, s.q) == conf;
  });
}

std::optional<Eigen::VectorXd> solution_with_configuration(const AnalyticIk& ik,
                                                           const Eigen::Isometry3d& X_WT,
                                                           const ArmConfiguration& configuration,
                                                           const Eigen::VectorXd& q_near) {
  return nearest_kept(ik.solutions(X_WT, q_near), q_near, [&](const ConfiguredSolution& s) {
    return s.configuration == configuration;
  });
}

}  // namespace grpvss::kinematics

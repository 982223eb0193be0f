#include "grpvss/kinematics/analytic_ik.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "elementary_rotations.hpp"
#include "turn_variants.hpp"

namespace grpvss::kinematics {
namespace {

// Chains that are exactly of the family fit with a deviation of a few ulps; above this the
// closed form is only a starting point and Newton steps on the chain finish the solution.
constexpr double kRefineAbove = 1e-13;

double length_scale_of(const KinematicChain& chain, const Eigen::Isometry3d& X_ET) {
  double scale = X_ET.translation().norm();
  for (const ChainJoint& joint : chain.joints) {
    scale += joint.X_PJ.translation().norm() + joint.X_JC.translation().norm();
  }
  return scale > 0 ? scale : 1.0;
}

void check_six(const KinematicChain& chain) {
  if (chain.joint_count() != 6) throw std::invalid_argument("AnalyticIk: the chain must have 6 joints");
}

// q equal to an earlier one up to whole turns and rounding (coinciding branches at a
// singular pose).
template <class Vector, std::size_t N>
bool already_listed(const std::array<Vector, N>& listed, int count, const Vector& q) {
  for (int k = 0; k < count; ++k) {
    bool same = true;
    for (int i = 0; i < q.size() && same; ++i) {
      same = std::abs(detail::wrap_angle(q[i] - listed[static_cast<std::size_t>(k)][i])) <= 1e-12;
    }
    if (same) return true;
  }
  return false;
}

}  // namespace

AnalyticIk::AnalyticIk(KinematicChain chain, OpwChainModel model)
    : chain_(std::move(chain)), model_(model) {
  check_six(chain_);
  length_scale_ = length_scale_of(chain_, model.X_ET);
  refine_ = model.fk_deviation > kRefineAbove;
}

AnalyticIk::AnalyticIk(KinematicChain chain, UrChainModel model)
    : chain_(std::move(chain)), model_(model) {
  check_six(chain_);
  length_scale_ = length_scale_of(chain_, model.X_ET);
  refine_ = model.fk_deviation > kRefineAbove;
}

const ModelPlacement& AnalyticIk::placement() const {
  if (const auto* opw_model = opw()) return opw_model->placement;
  return ur()->placement;
}

const Eigen::Isometry3d& AnalyticIk::X_ET() const {
  if (const auto* opw_model = opw()) return opw_model->X_ET;
  return ur()->X_ET;
}

std::string AnalyticIk::name() const { return opw() ? "OPW closed form" : "UR closed form"; }

ArmConfiguration AnalyticIk::configuration_of(const Eigen::VectorXd& q) const {
  const ModelAngles theta = placement().to_model(q);
  if (const auto* opw_model = opw()) return opw_configuration(opw_model->parameters, theta);
  return ur_configuration(ur()->parameters, theta);
}

AnalyticIk::Branches AnalyticIk::branch_solutions(const Eigen::Isometry3d& X_WT,
                                                  const Eigen::VectorXd& q_free) const {
  const ModelPlacement& place = placement();
  const Eigen::Isometry3d X_BF = place.flange_target(X_WT);
  const ModelAngles free_theta = place.to_model(q_free);
  const std::array<ModelBranch, 8> branches =
      opw() ? opw_inverse(opw()->parameters, X_BF, {free_theta[0], free_theta[3]})
            : ur_inverse(ur()->parameters, X_BF, free_theta[5]);
  Branches result;
  for (const ModelBranch& branch : branches) {
    if (!branch.valid) continue;
    Vector6d q;
    for (int i = 0; i < 6; ++i) q[i] = place.to_chain(i, branch.theta[static_cast<std::size_t>(i)]);
    if (refine_) refine(X_WT, q);
    if (already_listed(result.q, result.count, q)) continue;
    result.q[static_cast<std::size_t>(result.count++)] = q;
  }
  return result;
}

std::vector<ConfiguredSolution> AnalyticIk::solutions(const Eigen::Isometry3d& X_WT) const {
  return solutions(X_WT, Eigen::VectorXd::Zero(6));
}

std::vector<ConfiguredSolution> AnalyticIk::solutions(const Eigen::Isometry3d& X_WT,
                                                      const Eigen::VectorXd& q_near) const {
  if (q_near.size() != 6) throw std::logic_error("AnalyticIk: q_near must have 6 values");
  std::vector<ConfiguredSolution> all;
  const Branches branches = branch_solutions(X_WT, q_near);
  for (int b = 0; b < branches.count; ++b) {
    const Eigen::VectorXd q = branches.q[static_cast<std::size_t>(b)];
    // Per variant: at a singular pose (sin theta_5 = 0) a whole turn may round the sign.
    for (Eigen::VectorXd& variant : detail::turn_variants(chain_, q)) {
      const ArmConfiguration configuration = configuration_of(variant);
      all.push_back({std::move(variant), configuration});
    }
  }
  return all;
}

IkSolution AnalyticIk::solve(const Eigen::Isometry3d& X_WT, const Eigen::VectorXd& q_near) const {
  if (q_near.size() != 6) throw std::logic_error("AnalyticIk: q_near must have 6 values");
  double best_distance = std::numeric_limits<double>::infinity();
  const Branches branches = branch_solutions(X_WT, q_near);
  Vector6d nearest;
  Vector6d best;
  for (int b = 0; b < branches.count; ++b) {
    // The distance is a sum over joints: the nearest turn of each joint gives the nearest
    // variant of the branch.
    if (!detail::nearest_turns(chain_, branches.q[static_cast<std::size_t>(b)], q_near, nearest)) continue;
    const double distance = (nearest - q_near).norm();
    if (distance < best_distance) {
      best_distance = distance;
      best = nearest;
    }
  }
  if (best_distance == std::numeric_limits<double>::infinity()) return {IkStatus::kOutOfWorkspace, {}};
  return {IkStatus::kSolved, best};
}

}  // namespace grpvss::kinematics

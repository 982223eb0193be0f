#include "grpvss/kinematics/numeric_ik.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Cholesky>

#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/jacobian.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"

namespace grpvss::kinematics {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// Rotation vector (axis * angle, in W) of R_target R^T: the angular displacement still to go.
// Via the quaternion, so small angles keep full relative precision.
Eigen::Vector3d orientation_error(const Eigen::Matrix3d& R_target, const Eigen::Matrix3d& R) {
  Eigen::Quaterniond dq(R_target * R.transpose());
  dq.normalize();
  if (dq.w() < 0) dq.coeffs() = -dq.coeffs();
  const double n = dq.vec().norm();
  if (n < 1e-300) return Eigen::Vector3d::Zero();
  return (2 * std::atan2(n, dq.w()) / n) * dq.vec();
}

class NumericIk final : public InverseKinematics {
 public:
  NumericIk(const RobotModel& model, NumericIkOptions options)
      : chain_(make_chain(model)), options_(options) {
    if (chain_.joint_count() == 0) throw std::invalid_argument("make_numeric_ik: robot has no joints");
    // Seeds are fixed at construction: the same target always sees the same seeds.
    std::mt19937_64 generator(options_.generator_seed);
    for (int s = 0; s < options_.random_seeds; ++s) {
      Eigen::VectorXd q(chain_.joint_count());
      for (int i = 0; i < chain_.joint_count(); ++i) {
        const ChainJoint& joint = chain_.joints[static_cast<std::size_t>(i)];
        std::uniform_real_distribution<double> uniform(joint.minimum, joint.maximum);
        q[i] = uniform(generator);
      }
      random_seeds_.push_back(q);
    }
  }

  IkSolution solve(const Eigen::Isometry3d& X_WE_target,
                   const Eigen::VectorXd& q_near) const override {
    if (q_near.size() != chain_.joint_count()) {
      throw std::logic_error("NumericIk: q_near has the wrong size");
    }
    Workspace ws = Workspace::frames_only(chain_.joints.size());

    IkSolution best{IkStatus::kOutOfWorkspace, {}};
    double best_distance = std::numeric_limits<double>::infinity();
    auto try_seed = [&](const Eigen::VectorXd& seed) {
      if (!options_.exhaustive && best.status == IkStatus::kSolved) return;
      Eigen::VectorXd q;
      if (!descend(X_WE_target, project(seed), ws, q)) return;
      const double distance = (q - q_near).norm();
      if (distance < best_distance) {
        best_distance = distance;
        best = {IkStatus::kSolved, q};
      }
    };
    try_seed(q_near);
    try_seed(chain_.home());
    for (const Eigen::VectorXd& seed : random_seeds_) try_seed(seed);
    return best;
  }

  std::string name() const override { return "damped least squares"; }

 private:
  Eigen::VectorXd project(Eigen::VectorXd q) const {
    for (int i = 0; i < chain_.joint_count(); ++i) {
      const ChainJoint& joint = chain_.joints[static_cast<std::size_t>(i)];
      q[i] = std::clamp(q[i], joint.minimum, joint.maximum);
    }
    return q;
  }

  // Damped Gauss-Newton step with an active set: a joint sitting on a limit whose step points
  // outward is frozen and the step recomputed without it, so the remaining joints still make
  // full progress (plain clamping would shorten the whole step and stall along the limit).
  Eigen::VectorXd limited_step(const Eigen::MatrixXd& JtJ, const Eigen::VectorXd& g,
                               const Eigen::VectorXd& q, double lambda) const {
    const int n = chain_.joint_count();
    std::vector<bool> frozen(static_cast<std::size_t>(n), false);
    Eigen::VectorXd step = Eigen::VectorXd::Zero(n);
    for (int round = 0; round <= n; ++round) {
      Eigen::MatrixXd A = JtJ;
      A.diagonal().array() += lambda * (1.0 + JtJ.diagonal().array());
      Eigen::VectorXd b = g;
      for (int i = 0; i < n; ++i) {
        if (!frozen[static_cast<std::size_t>(i)]) continue;
        A.row(i).setZero();
        A.col(i).setZero();
        A(i, i) = 1.0;
        b[i] = 0.0;
      }
      step = A.ldlt().solve(b);
      bool changed = false;
      for (int i = 0; i < n; ++i) {
        const ChainJoint& joint = chain_.joints[static_cast<std::size_t>(i)];
        const bool outward = (q[i] <= joint.minimum && step[i] < 0) ||
                             (q[i] >= joint.maximum && step[i] > 0);
        if (outward && !frozen[static_cast<std::size_t>(i)]) {
          frozen[static_cast<std::size_t>(i)] = true;
          changed = true;
        }
      }
      if (!changed) break;
    }
    return step;
  }

  // Pose error (position rows, then rotation-vector rows) at q; fills ws.
  Vector6d pose_error(const Eigen::Isometry3d& X_target, const Eigen::VectorXd& q,
                      Workspace& ws) const {
    forward_kinematics(chain_, q, ws);
    const Eigen::Isometry3d& X_WE = ws.X_WL.back();
    Vector6d e;
    e.head<3>() = X_target.translation() - X_WE.translation();
    e.tail<3>() = orientation_error(X_target.linear(), X_WE.linear());
    return e;
  }

  bool converged(const Vector6d& e) const {
    return e.head<3>().norm() <= options_.position_tolerance &&
           e.tail<3>().norm() <= options_.orientation_tolerance;
  }

  double weighted_cost(const Vector6d& e) const {
    return options_.position_weight * options_.position_weight * e.head<3>().squaredNorm() +
           options_.orientation_weight * options_.orientation_weight * e.tail<3>().squaredNorm();
  }

  // Levenberg-Marquardt: minimise |W e|^2 over the box of joint limits; the damping shrinks
  // after a successful step and grows after a failed one, so far from the solution the step is
  // a short gradient step and near it a Gauss-Newton step (quadratic convergence).
  bool descend(const Eigen::Isometry3d& X_target, Eigen::VectorXd q, Workspace& ws,
               Eigen::VectorXd& q_out) const {
    Vector6d w;
    w << Eigen::Vector3d::Constant(options_.position_weight),
        Eigen::Vector3d::Constant(options_.orientation_weight);
    Vector6d e = pose_error(X_target, q, ws);
    double cost = weighted_cost(e);
    double lambda = 1e-3;
    for (int iteration = 0; iteration < options_.max_iterations; ++iteration) {
      if (converged(e)) {
        q_out = q;
        return true;
      }
      const Eigen::Matrix<double, 6, Eigen::Dynamic> J =
          w.asDiagonal() * end_effector_jacobian(chain_, ws);
      const Vector6d we = w.cwiseProduct(e);
      const Eigen::MatrixXd JtJ = J.transpose() * J;
      const Eigen::VectorXd g = J.transpose() * we;
      bool improved = false;
      while (lambda < 1e12) {
        const Eigen::VectorXd q_trial = project(q + limited_step(JtJ, g, q, lambda));
        const Vector6d e_trial = pose_error(X_target, q_trial, ws);
        const double cost_trial = weighted_cost(e_trial);
        if (cost_trial < cost) {
          q = q_trial;
          e = e_trial;
          cost = cost_trial;
          lambda = std::max(lambda * 0.1, 1e-15);
          improved = true;
          break;
        }
        lambda *= 10.0;
      }
      if (!improved) {
        // No descent left: a local minimum (or the limits) away from the target, or roundoff.
        return false;
      }
    }
    // The last accepted step may have reached the tolerance.
    if (!converged(e)) return false;
    q_out = q;
    return true;
  }

  KinematicChain chain_;
  NumericIkOptions options_;
  std::vector<Eigen::VectorXd> random_seeds_;
};

}  // namespace

std::unique_ptr<InverseKinematics> make_numeric_ik(const RobotModel& model,
                                                   NumericIkOptions options) {
  return std::make_unique<NumericIk>(model, options);
}

}  // namespace grpvss::kinematics

// AnalyticIk::refine: Newton steps on the chain itself, for chains that are only approximately
// of the family (the closed form of the fitted model is then within ~1e-9 of a solution).
#include <Eigen/QR>

#include "elementary_rotations.hpp"
#include "grpvss/kinematics/analytic_ik.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/jacobian.hpp"

namespace grpvss::kinematics {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// Position error, then the rotation vector of R_target R^T (both in W).
Vector6d tool_error(const Eigen::Isometry3d& X_target, const Eigen::Isometry3d& X) {
  Vector6d e;
  e.head<3>() = X_target.translation() - X.translation();
  const Eigen::AngleAxisd turn(X_target.linear() * X.linear().transpose());
  e.tail<3>() = turn.angle() * turn.axis();
  return e;
}

double size_of(const Vector6d& e, double length_scale) {
  return e.head<3>().norm() / length_scale + e.tail<3>().norm();
}

}  // namespace

void AnalyticIk::refine(const Eigen::Isometry3d& X_WT, Vector6d& q) const {
  Workspace ws = Workspace::frames_only(6);
  const auto error_at = [&](const Eigen::VectorXd& at) {
    forward_kinematics(chain_, at, ws);
    return tool_error(X_WT, ws.X_WL.back() * X_ET());
  };
  Vector6d e = error_at(q);
  double size = size_of(e, length_scale_);
  // Plain Newton steps, keeping the best iterate: near a singular pose of the chain (the
  // smallest singular value of J can be 1e-7) the first step may overshoot before the
  // quadratic convergence sets in, so a step is not required to improve.
  Eigen::VectorXd current = q;
  for (int step = 0; step < 6 && size > 1e-15; ++step) {
    // ws holds current's frames. The tool point moves as E's origin plus w x r.
    Eigen::Matrix<double, 6, 6> J = end_effector_jacobian(chain_, ws);
    const Eigen::Vector3d r = (ws.X_WL.back() * X_ET()).translation() - ws.X_WL.back().translation();
    for (int j = 0; j < 6; ++j) J.col(j).head<3>() += J.col(j).tail<3>().cross(r);
    // Least squares with rank detection: at a singular pose the minimum-norm step.
    current += J.completeOrthogonalDecomposition().solve(e);
    e = error_at(current);
    const double current_size = size_of(e, length_scale_);
    if (!(current_size < size)) continue;
    q = current;
    size = current_size;
  }
}

}  // namespace grpvss::kinematics

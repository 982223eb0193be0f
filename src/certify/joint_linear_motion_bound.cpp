#include "joint_linear_motion_bound.hpp"

#include <algorithm>
#include <cmath>

#include "grpvss/kinematics/forward_kinematics.hpp"  // place_points: the expression the FK bound covers
#include "grpvss/geometry/directed_rounding.hpp"

namespace grpvss::certify {
namespace {

namespace r = geometry::rounding;

// |b - a| rounded up (requires an active upward scope): one of the two differences is >= 0.
double abs_difference_up(double a, double b) { return std::max(r::sub_up(b, a), r::sub_up(a, b)); }

}  // namespace

double hull_curvature_bound(const HullRadiusTable& radii, int link, int hull,
                            const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to) {
  // proof: proofs/motion-bound.md#lemma-joint-linear-chord
  const int joints = std::min<int>(link, static_cast<int>(q_from.size()));
  r::UpwardRoundingScope upward;
  double bound = 0.0;
  double revolute_before = 0.0;  // sum_{j < m, j revolute} |dq_j|, rounded up
  for (int m = 1; m <= joints; ++m) {
    // The weight (R_mh or 1) is read from the table: no arithmetic, so no rounding.
    const double weight = radii.motion_bound_weight(link, hull, m);
    const bool revolute = radii.joint_type(m) == JointType::kRevolute;
    const double increment = abs_difference_up(q_from[m - 1], q_to[m - 1]);
    double factor = r::mul_up(2.0, revolute_before);
    if (revolute) factor = r::add_up(factor, increment);
    bound = r::add_up(bound, r::mul_up(weight, r::mul_up(increment, factor)));
    if (revolute) revolute_before = r::add_up(revolute_before, increment);
  }
  return bound;
}

double vertex_chord_bound(const std::vector<Eigen::Vector3d>& raw_L,
                          const Eigen::Isometry3d& X_WL_from, const Eigen::Isometry3d& X_WL_to,
                          double placement_error) {
  // proof: proofs/motion-bound.md#lemma-joint-linear-chord (floating point)
  // Placed in round-to-nearest, exactly as the FK rounding bound assumes.
  thread_local std::vector<Eigen::Vector3d> from_W, to_W;
  kinematics::place_points(X_WL_from, raw_L, from_W);
  kinematics::place_points(X_WL_to, raw_L, to_W);
  r::UpwardRoundingScope upward;
  double largest_square = 0.0;
  for (std::size_t v = 0; v < raw_L.size(); ++v) {
    double square = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double d = abs_difference_up(from_W[v][k], to_W[v][k]);
      square = r::add_up(square, r::mul_up(d, d));
    }
    largest_square = std::max(largest_square, square);
  }
  return r::add_up(r::sqrt_up(largest_square), r::mul_up(2.0, placement_error));
}

double joint_linear_motion_bound(const HullRadiusTable& radii, int link, int hull,
                                 const std::vector<Eigen::Vector3d>& raw_L,
                                 const Eigen::VectorXd& q_from, const Eigen::Isometry3d& X_WL_from,
                                 const Eigen::VectorXd& q_to, const Eigen::Isometry3d& X_WL_to,
                                 double placement_error) {
  const double chord = vertex_chord_bound(raw_L, X_WL_from, X_WL_to, placement_error);
  const double curvature = hull_curvature_bound(radii, link, hull, q_from, q_to);
  r::UpwardRoundingScope upward;
  return r::add_up(chord, r::div_up(curvature, 3.0));
}

}  // namespace grpvss::certify

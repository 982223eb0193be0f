#include "step_axis_radius.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "grpvss/geometry/directed_rounding.hpp"
#include "vertex_route.hpp"

namespace grpvss::certify {
namespace r = geometry::rounding;

namespace {

Eigen::Vector3d box_midpoint(const std::vector<Eigen::Vector3d>& points_L) {
  Eigen::Vector3d lo = points_L.front();
  Eigen::Vector3d hi = points_L.front();
  for (const Eigen::Vector3d& p : points_L) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (lo + hi) * 0.5;  // any centre is sound: the radius is measured from it
}

// max |u - c| over the vertices, rounded up (each coordinate difference as a range). An active
// UpwardRoundingScope is required.
double largest_distance_up(const std::vector<Eigen::Vector3d>& points_L, const Eigen::Vector3d& c) {
  double largest_square = 0.0;
  for (const Eigen::Vector3d& u : points_L) {
    double square = 0.0;
    for (int k = 0; k < 3; ++k) {
      square = r::add_up(square, r::square_up_of_range(r::sub_down(u[k], c[k]), r::sub_up(u[k], c[k])));
    }
    largest_square = std::max(largest_square, square);
  }
  return r::sqrt_up(largest_square);
}

}  // namespace

// proof: proofs/motion-bound.md#axis-distance-evaluation
double axis_point_distance_up(const Eigen::Vector3d& c, const Eigen::Vector3d& o,
                              const Eigen::Vector3d& z, double s) {
  double square = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double hi = r::sub_up(c[k], r::add_down(o[k], r::mul_down(s, z[k])));
    const double lo = r::sub_down(c[k], r::add_up(o[k], r::mul_up(s, z[k])));
    square = r::add_up(square, r::square_up_of_range(lo, hi));
  }
  return r::sqrt_up(square);
}

namespace {
std::atomic<unsigned long long> next_identity{1};
}  // namespace

void set_axis_balls(std::vector<LinkHull>& hulls) {
  // The centres in round-to-nearest, then every radius in one upward scope (a scope costs two
  // rounding-mode switches).
  for (LinkHull& hull : hulls) {
    hull.axis_ball_center_L = hull.raw_L.empty() ? Eigen::Vector3d::Zero() : box_midpoint(hull.raw_L);
  }
  r::UpwardRoundingScope upward;
  for (LinkHull& hull : hulls) {
    hull.axis_ball_radius_up = hull.raw_L.empty() ? 0.0 : largest_distance_up(hull.raw_L, hull.axis_ball_center_L);
  }
}

StepAxisRadii::StepAxisRadii(const RobotCell& cell)
    : cell_(&cell), identity_(next_identity.fetch_add(1)), joints_(cell.chain().joint_count()) {}

void StepAxisRadii::axis_distances(const ProbeResult& probe, std::vector<double>& distances) const {
  const std::vector<LinkHull>& hulls = cell_->hulls();
  const auto joints = static_cast<std::size_t>(joints_);
  distances.assign(hulls.size() * joints, 0.0);
  if (probe.X_WJ.size() != joints || probe.X_WL.size() <= joints) {
    // No frames kept with this probe: no tightening (R_jh stands).
    std::fill(distances.begin(), distances.end(), std::numeric_limits<double>::infinity());
    return;
  }
  // The centres placed and each axis parameter s taken in round-to-nearest, as the FK bound
  // and the checker assume; then only the distances are evaluated upward, in one scope.
  thread_local std::vector<Eigen::Vector3d> centers_W;
  thread_local std::vector<double> parameters;
  const double coordinate_limit = cell_->raw_coordinate_limit();
  centers_W.resize(hulls.size());
  parameters.assign(hulls.size() * joints, 0.0);
  for (std::size_t i = 0; i < hulls.size(); ++i) {
    centers_W[i] = probe.X_WL[static_cast<std::size_t>(hulls[i].link)] * hulls[i].axis_ball_center_L;
    for (int j = 1; j <= std::min(hulls[i].link, joints_); ++j) {
      const Eigen::Isometry3d& X_WJ = probe.X_WJ[static_cast<std::size_t>(j - 1)];
      // Near the foot of the perpendicular, within the FK bound's reach (any s is sound).
      parameters[i * joints + static_cast<std::size_t>(j - 1)] =
          std::clamp(X_WJ.linear().col(2).dot(centers_W[i] - X_WJ.translation()),
                     -coordinate_limit, coordinate_limit);
    }
  }
  r::UpwardRoundingScope upward;
  for (std::size_t i = 0; i < hulls.size(); ++i) {
    for (int j = 1; j <= std::min(hulls[i].link, joints_); ++j) {
      const std::size_t at = i * joints + static_cast<std::size_t>(j - 1);
      const Eigen::Isometry3d& X_WJ = probe.X_WJ[static_cast<std::size_t>(j - 1)];
      distances[at] = r::add_up(r::add_up(axis_point_distance_up(centers_W[i], X_WJ.translation(),
                                                                 X_WJ.linear().col(2), parameters[at]),
                                          cell_->placement_error()),
                                hulls[i].axis_ball_radius_up);
    }
  }
}

const std::vector<double>& StepAxisRadii::kept_or_computed(const ProbeResult& probe,
                                                           std::vector<double>& scratch) const {
  const bool kept = probe.axis_distances.size() == cell_->hulls().size() * static_cast<std::size_t>(joints_) &&
                    probe.axis_distances_q.size() == probe.q.size() && probe.axis_distances_q == probe.q;
  if (kept) return probe.axis_distances;
  axis_distances(probe, scratch);
  return scratch;
}

void StepAxisRadii::keep(ProbeResult& probe) const {
  axis_distances(probe, probe.axis_distances);
  probe.axis_distances_q = probe.q;
}

// proof: proofs/motion-bound.md#lemma-axis-distance-along-step
double StepAxisRadii::motion_bound(int hull_index, const Eigen::VectorXd& increments_up,
                                   const std::vector<double>& distances_from,
                                   const std::vector<double>& distances_to) const {
  const LinkHull& hull = cell_->hulls()[static_cast<std::size_t>(hull_index)];
  const HullRadiusTable& radii = cell_->radii();
  const int moving = std::min(hull.link, joints_);
  const std::size_t row = static_cast<std::size_t>(hull_index) * static_cast<std::size_t>(joints_);
  const std::vector<double>& R = radii.radii_of(hull.link, hull.hull);  // R_jh at j - 1, j <= link
  r::UpwardRoundingScope upward;
  // tail_j = sum_{j<m<=i} w_m V_m, accumulated from the hull's link down.
  double tail = 0.0;
  double bound = 0.0;
  for (int j = moving; j >= 1; --j) {
    const double increment = increments_up[j - 1];
    double weight = 1.0;  // w_j: R_jh for a revolute joint, 1 for a prismatic one
    if (radii.joint_type(j) == JointType::kRevolute) {
      weight = R[static_cast<std::size_t>(j - 1)];
      const double at_ends = std::min(distances_from[row + static_cast<std::size_t>(j - 1)],
                                      distances_to[row + static_cast<std::size_t>(j - 1)]);
      const double rho = std::min(weight, r::add_up(at_ends, tail));
      bound = r::add_up(bound, r::mul_up(increment, rho));
    } else {
      bound = r::add_up(bound, increment);
    }
    tail = r::add_up(tail, r::mul_up(weight, increment));
  }
  return bound;
}

void StepAxisRadii::proposal_axis_distances(const ProbeResult& probe,
                                            std::vector<double>& distances) const {
  std::vector<double> scratch;
  distances = kept_or_computed(probe, scratch);
  const auto joints = static_cast<std::size_t>(joints_);
  for (const SelfPairHulls& pair : cell_->self_pairs()) {
    const std::size_t b_row = static_cast<std::size_t>(pair.b) * joints;
    for (std::size_t j = 0; j < joints; ++j) distances.push_back(distances[b_row + j]);
  }
  // The revolution routes' rows (step_march.cpp): hull b's distances again, its own joint's
  // weighed vertex by vertex where the pair has the vertex bound
  // (proofs/two-ball-cover.md#revolution-vertex-bound).
  const std::vector<SelfPairHulls>& pairs = cell_->self_pairs();
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    if (!cell_->hulls()[static_cast<std::size_t>(pairs[p].a)].revolution_L) continue;
    const std::size_t b_row = static_cast<std::size_t>(pairs[p].b) * joints;
    const std::size_t route_row = distances.size();
    for (std::size_t j = 0; j < joints; ++j) distances.push_back(distances[b_row + j]);
    if (!has_vertex_route(*cell_, pairs[p])) continue;
    if (VertexRouteEnd* at = vertex_route_end(*this, p, probe)) {
      const int joint = cell_->hulls()[static_cast<std::size_t>(pairs[p].b)].link;
      double& own = distances[route_row + static_cast<std::size_t>(joint - 1)];
      own = std::min(own, vertex_route_proposal_radius(*this, *at, probe.self_pairs[p].revolution_distance));
    }
  }
}

Eigen::VectorXd increments_up(const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                              const Eigen::VectorXd& joint_variation) {
  if (joint_variation.size() > 0) return joint_variation.cwiseAbs();
  Eigen::VectorXd increments(q_from.size());
  r::UpwardRoundingScope upward;
  for (Eigen::Index j = 0; j < q_from.size(); ++j) {
    increments[j] = std::max(r::sub_up(q_to[j], q_from[j]), r::sub_up(q_from[j], q_to[j]));
  }
  return increments;
}

}  // namespace grpvss::certify

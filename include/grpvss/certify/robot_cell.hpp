#pragma once
/// \file
/// \brief Everything about one robot in one environment that does not change during a
/// verification: exact hulls, the tolerance offsets of every link hull (built once, in the
/// link frame), obstacle hulls and their spheres, the broadphase, the motion-bound radii and
/// the bound on forward kinematics' rounding error.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "grpvss/certify/motion_bound.hpp"
#include "grpvss/certify/obstacle_set.hpp"
#include "grpvss/evidence/setup.hpp"
#include "grpvss/geometry/broadphase.hpp"
#include "grpvss/geometry/centroid_cull.hpp"
#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/geometry/hull_skeleton.hpp"
#include "grpvss/geometry/revolution_solid.hpp"
#include "grpvss/geometry/vertex_clusters.hpp"
#include "grpvss/exact/minkowski_offset.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::certify {

/// \brief One link hull, in its link frame L.
struct LinkHull {
  int link = 0;
  int hull = 0;  ///< index within the link
  std::vector<Eigen::Vector3d> raw_L;       ///< exact-hull vertices of the input points
  std::vector<Eigen::Vector3d> expanded_L;  ///< vertices of H (+) P, P >= B(Delta + 2 eps)
  geometry::CertifiedSphere raw_sphere_L;
  geometry::CertifiedSphere expanded_sphere_L;
  geometry::Aabb expanded_box_L;  ///< box of expanded_L (the broadphase places it, O(1))
  geometry::Aabb raw_box_L;       ///< box of raw_L (a verdict's self pairs place it, O(1))
  /// Whether raw_L is decided on its link-frame template rather than placed (128+ vertices,
  /// geometry::kTemplateClimbMinVertices), and its largest |coordinate| for that.
  /// proof: proofs/fast-path.md#placed-separation
  bool raw_on_template = false;
  double raw_max_abs_L = 0.0;
  /// The offset's largest |coordinate| when the offset is decided on its template (128+
  /// vertices, and expanded_L exactly its exact hull's vertex list); -1: it is placed.
  double expanded_template_max_abs_L = -1.0;
  /// A solid of revolution about the axis of joint link + 1 containing this hull when it is round
  /// about it (geometry::enclosing_revolution_solid): the self pairs with this hull as
  /// their lower hull may then freeze that joint (proofs/two-ball-cover.md#revolution-route).
  std::optional<geometry::RevolutionSolid> revolution_L;
  /// For the upper hull of a self pair whose revolution route leaves only this hull's own joint
  /// moving (proofs/two-ball-cover.md#revolution-vertex-bound), else empty: its vertex clusters
  /// (geometry::cluster_vertices) with their centres, and each vertex's distance from its own
  /// joint's axis (the same at every configuration), rounded up, with each cluster's largest.
  std::vector<geometry::VertexCluster> vertex_clusters_L;
  std::vector<Eigen::Vector3d> vertex_cluster_centers_L;
  std::vector<double> own_axis_distances;
  std::vector<double> cluster_own_axis_distances;
  /// The ball the step's axis distances place (src/certify/step_axis_radius.hpp): the centre of
  /// raw_L's box and raw_L's largest distance from it, rounded up.
  /// proof: proofs/motion-bound.md#axis-distance-evaluation
  Eigen::Vector3d axis_ball_center_L = Eigen::Vector3d::Zero();
  double axis_ball_radius_up = 0.0;
};

/// \brief A self-collision pair as indices into RobotCell::hulls().
struct SelfPairHulls {
  int a = 0;  ///< hull on the lower chain link
  int b = 0;
};

/// \brief Everything that determines a cell's link offsets (minkowski_offset is a function of
/// these alone): the raw link hulls in the link frame, the expansion radius and the shape.
struct LinkOffsetInputs {
  const std::vector<LinkHull>& hulls;  ///< raw_L filled, in hulls() order
  double tolerance = 0.0;
  double expansion_radius = 0.0;
  geometry::OffsetShape offset_shape = geometry::OffsetShape::kRhombicuboctahedron;
};

/// \brief Where a cell may get its link offsets instead of building them (the set-up cache,
/// certify/setup_cache.hpp). A proposal is never trusted: the cell re-checks every proposed
/// offset exactly (geometry::recheck_offset) and builds the ones that fail.
/// proof: proofs/offset-containment.md#lemma-cached-offset
class LinkOffsetSource {
 public:
  virtual ~LinkOffsetSource() = default;
  /// Proposed vertices of every hull's offset, in inputs.hulls order; nullopt for none.
  virtual std::optional<std::vector<std::vector<Eigen::Vector3d>>> propose(
      const LinkOffsetInputs& inputs) = 0;
  /// The offsets the cell uses (expanded_L of every hull). `rejected` counts the proposed
  /// offsets that failed the re-check (all of them when the count of hulls differed).
  virtual void adopted(const LinkOffsetInputs& inputs,
                       const std::vector<std::vector<Eigen::Vector3d>>& expanded_L,
                       std::size_t rejected) = 0;
};

/// \brief The immutable verification context (model side of the model/workspace split). It
/// refers to the robot and the environment it was built from: both must outlive it.
class RobotCell {
 public:
  /// \throws InputError-free: inputs are already validated; throws geometry::DegenerateHullError
  ///         only for hulls the readers let through (never for valid files).
  RobotCell(const RobotModel& robot, const Environment& environment, const CellSettings& settings);
  /// Same cell, with the link offsets proposed by \p offsets (may be null: build them all).
  /// Proposals that pass the exact re-check give the same cell as building them would.
  RobotCell(const RobotModel& robot, const Environment& environment, const CellSettings& settings,
            LinkOffsetSource* offsets);

  const RobotModel& robot() const { return *robot_; }
  const Environment& environment() const { return *environment_; }
  /// What the cell was built for: the run reads the tolerance and offset shape here only.
  const CellSettings& settings() const { return settings_; }
  const kinematics::KinematicChain& chain() const { return chain_; }
  const std::vector<LinkHull>& hulls() const { return hulls_; }
  /// Exact hull of hull i's expanded_L (its input indices are positions in expanded_L):
  /// the combinatorial template that placed offsets are hulled from
  /// (ConvexPolytope::from_points_like).
  const geometry::ConvexPolytope& expanded_polytope_L(std::size_t i) const {
    return expanded_polytopes_L_[i];
  }
  /// Vertex graph of hull i's offset in expanded_L's numbering: GJK climbs it on the placed
  /// offset (geometry/hull_skeleton.hpp).
  const geometry::HullSkeleton& expanded_skeleton(std::size_t i) const {
    return expanded_skeletons_[i];
  }
  /// Vertex graph of hull i's raw_L (in raw_L's numbering): GJK climbs it on the placed raw
  /// hulls of a self pair.
  const geometry::HullSkeleton& raw_skeleton(std::size_t i) const { return raw_skeletons_[i]; }
  /// The obstacles: broadphase built, exact hulls and spheres built on first use.
  const ObstacleSet& obstacles() const { return obstacles_; }
  const HullRadiusTable& radii() const { return radii_; }
  /// The environment's allowed contacts (robot hull / obstacle pairs never verified), kept
  /// by the cell: the probe skips them, the certificate lists them.
  const std::vector<AllowedContactPair>& allowed_contacts() const { return allowed_contacts_; }
  bool contact_allowed(int link, int hull, int obstacle) const;
  /// robot().self_collision_pairs as hull indices, same order: the probe decides each pair,
  /// the step rule holds it to proofs/two-ball-cover.md#lemma-relative-motion.
  const std::vector<SelfPairHulls>& self_pairs() const { return self_pairs_; }
  double tolerance() const { return settings_.tolerance; }
  geometry::OffsetShape offset_shape() const { return settings_.offset_shape; }
  /// Strict upper bound on |computed placed point - exact placed point| for every point the
  /// verifier places (hull and offset vertices, sphere centres).
  /// proof: proofs/fk-rounding.md#fk-rounding
  double placement_error() const { return placement_error_; }
  /// Radius of the ball the link offsets are verified to contain: Delta + 2 * placement_error.
  /// proof: proofs/offset-containment.md#rounded-placement
  double expansion_radius() const { return expansion_radius_; }
  /// L, the largest |coordinate| of any raw hull vertex in its link frame.
  double raw_coordinate_limit() const { return raw_coordinate_limit_; }

 private:
  void build_offsets(const std::vector<geometry::ConvexPolytope>& raw_polytopes,
                     double coordinate_bound, LinkOffsetSource* offsets);
  /// Each hull's revolution_L, kept only within the FK bound's coordinate bound.
  void enclose_round_hulls(double coordinate_bound);
  /// Each hull's raw_on_template, raw_max_abs_L and expanded_template_max_abs_L.
  void choose_templates();
  /// The vertex clusters and own-axis distances of the hulls the vertex route needs
  /// (LinkHull::vertex_clusters_L); L = `coordinate_limit`, the raw vertices' largest |coordinate|.
  void prepare_vertex_routes(double coordinate_limit);
  const RobotModel* robot_;
  const Environment* environment_;
  CellSettings settings_;
  kinematics::KinematicChain chain_;
  HullRadiusTable radii_;
  double placement_error_ = 0.0;
  double expansion_radius_ = 0.0;
  double raw_coordinate_limit_ = 0.0;
  std::vector<LinkHull> hulls_;
  std::vector<geometry::ConvexPolytope> expanded_polytopes_L_;
  std::vector<geometry::HullSkeleton> expanded_skeletons_;
  std::vector<geometry::HullSkeleton> raw_skeletons_;
  ObstacleSet obstacles_;
  std::vector<AllowedContactPair> allowed_contacts_;
  std::vector<SelfPairHulls> self_pairs_;
};

/// robot.self_collision_pairs as indices into `hulls`.
/// \throws std::logic_error for a pair naming a hull `hulls` lacks.
std::vector<SelfPairHulls> self_pair_hulls(const RobotModel& robot,
                                           const std::vector<LinkHull>& hulls);

/// Largest |coordinate| of any point the verifier places for this robot (hull and offset
/// vertices, sphere centres), the input of the FK rounding bound.
double largest_link_coordinate(const std::vector<LinkHull>& hulls);

}  // namespace grpvss::certify

#include "grpvss/certify/robot_cell.hpp"

#include "step_axis_radius.hpp"  // axis_point_distance_up
#include "vertex_route.hpp"      // has_vertex_route

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/offset_recheck.hpp"
#include "grpvss/exact/polytope_skeleton.hpp"
#include "grpvss/geometry/directed_rounding.hpp"
#include "grpvss/geometry/placed_hull.hpp"
#include "grpvss/kinematics/fk_error_bound.hpp"

namespace grpvss::certify {

using geometry::max_abs_coordinate;

double largest_link_coordinate(const std::vector<LinkHull>& hulls) {
  double largest = 0.0;
  for (const LinkHull& hull : hulls) {
    largest = std::max(largest, max_abs_coordinate(hull.raw_L));
    largest = std::max(largest, max_abs_coordinate(hull.expanded_L));
    largest = std::max(largest, hull.expanded_sphere_L.center.cwiseAbs().maxCoeff());
  }
  return largest;
}

RobotCell::RobotCell(const RobotModel& robot, const Environment& environment,
                     const CellSettings& settings)
    : RobotCell(robot, environment, settings, nullptr) {}

RobotCell::RobotCell(const RobotModel& robot, const Environment& environment,
                     const CellSettings& settings, LinkOffsetSource* offsets)
    : robot_(&robot),
      environment_(&environment),
      settings_(settings),
      chain_(kinematics::make_chain(robot)),
      radii_(robot) {
  if (!(settings.tolerance > 0.0) || !std::isfinite(settings.tolerance)) {
    throw std::invalid_argument("RobotCell: tolerance must be finite and > 0");
  }
  // The offsets are built in the link frame, so the placement error bound must cover their
  // vertices too. Build with a provisional radius, measure, then rebuild once with the
  // final radius (the vertices move by far less than the 2x safety factor absorbs).
  std::vector<geometry::ConvexPolytope> raw_polytopes;
  for (int link = 0; link < static_cast<int>(robot.links.size()); ++link) {
    for (int hull = 0; hull < static_cast<int>(robot.links[link].hulls.size()); ++hull) {
      raw_polytopes.push_back(
          geometry::ConvexPolytope::from_points(robot.links[link].hulls[hull].points));
      LinkHull entry;
      entry.link = link;
      entry.hull = hull;
      entry.raw_L = raw_polytopes.back().vertices();
      raw_skeletons_.push_back(geometry::vertex_skeleton(raw_polytopes.back()));
      hulls_.push_back(std::move(entry));
    }
  }
  // Every vertex of H (+) P lies within |h| + circumradius(P) <= |h|_inf + 2 r per coordinate
  // for both shapes (cube: r, rhombicuboctahedron: r); 2x covers the retry inflation.
  double raw_extent = 0.0;
  for (const LinkHull& hull : hulls_) raw_extent = std::max(raw_extent, max_abs_coordinate(hull.raw_L));
  const double coordinate_bound = raw_extent + 2.0 * settings.tolerance + 1.0;
  // proof: proofs/fk-rounding.md#fk-rounding (the bound is strict: the lemma's bound is
  // doubled so that every use below may treat it as a strict inequality).
  const double fk_bound = kinematics::forward_kinematics_error_bound(chain_, coordinate_bound);
  // proof: proofs/offset-containment.md#rounded-placement
  // Rounded up: the checker decides expansion_radius >= Delta + 2 eps exactly (a nearest
  // rounding can land one ulp below and the certificate is then rejected).
  {
    namespace r = geometry::rounding;
    r::UpwardRoundingScope upward;
    // The stored hulls and obstacles are within their point errors of the exact ones (0 for
    // thesis files): one bound for every robot-obstacle distance the run measures.
    // proof: proofs/cell-geometry.md#lemma-geometry-error
    placement_error_ = r::mul_up(
        2.0, r::add_up(fk_bound, r::add_up(robot.hull_point_error, environment.point_error)));
    expansion_radius_ = r::add_up(settings.tolerance, r::mul_up(2.0, placement_error_));
  }
  build_offsets(raw_polytopes, coordinate_bound, offsets);
  enclose_round_hulls(coordinate_bound);
  choose_templates();
  if (largest_link_coordinate(hulls_) > coordinate_bound) {
    throw std::logic_error("RobotCell: offset vertices exceed the coordinate bound of the FK error");
  }
  obstacles_ = ObstacleSet(environment.obstacles);
  allowed_contacts_ = environment.allowed_contacts;
  self_pairs_ = self_pair_hulls(robot, hulls_);
  prepare_vertex_routes(raw_extent);
  raw_coordinate_limit_ = raw_extent;
  set_axis_balls(hulls_);
}

namespace {

// Each vertex's distance from its own link's joint axis, rounded up: any configuration bounds the
// same constant distance. proof: proofs/motion-bound.md#axis-distance-evaluation
std::vector<double> own_axis_distances_up(const RobotCell& cell, const LinkHull& hull, double coordinate_limit) {
  namespace r = geometry::rounding;
  const kinematics::PlacedAtOwnJoint placed =
      kinematics::place_at_middle_of_limits(cell.chain(), cell.robot(), hull.link, hull.raw_L);
  const std::vector<Eigen::Vector3d>& placed_W = placed.points_W;
  const Eigen::Vector3d o = placed.X_WJ.translation();
  const Eigen::Vector3d z = placed.X_WJ.linear().col(2);
  std::vector<double> parameters;
  for (const Eigen::Vector3d& v : placed_W) {
    parameters.push_back(std::clamp(z.dot(v - o), -coordinate_limit, coordinate_limit));  // any |s| <= L
  }
  std::vector<double> distances(placed_W.size());
  r::UpwardRoundingScope upward;
  for (std::size_t i = 0; i < placed_W.size(); ++i) {
    distances[i] = r::add_up(axis_point_distance_up(placed_W[i], o, z, parameters[i]), cell.placement_error());
  }
  return distances;
}

}  // namespace

// proof: proofs/two-ball-cover.md#revolution-vertex-bound
void RobotCell::prepare_vertex_routes(double coordinate_limit) {
  for (const SelfPairHulls& pair : self_pairs_) {
    LinkHull& b = hulls_[static_cast<std::size_t>(pair.b)];
    if (!has_vertex_route(*this, pair) || !b.vertex_clusters_L.empty() || b.raw_L.empty()) continue;
    b.vertex_clusters_L = geometry::cluster_vertices(b.raw_L, geometry::kVertexClusterLeaves);
    b.own_axis_distances = own_axis_distances_up(*this, b, coordinate_limit);
    for (const geometry::VertexCluster& cluster : b.vertex_clusters_L) {
      b.vertex_cluster_centers_L.push_back(cluster.center_L);
      double largest = 0.0;
      for (const int v : cluster.members) largest = std::max(largest, b.own_axis_distances[static_cast<std::size_t>(v)]);
      b.cluster_own_axis_distances.push_back(largest);
    }
  }
}

// Below kTemplateClimbMinVertices placing every vertex is cheaper than climbing the template
// (docs/performance.md#placed-templates); an offset whose points are not exactly its exact
// hull's vertex list has no template (its skeleton numbers another list).
void RobotCell::choose_templates() {
  for (std::size_t i = 0; i < hulls_.size(); ++i) {
    LinkHull& hull = hulls_[i];
    hull.raw_max_abs_L = max_abs_coordinate(hull.raw_L);
    hull.raw_on_template = hull.raw_L.size() >= geometry::kTemplateClimbMinVertices;
    const bool vertex_list = expanded_polytopes_L_[i].vertices().size() == hull.expanded_L.size();
    const bool big = hull.expanded_L.size() >= geometry::kTemplateClimbMinVertices;
    hull.expanded_template_max_abs_L = vertex_list && big ? max_abs_coordinate(hull.expanded_L) : -1.0;
  }
}

// proof: proofs/two-ball-cover.md#revolution-solid (the solid's points are placed
// within the placement error only inside the FK bound's coordinate box)
void RobotCell::enclose_round_hulls(double coordinate_bound) {
  for (LinkHull& hull : hulls_) {
    if (hull.link >= chain_.joint_count()) continue;
    const kinematics::ChainJoint& next = chain_.joints[static_cast<std::size_t>(hull.link)];
    if (next.type != JointType::kRevolute) continue;
    const geometry::JointAxisLine_L axis =
        geometry::joint_axis_line(next.X_PJ, next.X_PJ_error.rotation, next.X_PJ_error.translation);
    hull.revolution_L = geometry::enclosing_revolution_solid(hull.raw_L, axis, robot_->hull_point_error);
    if (hull.revolution_L && !(geometry::revolution_solid_extent(*hull.revolution_L) <= coordinate_bound)) {
      hull.revolution_L.reset();
    }
  }
}

std::vector<SelfPairHulls> self_pair_hulls(const RobotModel& robot,
                                           const std::vector<LinkHull>& hulls) {
  std::vector<SelfPairHulls> pairs;
  const auto index_of = [&hulls](int link, int hull) {
    for (std::size_t i = 0; i < hulls.size(); ++i) {
      if (hulls[i].link == link && hulls[i].hull == hull) return static_cast<int>(i);
    }
    throw std::logic_error("RobotCell: a self-collision pair names a hull the robot lacks");
  };
  for (const SelfCollisionPair& pair : robot.self_collision_pairs) {
    pairs.push_back({index_of(pair.link_a, pair.hull_a), index_of(pair.link_b, pair.hull_b)});
  }
  return pairs;
}

bool RobotCell::contact_allowed(int link, int hull, int obstacle) const {
  return std::binary_search(allowed_contacts_.begin(), allowed_contacts_.end(),
                            AllowedContactPair{link, hull, obstacle});
}

// Each offset is a proposal that passed the exact re-check, or built here; either way it
// contains H (+) B(0, expansion_radius). proof: proofs/offset-containment.md#lemma-cached-offset
void RobotCell::build_offsets(const std::vector<geometry::ConvexPolytope>& raw_polytopes,
                              double coordinate_bound, LinkOffsetSource* offsets) {
  const LinkOffsetInputs inputs{hulls_, settings_.tolerance, expansion_radius_,
                                settings_.offset_shape};
  std::optional<std::vector<std::vector<Eigen::Vector3d>>> proposed;
  if (offsets != nullptr) proposed = offsets->propose(inputs);
  std::size_t rejected = 0;
  if (proposed && proposed->size() != hulls_.size()) {
    rejected = hulls_.size();
    proposed.reset();
  }
  for (std::size_t i = 0; i < hulls_.size(); ++i) {
    std::optional<geometry::ConvexPolytope> checked;
    if (proposed) {
      // Also within the coordinate bound the FK error bound was computed for.
      if (max_abs_coordinate((*proposed)[i]) <= coordinate_bound) {
        checked = geometry::recheck_offset((*proposed)[i], raw_polytopes[i], expansion_radius_);
      }
      if (checked) hulls_[i].expanded_L = (*proposed)[i];
      else ++rejected;
    }
    if (!checked) {
      hulls_[i].expanded_L = geometry::minkowski_offset(raw_polytopes[i], expansion_radius_,
                                                        settings_.offset_shape)
                                 .vertices();
      checked = geometry::ConvexPolytope::from_points(hulls_[i].expanded_L);
    }
    expanded_polytopes_L_.push_back(std::move(*checked));
    expanded_skeletons_.push_back(geometry::hull_skeleton(
        expanded_polytopes_L_.back(), static_cast<int>(hulls_[i].expanded_L.size())));
    hulls_[i].raw_sphere_L = geometry::certified_sphere(hulls_[i].raw_L);
    hulls_[i].expanded_sphere_L = geometry::certified_sphere(hulls_[i].expanded_L);
    hulls_[i].expanded_box_L = geometry::Aabb::of_points(hulls_[i].expanded_L);
    hulls_[i].raw_box_L = geometry::Aabb::of_points(hulls_[i].raw_L);
  }
  if (offsets != nullptr) {
    std::vector<std::vector<Eigen::Vector3d>> expanded_L;
    for (const LinkHull& hull : hulls_) expanded_L.push_back(hull.expanded_L);
    offsets->adopted(inputs, expanded_L, rejected);
  }
}

}  // namespace grpvss::certify

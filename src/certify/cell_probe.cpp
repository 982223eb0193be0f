#include "cell_probe.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <tuple>

#include "grpvss/exact/certified_query.hpp"
#include "grpvss/exact/placed_separation.hpp"
#include "grpvss/geometry/directed_rounding.hpp"
#include "grpvss/geometry/placed_box.hpp"
#include "grpvss/geometry/placed_hull.hpp"
#include "grpvss/exact/exact_contact.hpp"
#include "sphere_slab.hpp"

namespace grpvss::certify {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Radii are certified lower bounds: every sum or difference forming one is rounded down
// (exactly, without switching the rounding mode: directed_rounding.hpp).
double add_down(double a, double b) { return geometry::rounding::nearest_mode_add_down(a, b); }
double sub_down(double a, double b) { return geometry::rounding::nearest_mode_sub_down(a, b); }

}  // namespace

double ProbeResult::link_radius(const RobotCell& cell, int link) const {
  double smallest = kInfinity;
  for (std::size_t i = 0; i < hulls.size(); ++i) {
    if (cell.hulls()[i].link == link) smallest = std::min(smallest, hulls[i].radius);
  }
  return smallest;
}

int ProbeResult::link_nearest_obstacle(const RobotCell& cell, int link) const {
  double smallest = kInfinity;
  int nearest = -1;
  for (std::size_t i = 0; i < hulls.size(); ++i) {
    if (cell.hulls()[i].link == link && hulls[i].radius < smallest) {
      smallest = hulls[i].radius;
      nearest = hulls[i].nearest_obstacle;
    }
  }
  return nearest;
}

CellProbe::CellProbe(const RobotCell& cell)
    : cell_(&cell),
      workspace_(kinematics::Workspace::frames_only(cell.chain().joints.size())),
      self_pairs_(cell),
      warm_normals_(cell.hulls().size() * static_cast<std::size_t>(cell.obstacles().size())),
      has_warm_normal_(cell.hulls().size() * static_cast<std::size_t>(cell.obstacles().size()), 0),
      anchor_bounds_(cell.hulls().size() * static_cast<std::size_t>(cell.obstacles().size()), 0.0),
      climb_hints_(cell.hulls().size() * static_cast<std::size_t>(cell.obstacles().size()), 0),
      simplex_hints_(cell.hulls().size() * static_cast<std::size_t>(cell.obstacles().size())),
      unmoved_hulls_(cell.hulls().size()),
      nearby_obstacles_(cell.hulls().size()),
      last_centers_W_(cell.hulls().size()) {}

void CellProbe::set_need(ProbeNeed need) {
  // A kept proof answers the need it was made for (a verdict's radii are far below the
  // closest): after a change every hull is decided again.
  if (need != need_) {
    for (UnmovedHull& kept : unmoved_hulls_) kept.valid = false;
  }
  need_ = need;
  self_pairs_.set_need(need);
}

void CellProbe::set_loose_terms(const LooseTerms& loose) {
  loose_hull_floors_.assign(loose.hull_floors.begin(), loose.hull_floors.end());
  self_pairs_.set_loose_pairs(loose.pair_floors);
}

bool CellProbe::reuse_unmoved_hull(int hull_index, const Eigen::Isometry3d& X_WL,
                                   ProbeResult& out) const {
  const UnmovedHull& last = unmoved_hulls_[static_cast<std::size_t>(hull_index)];
  if (!last.valid) return false;
  // Bit for bit (even -0.0 and 0.0 differ here): the same doubles in, the same decisions out.
  // The rotation and translation only: an isometry's bottom row is not part of the pose.
  for (int column = 0; column < 4; ++column) {
    if (std::memcmp(last.X_WL.matrix().col(column).data(), X_WL.matrix().col(column).data(),
                    sizeof(double) * 3) != 0) {
      return false;
    }
  }
  out.hulls[static_cast<std::size_t>(hull_index)] = last.state;
  out.evidence.insert(out.evidence.end(), last.evidence.begin(), last.evidence.end());
  return true;
}

void CellProbe::probe(const Eigen::VectorXd& q, bool with_points, ProbeResult& out) {
  out.q = q;
  out.hulls.assign(cell_->hulls().size(), HullState{});
  out.evidence.clear();
  out.interference_points.clear();
  out.any_expanded_interference = false;
  out.any_collision = false;
  out.any_self_collision = false;
  kinematics::forward_kinematics(cell_->chain(), q, workspace_);
  out.X_WL = workspace_.X_WL;
  out.X_WJ = workspace_.X_WJ;
  for (int i = 0; i < static_cast<int>(cell_->hulls().size()); ++i) probe_hull(i, with_points, out);
  // A self pair far beyond its hulls' obstacle radii needs no closer look than its balls.
  hull_radii_.resize(out.hulls.size());
  for (std::size_t i = 0; i < out.hulls.size(); ++i) hull_radii_[i] = out.hulls[i].radius;
  if (self_pairs_.probe(out.X_WL, hull_radii_, out.self_pairs)) {
    out.any_self_collision = out.any_collision = true;
  }
  sort_points(out);
}

void CellProbe::add_interference_points(ProbeResult& probed) {
  const RobotCell& cell = *cell_;
  kinematics::forward_kinematics(cell.chain(), probed.q, workspace_);
  probed.interference_points.clear();
  for (int i = 0; i < static_cast<int>(cell.hulls().size()); ++i) {
    if (!probed.hulls[static_cast<std::size_t>(i)].expanded_interferes) continue;
    const LinkHull& hull = cell.hulls()[static_cast<std::size_t>(i)];
    kinematics::place_points(workspace_.X_WL[hull.link], hull.expanded_L, placed_expanded_);
    expanded_polytope_.reset();
    for (const PairEvidence& evidence : probed.evidence) {
      if (evidence.hull_index == i && evidence.expanded && !evidence.separated) {
        append_points(i, evidence.obstacle, probed);
      }
    }
  }
  sort_points(probed);
}

void CellProbe::sort_points(ProbeResult& out) {
  // Reports must be byte-identical across runs: the exact core's point order may follow
  // memory addresses, so the points get one canonical order here.
  std::sort(out.interference_points.begin(), out.interference_points.end(),
            [](const InterferencePoint& a, const InterferencePoint& b) {
              return std::tie(a.link, a.hull, a.obstacle, a.kind, a.p_W.x(), a.p_W.y(), a.p_W.z()) <
                     std::tie(b.link, b.hull, b.obstacle, b.kind, b.p_W.x(), b.p_W.y(), b.p_W.z());
            });
}

void CellProbe::append_points(int hull_index, int obstacle, ProbeResult& out) {
  const RobotCell& cell = *cell_;
  const LinkHull& hull = cell.hulls()[static_cast<std::size_t>(hull_index)];
  // In the link frame the offset's exact hull is prebuilt and only the obstacle (8-16
  // vertices) is placed, by X_LW, and hulled from its world-frame template: the exact points
  // of that pair, mapped back by X_WL. Both frames see the true placement up to the FK
  // rounding; the points are report content, no claim rests on them
  // (docs/verification.md#interference-points).
  const Eigen::Isometry3d& X_WL = workspace_.X_WL[hull.link];
  kinematics::place_points(X_WL.inverse(), cell.obstacles().vertices_W(obstacle),
               placed_obstacle_L_);
  const geometry::ConvexPolytope obstacle_L = geometry::ConvexPolytope::from_points_like(
      placed_obstacle_L_, cell.obstacles().polytope_W(obstacle));
  const std::size_t found_before = out.interference_points.size();
  for (const auto& point : geometry::interference_points(
           cell.expanded_polytope_L(static_cast<std::size_t>(hull_index)), obstacle_L)) {
    out.interference_points.push_back(
        {hull.link, hull.hull, obstacle, X_WL * point.point, point.kind});
  }
  if (out.interference_points.size() > found_before) return;
  // The world-frame query found the pair interfering (this is only called then) but the
  // link-frame images merely touch or miss: the world-frame placed offset decides the points.
  if (!expanded_polytope_) {
    expanded_polytope_ = geometry::ConvexPolytope::from_points_like(
        placed_expanded_, cell.expanded_polytope_L(static_cast<std::size_t>(hull_index)));
  }
  for (const auto& point :
       geometry::interference_points(*expanded_polytope_, cell.obstacles().polytope_W(obstacle))) {
    out.interference_points.push_back(
        {hull.link, hull.hull, obstacle, point.point, point.kind});
  }
}

void CellProbe::probe_hull(int hull_index, bool with_points, ProbeResult& out) {
  const RobotCell& cell = *cell_;
  const LinkHull& link_hull = cell.hulls()[hull_index];
  HullProbe hull{hull_index, link_hull, workspace_.X_WL[link_hull.link]};
  if (reuse_unmoved_hull(hull_index, hull.X_WL, out)) return;
  const std::size_t evidence_before = out.evidence.size();
  HullState& state = out.hulls[hull_index];
  collect_candidates(hull, state);
  order_candidates(hull);
  for (const auto& [gap_estimate, o] : ordered_candidates_) {
    PairEvidence evidence;
    evidence.hull_index = hull_index;
    evidence.obstacle = o;
    decide_expanded(hull, o, gap_estimate, evidence);
    if (evidence.separated) {
      record_clearance(hull, state, evidence, out);
      continue;
    }
    // The expanded hull interferes: record it, then decide the raw hull.
    state.expanded_interferes = true;
    out.any_expanded_interference = true;
    out.evidence.push_back(evidence);
    if (with_points) append_points(hull_index, o, out);
    decide_raw(hull, o, state, out);
  }
  // A hull with no obstacle in reach has an unbounded radius; it is capped so that every
  // number in the certificate is finite (a smaller radius is always still a valid one).
  state.radius = std::min(state.radius, kUnboundedRadius);
  state.radius_beside_collisions = std::min(state.radius_beside_collisions, kUnboundedRadius);
  keep_unmoved_hull(hull, state, evidence_before, out);
}

// Candidate obstacles: all of them in small cells, the broadphase's otherwise.
void CellProbe::collect_candidates(HullProbe& hull, HullState& state) {
  const RobotCell& cell = *cell_;
  const int obstacle_count = cell.obstacles().size();
  candidates_.clear();
  state.broadphase_margin = kInfinity;
  hull.expanded_placed = false;
  // A verdict takes the boxes' answer in small cells too: a box apart settles an obstacle.
  if (obstacle_count <= kBroadphaseThreshold && need_ == ProbeNeed::kClearance) {
    for (int o = 0; o < obstacle_count; ++o) candidates_.push_back(o);
  } else {
    // The offset's vertices are placed only if an obstacle is a candidate (decide_expanded).
    // proof: proofs/fast-path.md#placed-box-enclosure
    const double room = 0.25 * cell.radii().radius(cell.radii().link_count() - 1, 0, 1);
    // Obstacles beyond the margin raise the hull's radius by it; a verdict needs no radius, and
    // a box apart from the hull's is strictly apart from it (margin 0).
    // proof: proofs/configuration-check.md#lemma-configuration-verdict
    state.broadphase_margin = need_ == ProbeNeed::kVerdict ? 0.0 : room;
    const geometry::Aabb query_W = geometry::placed_box_enclosure(hull.hull.expanded_box_L, hull.X_WL);
    // The tree is walked for a box with room to move; while the hull's box inflated by the
    // room stays inside it, its answer holds every candidate and a filter gives the same list.
    NearbyObstacles& nearby = nearby_obstacles_[static_cast<std::size_t>(hull.index)];
    const geometry::Aabb inflated_W = query_W.inflated(room);
    if (!nearby.box_W.contains(inflated_W)) {  // the empty box of the first query contains none
      nearby.box_W = inflated_W.inflated(room);
      cell.obstacles().index().candidates(nearby.box_W, 0.0, nearby.obstacles);
    }
    cell.obstacles().index().candidates_among(nearby.obstacles, query_W, state.broadphase_margin,
                                              candidates_);
  }
  // Allowed contacts (a cell's allowed_contacts) are never verified; the certificate lists
  // them and the checker skips the same pairs.
  if (!cell.allowed_contacts().empty()) {
    candidates_.erase(std::remove_if(candidates_.begin(), candidates_.end(),
                                     [&](int o) {
                                       return cell.contact_allowed(hull.hull.link, hull.hull.hull, o);
                                     }),
                      candidates_.end());
  }
  // proof: proofs/two-ball-cover.md#corollary-step (obstacles beyond the margin are farther
  // than Delta + margin from every true point of the hull)
  state.radius = add_down(cell.tolerance(), state.broadphase_margin);
  state.radius_beside_collisions = state.radius;
}

// Nearest first: a sphere slab is enough for every obstacle whose sphere gap is not below the
// smallest proven clearance so far; only the others need the pair query.
void CellProbe::order_candidates(HullProbe& hull) {
  const RobotCell& cell = *cell_;
  hull.center_W = hull.X_WL * hull.hull.expanded_sphere_L.center;
  std::optional<Eigen::Vector3d>& last_center_W = last_centers_W_[static_cast<std::size_t>(hull.index)];
  if (last_center_W) hull.moved = (hull.center_W - *last_center_W).norm();
  last_center_W = hull.center_W;
  hull.radius_W = placed_sphere_radius(hull.hull.expanded_sphere_L.radius_upper,
                                       cell.placement_error());
  ordered_candidates_.clear();
  for (int o : candidates_) {
    const geometry::CertifiedSphere& sphere = cell.obstacles().sphere_W(o);
    const double gap = (sphere.center - hull.center_W).norm() - hull.radius_W - sphere.radius_upper;
    ordered_candidates_.emplace_back(gap, o);
  }
  // A verdict settles each pair on its own; a clearance needs the nearest first.
  if (need_ == ProbeNeed::kClearance) std::sort(ordered_candidates_.begin(), ordered_candidates_.end());
  expanded_polytope_.reset();
}

// A separation witness for the placed offset and obstacle o, or none when they interfere.
void CellProbe::decide_expanded(HullProbe& hull, int o, double gap_estimate,
                                PairEvidence& evidence) {
  const RobotCell& cell = *cell_;
  const geometry::CertifiedSphere& sphere = cell.obstacles().sphere_W(o);
  // For a verdict any ball slab settles the pair (proofs/configuration-check.md#lemma-configuration-verdict);
  // for a clearance only one that cannot lower the hull's radius.
  const bool any_slab = need_ == ProbeNeed::kVerdict;
  if (gap_estimate > 0.0 && (any_slab || gap_estimate >= hull.smallest_clearance) &&
      sphere_witness(hull.center_W, hull.radius_W, sphere.center, sphere.radius_upper,
                     evidence.witness, evidence.lower_bound)) {
    evidence.separated = true;
    return;
  }
  const int obstacle_count = cell.obstacles().size();
  const std::size_t warm_slot = static_cast<std::size_t>(hull.index) * obstacle_count + o;
  if (separate_by_kept_normal(hull, o, warm_slot, evidence)) return;
  if (separate_by_template(hull, o, warm_slot, evidence)) return;
  place_expanded(hull);
  const geometry::CertifiedPairResult result = geometry::certified_pair_query(
      placed_expanded_, cell.obstacles().vertices_W(o),
      has_warm_normal_[warm_slot] ? &warm_normals_[warm_slot] : nullptr,
      &cell.expanded_skeleton(static_cast<std::size_t>(hull.index)), &climb_hints_[warm_slot]);
  if (result.contact == geometry::Contact::kSeparated && result.witness) {
    keep_separation(result, warm_slot, evidence);
  }
}

// The witness proven is the one a scan of the placed offset would prove
// (proofs/fast-path.md#placed-separation); the checker re-checks it on every placed vertex.
std::optional<geometry::PlacedHull> CellProbe::offset_template(const HullProbe& hull) const {
  const double max_abs_L = hull.hull.expanded_template_max_abs_L;
  if (!(max_abs_L >= 0.0)) return std::nullopt;
  geometry::PlacedHull offset;
  offset.vertices_L = &hull.hull.expanded_L;
  offset.skeleton = &cell_->expanded_skeleton(static_cast<std::size_t>(hull.index));
  offset.X_WL = hull.X_WL;
  offset.max_abs_L = max_abs_L;
  return offset;
}

// Any proven slab is evidence (the checker re-checks it on every placed vertex); the hull's
// radius is the smallest clearance over its obstacles, which a bound not below the smallest so
// far leaves as it is. proof: proofs/fast-path.md#placed-separation
bool CellProbe::separate_by_kept_normal(HullProbe& hull, int o, std::size_t warm_slot,
                                        PairEvidence& evidence) {
  if (!has_warm_normal_[warm_slot]) return false;
  // The bound the kept normal must reach: for a verdict any (a returned slab has a positive
  // gap); else a farther obstacle's must not lower the hull's radius, and a loose hull's
  // nearest keeps kLooseKeep of its last closest witness's and the radius its floor asks
  // (radius = Delta + bound).
  const bool any_slab = need_ == ProbeNeed::kVerdict;
  const bool nearest = !(hull.smallest_clearance < kInfinity);
  const auto h = static_cast<std::size_t>(hull.index);
  const bool loose = nearest && h < loose_hull_floors_.size() && loose_hull_floors_[h] < kInfinity;
  if (!any_slab && nearest && !loose) return false;
  const double required =
      any_slab ? 0.0
      : loose  ? std::max(kLooseKeep * anchor_bounds_[warm_slot], loose_hull_floors_[h] - cell_->tolerance())
               : hull.smallest_clearance;
  if (!any_slab && !(required > 0.0)) return false;
  // After a long move the kept normal is stale: its bound would mostly fall short (wasted climbs).
  if (!(hull.moved < (any_slab || loose ? anchor_bounds_[warm_slot] : required))) return false;
  const std::optional<geometry::CertifiedSeparation> separation = kept_normal_slab(hull, o, warm_slot);
  if (!separation || !(separation->lower_bound >= required)) return false;
  evidence.separated = true;
  evidence.witness = separation->witness;
  evidence.lower_bound = separation->lower_bound;
  return true;
}

// On the template, the slab a scan of the placed offset would prove
// (proofs/fast-path.md#placed-separation). Below the template size the offset is placed (cheaper
// than climbing, docs/performance.md#placed-templates) and the normal is proven on every placed
// vertex, as GJK's is in the full query (proofs/fast-path.md#certified-separation).
std::optional<geometry::CertifiedSeparation> CellProbe::kept_normal_slab(HullProbe& hull, int o,
                                                                        std::size_t warm_slot) {
  const std::vector<Eigen::Vector3d>& obstacle_W = cell_->obstacles().vertices_W(o);
  if (const std::optional<geometry::PlacedHull> offset = offset_template(hull)) {
    return geometry::certify_placed_separation(*offset, climb_hints_[warm_slot], obstacle_W,
                                               warm_normals_[warm_slot]);
  }
  place_expanded(hull);
  return geometry::certify_separation(placed_expanded_, obstacle_W, warm_normals_[warm_slot]);
}

void CellProbe::place_expanded(HullProbe& hull) {
  if (hull.expanded_placed) return;
  kinematics::place_points(hull.X_WL, hull.hull.expanded_L, placed_expanded_);
  hull.expanded_placed = true;
}

bool CellProbe::separate_by_template(const HullProbe& hull, int o, std::size_t warm_slot,
                                     PairEvidence& evidence) {
  const RobotCell& cell = *cell_;
  const std::optional<geometry::PlacedHull> offset = offset_template(hull);
  if (!offset) return false;
  const auto result = geometry::certified_placed_separation_query(
      *offset, cell.obstacles().vertices_W(o),
      has_warm_normal_[warm_slot] ? &warm_normals_[warm_slot] : nullptr, &climb_hints_[warm_slot],
      &simplex_hints_[warm_slot]);
  if (!result) return false;
  keep_separation(*result, warm_slot, evidence);
  return true;
}

void CellProbe::keep_separation(const geometry::CertifiedPairResult& result, std::size_t warm_slot,
                                PairEvidence& evidence) {
  evidence.separated = true;
  evidence.witness = *result.witness;
  evidence.lower_bound = result.clearance_lower_bound;
  warm_normals_[warm_slot] = result.witness->normal;
  has_warm_normal_[warm_slot] = 1;
  anchor_bounds_[warm_slot] = result.clearance_lower_bound;
}

void CellProbe::record_clearance(HullProbe& hull, HullState& state, const PairEvidence& evidence,
                                 ProbeResult& out) {
  hull.smallest_clearance = std::min(hull.smallest_clearance, evidence.lower_bound);
  // proof: proofs/offset-containment.md#clearance-through-offset
  const double radius = add_down(cell_->tolerance(), evidence.lower_bound);
  if (radius < state.radius) {
    state.radius = radius;
    state.nearest_obstacle = evidence.obstacle;
  }
  state.radius_beside_collisions = std::min(state.radius_beside_collisions, radius);
  out.evidence.push_back(evidence);
}

// The expanded hull interferes with obstacle o: the raw hull either keeps a proven clearance
// from it or collides.
void CellProbe::decide_raw(HullProbe& hull, int o, HullState& state, ProbeResult& out) {
  const RobotCell& cell = *cell_;
  if (!hull.raw_placed) {
    kinematics::place_points(hull.X_WL, hull.hull.raw_L, placed_raw_);
    hull.raw_placed = true;
  }
  PairEvidence raw;
  raw.hull_index = hull.index;
  raw.obstacle = o;
  raw.expanded = false;
  const geometry::CertifiedPairResult raw_result =
      geometry::certified_pair_query(placed_raw_, cell.obstacles().vertices_W(o), nullptr);
  if (raw_result.contact != geometry::Contact::kSeparated) {
    state.raw_collides = true;
    out.any_collision = true;
    state.radius = 0.0;
    state.nearest_obstacle = o;
    out.evidence.push_back(raw);
    return;
  }
  // proof: proofs/two-ball-cover.md#corollary-step (raw radius: lb - eps < true distance)
  // A gap too small for any double witness (~1e-16) proves nothing usable: radius 0.
  double radius = 0.0;
  if (raw_result.witness) {
    raw.separated = true;
    raw.witness = *raw_result.witness;
    raw.lower_bound = raw_result.clearance_lower_bound;
    radius = std::max(0.0, sub_down(raw.lower_bound, cell.placement_error()));
    out.evidence.push_back(raw);
  }
  if (radius < state.radius) {
    state.radius = radius;
    state.nearest_obstacle = o;
  }
  state.radius_beside_collisions = std::min(state.radius_beside_collisions, radius);
}

void CellProbe::keep_unmoved_hull(const HullProbe& hull, const HullState& state,
                                  std::size_t evidence_before, const ProbeResult& out) {
  UnmovedHull& kept = unmoved_hulls_[static_cast<std::size_t>(hull.index)];
  kept.valid = !state.expanded_interferes;  // no points, no raw query to replay
  if (!kept.valid) return;
  kept.X_WL = hull.X_WL;
  kept.state = state;
  kept.evidence.assign(out.evidence.begin() + static_cast<std::ptrdiff_t>(evidence_before),
                       out.evidence.end());
}

}  // namespace grpvss::certify

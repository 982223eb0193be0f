#include "self_pair_probe.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "grpvss/common/next_double.hpp"
#include "grpvss/exact/certified_query.hpp"
#include "grpvss/exact/placed_separation.hpp"
#include "grpvss/geometry/directed_rounding.hpp"
#include "grpvss/geometry/placed_box.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "sphere_slab.hpp"

namespace grpvss::certify {

// proof: proofs/cell-geometry.md#lemma-geometry-error (each of the two placed hulls is within
// placement_error of its exact placement)
double exact_distance_lower_bound(double lower_bound, double placement_error) {
  namespace r = geometry::rounding;
  const double twice = r::nearest_mode_add_up(placement_error, placement_error);
  if (!std::isfinite(twice) || !(lower_bound > twice)) return 0.0;
  return std::max(0.0, r::nearest_mode_sub_down(lower_bound, twice));
}

SelfPairProbe::SelfPairProbe(const RobotCell& cell)
    : cell_(&cell),
      placed_raw_(cell.hulls().size()),
      is_placed_(cell.hulls().size(), 0),
      placed_boxes_W_(cell.hulls().size()),
      is_box_placed_(cell.hulls().size(), 0),
      warm_normals_(cell.self_pairs().size()),
      has_warm_normal_(cell.self_pairs().size(), 0),
      anchor_bounds_(cell.self_pairs().size(), 0.0),
      climb_hints_a_(cell.self_pairs().size(), 0),
      climb_hints_b_(cell.self_pairs().size(), 0),
      simplex_hints_(cell.self_pairs().size()) {}

geometry::PlacedHull SelfPairProbe::template_placed(int hull,
                                                    const std::vector<Eigen::Isometry3d>& X_WL) const {
  const auto h = static_cast<std::size_t>(hull);
  const LinkHull& link_hull = cell_->hulls()[h];
  geometry::PlacedHull placed;
  placed.vertices_L = &link_hull.raw_L;
  placed.skeleton = &cell_->raw_skeleton(h);
  placed.X_WL = X_WL[static_cast<std::size_t>(link_hull.link)];
  placed.max_abs_L = link_hull.raw_max_abs_L;
  return placed;
}

// Only the vertices around each support are placed, and the witness proven is the one a scan
// of the placed points would prove (proofs/fast-path.md#placed-separation).
bool SelfPairProbe::settle_by_templates(std::size_t p, const std::vector<Eigen::Isometry3d>& X_WL,
                                        SelfPairEvidence& evidence) {
  const SelfPairHulls& pair = cell_->self_pairs()[p];
  const auto on_template = [&](int hull) { return cell_->hulls()[static_cast<std::size_t>(hull)].raw_on_template; };
  if (!on_template(pair.a) && !on_template(pair.b)) return false;
  const auto result = geometry::certified_placed_separation_query(
      template_placed(pair.a, X_WL), template_placed(pair.b, X_WL),
      has_warm_normal_[p] ? &warm_normals_[p] : nullptr, &climb_hints_a_[p], &climb_hints_b_[p],
      &simplex_hints_[p]);
  if (!result) return false;
  keep(p, *result, evidence);
  return true;
}

void SelfPairProbe::set_loose_pairs(const std::vector<double>& floors) {
  loose_floors_.assign(floors.begin(), floors.end());
}

// Any proven slab is evidence (proofs/fast-path.md#placed-separation; the checker re-checks it
// on every placed vertex); only its distance, the pair's allowance, is a little smaller.
bool SelfPairProbe::settle_by_kept_normal(std::size_t p, const std::vector<Eigen::Isometry3d>& X_WL,
                                          SelfPairEvidence& evidence) {
  // For a verdict every pair is settled by any slab proving a positive distance
  // (proofs/configuration-check.md#lemma-configuration-verdict).
  const bool any_slab = need_ == ProbeNeed::kVerdict;
  const bool loose = p < loose_floors_.size() && loose_floors_[p] < std::numeric_limits<double>::infinity();
  if (!(any_slab || loose) || !has_warm_normal_[p] || !(anchor_bounds_[p] > 0.0)) return false;
  const std::optional<geometry::CertifiedSeparation> separation = kept_normal_slab(p, X_WL);
  if (!separation) return false;
  const double distance = exact_distance_lower_bound(separation->lower_bound, cell_->placement_error());
  if (any_slab ? !(distance > 0.0)
               : !(separation->lower_bound >= kLooseKeep * anchor_bounds_[p]) || !(distance >= loose_floors_[p])) {
    return false;
  }
  evidence.separated = true;
  evidence.witness = separation->witness;
  evidence.lower_bound = separation->lower_bound;
  evidence.distance = distance;
  return true;
}

// On the templates, the slab a scan of the placed hulls would prove
// (proofs/fast-path.md#placed-separation). Two hulls below the template size are placed
// (cheaper than climbing, docs/performance.md#placed-templates) and the normal is proven on
// every placed vertex, as GJK's is in the full query (proofs/fast-path.md#certified-separation).
std::optional<geometry::CertifiedSeparation> SelfPairProbe::kept_normal_slab(
    std::size_t p, const std::vector<Eigen::Isometry3d>& X_WL) {
  const SelfPairHulls& pair = cell_->self_pairs()[p];
  const auto on_template = [&](int hull) { return cell_->hulls()[static_cast<std::size_t>(hull)].raw_on_template; };
  if (on_template(pair.a) || on_template(pair.b)) {
    return geometry::certify_placed_separation(template_placed(pair.a, X_WL), climb_hints_a_[p],
                                               template_placed(pair.b, X_WL), climb_hints_b_[p],
                                               warm_normals_[p]);
  }
  const std::vector<Eigen::Vector3d>& a = placed(pair.a, X_WL);
  return geometry::certify_separation(a, placed(pair.b, X_WL), warm_normals_[p]);
}

void SelfPairProbe::keep(std::size_t p, const geometry::CertifiedPairResult& result,
                         SelfPairEvidence& evidence) {
  anchor_bounds_[p] = result.clearance_lower_bound;
  evidence.separated = true;
  evidence.witness = *result.witness;
  evidence.lower_bound = result.clearance_lower_bound;
  evidence.distance = exact_distance_lower_bound(result.clearance_lower_bound,
                                                 cell_->placement_error());
  warm_normals_[p] = result.witness->normal;
  has_warm_normal_[p] = 1;
}

const std::vector<Eigen::Vector3d>& SelfPairProbe::placed(
    int hull, const std::vector<Eigen::Isometry3d>& X_WL) {
  const auto h = static_cast<std::size_t>(hull);
  if (!is_placed_[h]) {
    const LinkHull& link_hull = cell_->hulls()[h];
    kinematics::place_points(X_WL[static_cast<std::size_t>(link_hull.link)], link_hull.raw_L,
                             placed_raw_[h]);
    is_placed_[h] = 1;
  }
  return placed_raw_[h];
}

// proof: proofs/configuration-check.md#lemma-configuration-verdict (case W with an axis slab:
// every computed placed point lies in its hull's placed box, proofs/fast-path.md#placed-box-enclosure)
bool SelfPairProbe::settle_by_boxes(const SelfPairHulls& pair, const std::vector<Eigen::Isometry3d>& X_WL,
                                    SelfPairEvidence& evidence) {
  const auto box_W = [&](int hull) -> const geometry::Aabb& {
    const auto h = static_cast<std::size_t>(hull);
    if (!is_box_placed_[h]) {
      const LinkHull& link_hull = cell_->hulls()[h];
      placed_boxes_W_[h] = geometry::placed_box_enclosure(link_hull.raw_box_L,
                                                          X_WL[static_cast<std::size_t>(link_hull.link)]);
      is_box_placed_[h] = 1;
    }
    return placed_boxes_W_[h];
  };
  const geometry::Aabb& a = box_W(pair.a);
  const geometry::Aabb& b = box_W(pair.b);
  // The widest gap between the boxes along an axis: n = +-e_k, |n| = 1 exactly.
  double best_gap = 0.0;
  geometry::SeparationWitness witness;
  for (int k = 0; k < 3; ++k) {
    const double above = geometry::rounding::nearest_mode_sub_down(b.lo[k], a.hi[k]);  // b beyond a
    const double below = geometry::rounding::nearest_mode_sub_down(a.lo[k], b.hi[k]);  // b before a
    if (above > best_gap) {
      best_gap = above;
      witness.normal = Eigen::Vector3d::Unit(k);
      witness.offset_a = a.hi[k];
      witness.offset_b = b.lo[k];
    }
    if (below > best_gap) {
      best_gap = below;
      witness.normal = -Eigen::Vector3d::Unit(k);
      witness.offset_a = -a.lo[k];
      witness.offset_b = -b.hi[k];
    }
  }
  if (!(best_gap > 0.0)) return false;
  const double distance = exact_distance_lower_bound(best_gap, cell_->placement_error());
  if (!(distance > 0.0)) return false;
  evidence.separated = true;
  evidence.witness = witness;
  evidence.lower_bound = best_gap;
  evidence.distance = distance;
  return true;
}

bool SelfPairProbe::settle_by_balls(const SelfPairHulls& pair,
                                    const std::vector<Eigen::Isometry3d>& X_WL, double ample,
                                    SelfPairEvidence& evidence) const {
  const auto ball_W = [&](int hull, Eigen::Vector3d& center_W, double& radius_W) {
    const LinkHull& link_hull = cell_->hulls()[static_cast<std::size_t>(hull)];
    center_W = X_WL[static_cast<std::size_t>(link_hull.link)] * link_hull.raw_sphere_L.center;
    radius_W = placed_sphere_radius(link_hull.raw_sphere_L.radius_upper, cell_->placement_error());
  };
  Eigen::Vector3d center_a, center_b;
  double radius_a = 0.0, radius_b = 0.0;
  ball_W(pair.a, center_a, radius_a);
  ball_W(pair.b, center_b, radius_b);
  // A cheap estimate first: most pairs are either far apart or close.
  if (!((center_b - center_a).norm() - radius_a - radius_b >= ample)) return false;
  geometry::SeparationWitness witness;
  double lower_bound = 0.0;
  // proof: proofs/separation-witness.md#sphere-slab (each placed hull lies in its placed ball)
  if (!sphere_witness(center_a, radius_a, center_b, radius_b, witness, lower_bound)) return false;
  const double distance = exact_distance_lower_bound(lower_bound, cell_->placement_error());
  if (!(distance >= ample)) return false;
  evidence.separated = true;
  evidence.witness = witness;
  evidence.lower_bound = lower_bound;
  evidence.distance = distance;
  return true;
}

// proof: proofs/two-ball-cover.md#revolution-route
void SelfPairProbe::add_revolution_bound(const SelfPairHulls& pair,
                                         const std::vector<Eigen::Isometry3d>& X_WL,
                                         SelfPairEvidence& evidence) const {
  const LinkHull& a = cell_->hulls()[static_cast<std::size_t>(pair.a)];
  // The route bounds a step's motion: a verdict has no step.
  if (need_ == ProbeNeed::kVerdict || !a.revolution_L || !evidence.separated) return;
  geometry::SeparationWitness solid_side = evidence.witness;
  solid_side.offset_a = geometry::placed_solid_support_upper(
      *a.revolution_L, X_WL[static_cast<std::size_t>(a.link)], evidence.witness.normal);
  if (!(solid_side.offset_a < solid_side.offset_b)) return;
  evidence.revolution_lower_bound = geometry::certified_lower_bound(solid_side);
  evidence.revolution_distance =
      exact_distance_lower_bound(evidence.revolution_lower_bound, cell_->placement_error());
}

bool SelfPairProbe::probe(const std::vector<Eigen::Isometry3d>& X_WL,
                          const std::vector<double>& hull_radius,
                          std::vector<SelfPairEvidence>& out) {
  const std::vector<SelfPairHulls>& pairs = cell_->self_pairs();
  out.assign(pairs.size(), SelfPairEvidence{});
  std::fill(is_placed_.begin(), is_placed_.end(), 0);
  std::fill(is_box_placed_.begin(), is_box_placed_.end(), 0);
  bool any_contact = false;
  // The distance a ball slab must prove to settle a pair: any positive one for a verdict, the
  // sum of the hulls' radii for a clearance; without radii the balls are not tried.
  const bool balls_may_settle = need_ == ProbeNeed::kVerdict || !hull_radius.empty();
  const auto ample = [&](const SelfPairHulls& pair) {
    if (need_ == ProbeNeed::kVerdict) return next_up(0.0);  // not denorm_min: see next_up
    return hull_radius[static_cast<std::size_t>(pair.a)] + hull_radius[static_cast<std::size_t>(pair.b)];
  };
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    if (balls_may_settle && settle_by_balls(pairs[p], X_WL, ample(pairs[p]), out[p])) {
      add_revolution_bound(pairs[p], X_WL, out[p]);
      continue;
    }
    // Boxes apart where balls meet: long links side by side (a verdict only).
    if (need_ == ProbeNeed::kVerdict && settle_by_boxes(pairs[p], X_WL, out[p])) continue;
    if (settle_by_kept_normal(p, X_WL, out[p]) || settle_by_templates(p, X_WL, out[p])) {
      add_revolution_bound(pairs[p], X_WL, out[p]);
      continue;
    }
    const std::vector<Eigen::Vector3d>& a = placed(pairs[p].a, X_WL);
    const std::vector<Eigen::Vector3d>& b = placed(pairs[p].b, X_WL);
    // GJK climbs both hulls' skeletons (it only proposes: the witness is certified over
    // every vertex, proofs/fast-path.md#certified-query).
    const geometry::CertifiedPairResult result = geometry::certified_pair_query(
        a, b, has_warm_normal_[p] ? &warm_normals_[p] : nullptr,
        &cell_->raw_skeleton(static_cast<std::size_t>(pairs[p].a)), &climb_hints_a_[p],
        &cell_->raw_skeleton(static_cast<std::size_t>(pairs[p].b)), &climb_hints_b_[p]);
    SelfPairEvidence& evidence = out[p];
    if (result.contact != geometry::Contact::kSeparated) {
      evidence.contact = true;
      any_contact = true;
      continue;
    }
    // A gap too small for a double slab (~1e-16) proves no usable distance: neither separated
    // nor a contact (the step rule cannot pass it; it is no collision either).
    if (!result.witness) continue;
    keep(p, result, evidence);
    add_revolution_bound(pairs[p], X_WL, evidence);
  }
  return any_contact;
}

}  // namespace grpvss::certify

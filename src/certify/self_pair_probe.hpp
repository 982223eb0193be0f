#pragma once
// Self-collision at one configuration: for every self pair of the cell (two hulls on chain
// links at least two apart), a certified lower bound of the distance between the two exactly
// placed raw hulls, or their contact. proof: proofs/two-ball-cover.md#lemma-relative-motion

#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/exact/certified_query.hpp"
#include "grpvss/geometry/broadphase.hpp"
#include "grpvss/geometry/gjk.hpp"
#include "grpvss/geometry/placed_hull.hpp"
#include "grpvss/geometry/separation_witness.hpp"
#include "loose_terms.hpp"
#include "probe_need.hpp"

namespace grpvss::certify {

/// \brief The proof about one self-collision pair (RobotCell::self_pairs()) at one
/// configuration: both raw hulls placed, a separating slab or their contact.
struct SelfPairEvidence {
  bool separated = false;  ///< a witness proves the distance below
  bool contact = false;    ///< the two hulls meet: a self-collision (never with `separated`)
  geometry::SeparationWitness witness;  ///< valid when separated; from hull a to hull b
  double lower_bound = 0.0;  ///< certified lower bound of the placed hulls' distance
  /// Certified lower bound of the exactly placed hulls' distance: lower_bound minus twice the
  /// placement error, at least 0. proof: proofs/cell-geometry.md#lemma-geometry-error
  double distance = 0.0;
  /// When hull a has a solid of revolution about joint a+1 (LinkHull::revolution_L): a certified lower
  /// bound of the distance from the placed solid to placed hull b on the witness's normal
  /// (0: none), and the same less twice the placement error (the route's d).
  /// proof: proofs/two-ball-cover.md#revolution-route
  double revolution_lower_bound = 0.0;
  double revolution_distance = 0.0;
};

/// \brief d = lower_bound - 2 placement_error rounded down, at least 0: each placed hull is
/// within placement_error of its exact placement (Hausdorff), so the exact hulls are farther
/// apart than d. proof: proofs/cell-geometry.md#lemma-geometry-error
double exact_distance_lower_bound(double lower_bound, double placement_error);

/// \brief Per-query buffers and warm starts for the self pairs of one cell.
class SelfPairProbe {
 public:
  explicit SelfPairProbe(const RobotCell& cell);
  /// Decides every self pair at the link poses X_WL; `out` gets one entry per pair. True when
  /// some pair's hulls meet.
  /// \param hull_radius per hull (RobotCell::hulls() order), empty or the hulls' clearance
  ///        radii from the obstacles at X_WL: a pair (a, b) whose placed balls are proven at
  ///        least hull_radius[a] + hull_radius[b] apart keeps that ball slab as its evidence,
  ///        without GJK or a vertex scan. The slab is a valid witness whatever the threshold;
  ///        this one keeps the pair from limiting a step more than its hulls' obstacles do
  ///        (the pair's motion bound is at most the sum of its hulls' bounds, each of which
  ///        the step must keep below that hull's allowance). Empty: every pair is decided by
  ///        its closest witness.
  bool probe(const std::vector<Eigen::Isometry3d>& X_WL, const std::vector<double>& hull_radius,
             std::vector<SelfPairEvidence>& out);
  /// [pair]: the pairs later probes may settle on their kept normals, and the distance each
  /// must keep (LooseTerms::pair_floors).
  void set_loose_pairs(const std::vector<double>& floors);
  /// What later probes must prove of each pair (kClearance at first). kVerdict: any slab proving
  /// a positive distance settles a pair, `hull_radius` aside.
  void set_need(ProbeNeed need) { need_ = need; }

 private:
  const std::vector<Eigen::Vector3d>& placed(int hull, const std::vector<Eigen::Isometry3d>& X_WL);
  /// Hull `hull`'s raw template under its link's pose, for queries that place only what they visit.
  geometry::PlacedHull template_placed(int hull, const std::vector<Eigen::Isometry3d>& X_WL) const;
  /// Pair p decided on the two raw templates under X_WL when one hull is big enough to be
  /// worth it (geometry::kTemplateClimbMinVertices); false when that proves nothing.
  bool settle_by_templates(std::size_t p, const std::vector<Eigen::Isometry3d>& X_WL,
                           SelfPairEvidence& evidence);
  /// A loose pair's last witness normal proven again (kept_normal_slab; no GJK), kept when
  /// its bound is at least kLooseKeep of the bound the normal was found with and its distance
  /// is at least the pair's floor.
  bool settle_by_kept_normal(std::size_t p, const std::vector<Eigen::Isometry3d>& X_WL,
                             SelfPairEvidence& evidence);
  /// The slab pair p's kept witness normal proves: on the two templates when one hull is big
  /// enough for them, else on the two placed hulls.
  std::optional<geometry::CertifiedSeparation> kept_normal_slab(std::size_t p,
                                                                const std::vector<Eigen::Isometry3d>& X_WL);
  /// Keeps a proven separation of pair p as its evidence and its normal as the next warm start.
  void keep(std::size_t p, const geometry::CertifiedPairResult& result, SelfPairEvidence& evidence);
  /// The revolution route's distances of a separated pair whose hull a has a solid of revolution: the
  /// witness's normal, its side at hull b, and the placed solid's support on the other.
  void add_revolution_bound(const SelfPairHulls& pair, const std::vector<Eigen::Isometry3d>& X_WL,
                            SelfPairEvidence& evidence) const;
  /// For a verdict: an axis slab between the two hulls' placed boxes, kept in `evidence` when
  /// it proves a positive distance (false otherwise).
  bool settle_by_boxes(const SelfPairHulls& pair, const std::vector<Eigen::Isometry3d>& X_WL,
                       SelfPairEvidence& evidence);
  /// The slab of the two hulls' placed balls, kept in `evidence` when it proves at least
  /// `ample` (false otherwise).
  bool settle_by_balls(const SelfPairHulls& pair, const std::vector<Eigen::Isometry3d>& X_WL,
                       double ample, SelfPairEvidence& evidence) const;

  const RobotCell* cell_;
  ProbeNeed need_ = ProbeNeed::kClearance;
  std::vector<std::vector<Eigen::Vector3d>> placed_raw_;  ///< [hull], this probe's
  std::vector<char> is_placed_;
  std::vector<geometry::Aabb> placed_boxes_W_;  ///< [hull], this probe's (settle_by_boxes)
  std::vector<char> is_box_placed_;
  std::vector<Eigen::Vector3d> warm_normals_;  ///< [pair]
  std::vector<char> has_warm_normal_;
  std::vector<double> anchor_bounds_;  ///< [pair]: the lower bound the kept normal was found with
  std::vector<double> loose_floors_;   ///< [pair], set_loose_pairs()
  std::vector<int> climb_hints_a_;  ///< [pair]: where GJK's climb on hull a starts
  std::vector<int> climb_hints_b_;  ///< [pair]: the same on hull b
  std::vector<geometry::GjkSimplexHint> simplex_hints_;  ///< [pair]: GJK's last simplex on the templates
};

}  // namespace grpvss::certify

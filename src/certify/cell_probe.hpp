#pragma once
/// \file
/// \brief Evaluates one configuration: places every link hull and its tolerance offset,
/// decides interference of the expanded robot with every obstacle, and proves for each hull
/// a radius r_h such that the open ball of radius r_h around every point of the TRUE
/// (exactly placed) hull is free of obstacles. Every proof is kept as evidence.

#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/exact/certified_query.hpp"
#include "grpvss/geometry/gjk.hpp"
#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/evidence/certificate.hpp"
#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/geometry/separation_witness.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "loose_terms.hpp"
#include "probe_need.hpp"
#include "self_pair_probe.hpp"

namespace grpvss::certify {

/// \brief The proof about one (link hull, obstacle) pair at one configuration.
struct PairEvidence {
  int hull_index = 0;      ///< into RobotCell::hulls()
  int obstacle = 0;
  bool expanded = true;    ///< about the placed offset (true) or the placed raw hull (false)
  bool separated = false;  ///< false: the pair interferes (no witness)
  geometry::SeparationWitness witness;  ///< valid when separated
  double lower_bound = 0.0;             ///< certified distance lower bound of the witness
};

/// \brief What one configuration proves about one link hull.
struct HullState {
  bool expanded_interferes = false;  ///< the expanded hull meets some obstacle
  bool raw_collides = false;         ///< the raw hull meets some obstacle
  /// Certified: every point of the true hull is farther than `radius` from every obstacle
  /// (strictly). 0 when the raw hull collides.
  /// proof: proofs/two-ball-cover.md#corollary-step
  double radius = 0.0;
  int nearest_obstacle = -1;   ///< the obstacle that governs `radius` (-1: broadphase margin)
  /// As `radius`, over the obstacles the raw hull does not collide with (= radius when it
  /// collides with none).
  double radius_beside_collisions = 0.0;
  /// Obstacles without explicit evidence are farther than this from the placed offset
  /// (broadphase, exact box test); +inf when every obstacle has evidence.
  double broadphase_margin = 0.0;
};

struct ProbeResult {
  Eigen::VectorXd q;
  /// X_WL[i]: link frame i's pose as forward kinematics computed it for q (i = 0..N).
  std::vector<Eigen::Isometry3d> X_WL;
  /// X_WJ[j-1]: joint frame J_j (its z axis is joint j's axis), as forward kinematics computed it.
  std::vector<Eigen::Isometry3d> X_WJ;
  /// D_jh at `axis_distances_q` (step_axis_radius.hpp), kept by the certified march so that each
  /// configuration's axis distances are evaluated once; stale when axis_distances_q != q.
  std::vector<double> axis_distances;
  Eigen::VectorXd axis_distances_q;
  std::vector<HullState> hulls;  ///< index = RobotCell::hulls() index
  std::vector<PairEvidence> evidence;
  std::vector<InterferencePoint> interference_points;  ///< filled only when requested
  /// One per RobotCell::self_pairs() entry, in that order (empty without self pairs).
  std::vector<SelfPairEvidence> self_pairs;
  bool any_expanded_interference = false;
  bool any_collision = false;       ///< with an obstacle or (any_self_collision) of the robot
  bool any_self_collision = false;  ///< two hulls of a self pair meet

  /// Smallest hull radius of a link (the link's certified clearance at this configuration).
  double link_radius(const RobotCell& cell, int link) const;
  /// The obstacle that governs link_radius (-1 when no obstacle is within the margins).
  int link_nearest_obstacle(const RobotCell& cell, int link) const;
};

/// \brief Per-query buffers and warm starts (workspace side of the model/workspace split).
class CellProbe {
 public:
  explicit CellProbe(const RobotCell& cell);

  /// The terms later probes may settle on their kept normals (until the next call).
  void set_loose_terms(const LooseTerms& loose);

  /// What later probes must prove of each term (until the next call; kClearance at first).
  void set_need(ProbeNeed need);

  /// Evaluates configuration q. `with_points`: also compute the exact interference points.
  void probe(const Eigen::VectorXd& q, bool with_points, ProbeResult& out);

  /// Adds to a result of probe(q, false, ...) the exact interference points that
  /// probe(q, true, ...) would have found: those of the pairs its evidence shows interfering,
  /// without deciding every pair again.
  void add_interference_points(ProbeResult& probed);

  /// Obstacle count above which the broadphase is used instead of testing every obstacle.
  static constexpr int kBroadphaseThreshold = 16;

 private:
  /// One hull's probe in progress.
  struct HullProbe {
    int index = 0;
    const LinkHull& hull;
    const Eigen::Isometry3d& X_WL;
    Eigen::Vector3d center_W = Eigen::Vector3d::Zero();  ///< of the placed offset's sphere
    double radius_W = 0.0;
    bool expanded_placed = false;  ///< placed_expanded_ holds this hull's placed offset
    bool raw_placed = false;       ///< placed_raw_ holds this hull's placed raw hull
    double smallest_clearance = std::numeric_limits<double>::infinity();
    /// How far the sphere's centre moved since this CellProbe's last probe of the hull
    /// (infinity at the first): kept normals are tried only after a small move.
    double moved = std::numeric_limits<double>::infinity();
  };
  void probe_hull(int hull_index, bool with_points, ProbeResult& out);
  void collect_candidates(HullProbe& hull, HullState& state);
  void order_candidates(HullProbe& hull);
  void decide_expanded(HullProbe& hull, int obstacle, double gap_estimate, PairEvidence& evidence);
  /// decide_expanded's first try: the offset's template under X_WL against the obstacle,
  /// placing only the vertices visited. False when that proves nothing.
  bool separate_by_template(const HullProbe& hull, int obstacle, std::size_t warm_slot,
                            PairEvidence& evidence);
  /// Before that, once a nearer obstacle has set the hull's smallest clearance: the pair's
  /// last witness normal proven again (kept_normal_slab; no GJK). Taken only when its bound does
  /// not lower that clearance, so the hull's radius is the one the full query gives. For a
  /// loose hull's nearest obstacle, taken when its bound keeps kLooseKeep of the bound the
  /// normal was found with and the hull's radius its floor (LooseTerms::hull_floors).
  bool separate_by_kept_normal(HullProbe& hull, int obstacle, std::size_t warm_slot,
                               PairEvidence& evidence);
  /// The slab the pair's kept witness normal proves between the placed offset and the obstacle:
  /// on the offset's template, or on its placed vertices below the template size.
  std::optional<geometry::CertifiedSeparation> kept_normal_slab(HullProbe& hull, int obstacle,
                                                                std::size_t warm_slot);
  /// Places the hull's offset into placed_expanded_ once per hull probe.
  void place_expanded(HullProbe& hull);
  /// The placed offset on its template, or nullopt when the offset is placed instead.
  std::optional<geometry::PlacedHull> offset_template(const HullProbe& hull) const;
  /// Keeps a proven separation of the offset and an obstacle as evidence and warm start.
  void keep_separation(const geometry::CertifiedPairResult& result, std::size_t warm_slot,
                       PairEvidence& evidence);
  void record_clearance(HullProbe& hull, HullState& state, const PairEvidence& evidence,
                        ProbeResult& out);
  void decide_raw(HullProbe& hull, int obstacle, HullState& state, ProbeResult& out);
  void keep_unmoved_hull(const HullProbe& hull, const HullState& state,
                         std::size_t evidence_before, const ProbeResult& out);
  /// Appends the points of the offset of hull `hull_index` with obstacle `obstacle`, computed
  /// in the link frame (the offset's exact hull is prebuilt there; the obstacle is placed) and
  /// mapped to the world frame; the world-frame placed offset (placed_expanded_, hulled once
  /// per hull into expanded_polytope_) only when the link frame shows no point.
  void append_points(int hull_index, int obstacle, ProbeResult& out);
  /// Sorts out.interference_points into the one canonical order reports use.
  static void sort_points(ProbeResult& out);

  /// What the last probe proved about one hull that no obstacle's offset interference touched,
  /// with the pose of its link it was proved for. The obstacles are static, so a later probe
  /// that places the link bit for bit the same (the base; every link a PTP move leaves still)
  /// proves the same from the same inputs: it copies this instead of deciding again.
  struct UnmovedHull {
    bool valid = false;
    Eigen::Isometry3d X_WL;
    HullState state;
    std::vector<PairEvidence> evidence;
  };
  bool reuse_unmoved_hull(int hull_index, const Eigen::Isometry3d& X_WL, ProbeResult& out) const;

  const RobotCell* cell_;
  ProbeNeed need_ = ProbeNeed::kClearance;
  kinematics::Workspace workspace_;
  SelfPairProbe self_pairs_;
  std::vector<double> hull_radii_;  ///< [hull]: this probe's radii, for SelfPairProbe::probe
  std::vector<Eigen::Vector3d> placed_expanded_;
  std::vector<Eigen::Vector3d> placed_raw_;
  std::vector<Eigen::Vector3d> placed_obstacle_L_;
  std::optional<geometry::ConvexPolytope> expanded_polytope_;
  std::vector<int> candidates_;
  std::vector<std::pair<double, int>> ordered_candidates_;
  std::vector<Eigen::Vector3d> warm_normals_;  ///< [hull * obstacles + obstacle]
  std::vector<char> has_warm_normal_;
  /// [hull * obstacles + obstacle]: the lower bound the kept normal was found with (by GJK)
  std::vector<double> anchor_bounds_;
  std::vector<double> loose_hull_floors_;  ///< [hull], set_loose_terms()
  std::vector<int> climb_hints_;  ///< [hull * obstacles + obstacle]: GJK's last support of A
  /// [hull * obstacles + obstacle]: GJK's last simplex on the offset's template
  std::vector<geometry::GjkSimplexHint> simplex_hints_;
  std::vector<UnmovedHull> unmoved_hulls_;  ///< [hull]
  /// The broadphase's answer for a box around a hull's last query, with room to move.
  struct NearbyObstacles {
    geometry::Aabb box_W;  ///< empty until the first walk
    std::vector<int> obstacles;  ///< sorted
  };
  std::vector<NearbyObstacles> nearby_obstacles_;  ///< [hull]
  std::vector<std::optional<Eigen::Vector3d>> last_centers_W_;  ///< [hull], at the last probe
};

}  // namespace grpvss::certify

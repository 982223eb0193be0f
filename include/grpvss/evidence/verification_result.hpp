#pragma once
/// \file
/// \brief Everything one verification run produces, in library units (radians, lengths).
/// The report stage renders it (thesis output file, JSON report); the certificate is a
/// separate document (certificate.hpp) written from the same run.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "grpvss/geometry/interference_kind.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::certify {

/// The two labelled resolution modes (issue 4; docs/verification.md).
enum class ResolutionMode {
  kCertified,  ///< every point of every hull; two-ball cover with clearance (proofs/two-ball-cover.md#corollary-step)
  kThesis,     ///< thesis Eq. 3-3 at link-frame origins; reproduces the thesis, never "certified"
};

enum class Verdict {
  kClear,            ///< certified: the nominal robot never touches an obstacle
  kCollision,        ///< the unexpanded robot intersects an obstacle at a reported configuration
  kWithinTolerance,  ///< only the expanded robot interferes; the unexpanded robot proven clear
  kUndecided,        ///< only the expanded robot interferes and refinement hit its limit
  kError,            ///< a thesis error 1-6 or a CP-model violation stopped the path
};

/// What a CLEAR verdict claims (issue 20 point 7; docs/verification.md#claim).
enum class ClearClaim {
  /// The robot expanded by Delta is proven clear along the whole motion: every transition keeps
  /// g >= Delta (proofs/two-ball-cover.md#lemma-tolerance-along-motion). The default.
  kMotion,
  /// The nominal robot clear along the whole motion, the expanded robot at every step.
  kSteps,
};

/// Where a CLEAR run with claim `motion` fell short of it: the first transition (ending at
/// `step`) whose motion clearance g of a hull of `link` against `obstacle` (the nearer end's
/// nearest obstacle; -1 unknown) is below Delta, although the nominal rule held. For a self
/// pair (proofs/two-ball-cover.md#corollary-self-tolerance-along-motion) `other_link` names the
/// pair's second link and `obstacle` is -1; for an obstacle `other_link` is -1.
struct ToleranceShortfall {
  int step = 0;
  int link = 0;
  int obstacle = -1;
  int other_link = -1;
  double motion_clearance = 0.0;  ///< g, rounded down
};

/// Which term bounded a step's allowance (recorded per link in every step).
enum class GoverningTerm {
  kTolerance,   ///< allowance = 2*Delta (no extra clearance at the step ends)
  kClearance,   ///< allowance = (Delta + c_k) + (Delta + c_k1) with clearance > 0
  kThesisRule,  ///< thesis mode: max{min[2D/cos(theta/2), 2D+L], Dmin}
  kRawClearance,  ///< refinement: the expanded hull interferes; radii from the raw hull's clearance
  kUncertified,   ///< no rule could be met (collision at a step end, or the step floor reached)
  kSegmentEnd,  ///< the step was cut short by the segment's end
};

/// One interference point with its ids: exact in the link frame, rounded, and mapped to the
/// world frame by the link's floating-point pose (docs/verification.md#interference-points).
struct InterferencePoint {
  int link = 0;      ///< 0..N
  int hull = 0;      ///< index within the link (0-based)
  int obstacle = 0;  ///< index within the environment (0-based)
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  /// A is the link hull's offset, B the obstacle; printed by geometry::to_string.
  geometry::InterferenceKind kind = geometry::InterferenceKind::kEdgeOfAOnFaceOfB;
};

/// One (link hull, obstacle) pair whose expanded hull interferes at a step.
struct PairContact {
  int link = 0;      ///< 0..N
  int hull = 0;      ///< index within the link (0-based)
  int obstacle = 0;  ///< index within the environment (0-based)
  bool unexpanded_collides = false;  ///< the unexpanded hull meets the obstacle too
};

/// A run of consecutive steps at which one (link hull, obstacle) pair interferes: where a
/// collision begins and ends, which the per-step points leave the reader to piece together.
struct InterferenceEpisode {
  int link = 0;
  int hull = 0;
  int obstacle = 0;
  int first_step = 0;  ///< step indices; 0 is the start configuration
  int last_step = 0;
  int first_segment = 0;  ///< segments of first_step and last_step (0: the start)
  int last_segment = 0;
  double first_time = 0.0;  ///< path times of first_step and last_step, s
  double last_time = 0.0;
  /// First and last step of the run at which the unexpanded hull meets the obstacle.
  std::optional<int> first_collision_step;
  std::optional<int> last_collision_step;
  /// The step after last_step (the pair no longer interferes there) and its path time; empty
  /// when the path stops first. Inside a collision the colliding pair is not sampled
  /// (docs/verification.md#steps-through-a-collision), so the episode ends somewhere in
  /// (last_time, cleared_time).
  std::optional<int> cleared_step;
  std::optional<double> cleared_time;
};

/// A run of consecutive steps at which the two hulls of one self-collision pair meet.
struct SelfCollisionEpisode {
  SelfCollisionPair pair;
  int first_step = 0;
  int last_step = 0;
  double first_time = 0.0;  ///< s
  double last_time = 0.0;
};

struct LinkStepRecord {
  double motion_bound = 0.0;   ///< upper bound on the path length of any point of the link
  double allowance = 0.0;      ///< what the step rule compared the bound with
  GoverningTerm governing = GoverningTerm::kTolerance;
  double clearance = 0.0;      ///< certified lower bound of dist(link, obstacles) at this step
                               ///< (unexpanded link, raw obstacles); 0 when interfering
  int nearest_obstacle = -1;   ///< the obstacle that governs `clearance` (-1: none nearby)
  /// Certified mode: every point of the link stays farther than this from every obstacle
  /// throughout the transition from the previous step (0 when nothing is proven). Absent in
  /// thesis mode and at the start configuration.
  /// proof: proofs/two-ball-cover.md#corollary-motion-clearance
  std::optional<double> motion_clearance;
};

struct StepRecord {
  int index = 0;        ///< 1-based over the whole path (the thesis numbers steps this way)
  int segment = 0;      ///< 1-based
  double path_time = 0.0;     ///< s from the start of the path
  double segment_parameter = 0.0;  ///< PTP: s since segment start; CP: arc length from start
  Eigen::VectorXd q;
  Eigen::Vector3d end_effector_W = Eigen::Vector3d::Zero();
  std::vector<LinkStepRecord> links;  ///< index = link number 0..N (link 0 has bound 0)
  std::vector<InterferencePoint> interference_points;  ///< expanded robot vs obstacles
  std::vector<PairContact> contacts;  ///< every interfering pair, in (link, hull, obstacle) order
  /// Self-collision pairs whose hulls meet at this step (the unexpanded robot), sorted.
  std::vector<SelfCollisionPair> self_contacts;
  bool expanded_interferes = false;
  bool unexpanded_collides = false;
  bool refinement = false;  ///< inserted by the automatic refinement of Section 5.2.2
};

/// A thesis error (A.4, codes 1-6) or a new detection (codes >= 7, docs/user-guide.md).
struct PathError {
  int code = 0;
  int segment = 0;  ///< 1-based; 0 when not tied to a segment
  int step = 0;     ///< last step reached; 0 when none
  std::string message;
};

struct SegmentRecord {
  int number = 0;  ///< 1-based
  PathSegment input;
  Eigen::VectorXd start_q;
  Eigen::VectorXd end_q;  ///< empty when the segment was refused
  int first_step = 0;     ///< 0 when the segment produced no step
  int last_step = 0;
  double cycle_time = 0.0;
  bool simulated = false;
  /// A piece of a planner's joint trajectory: `input` is a joint target (the next waypoint)
  /// without speeds.
  bool trajectory_piece = false;
};

struct LinkClearanceSummary {
  int link = 0;
  double min_clearance = 0.0;  ///< smallest certified clearance over all steps
  int step = 0;                ///< where it occurs
  int obstacle = -1;
  /// Smallest motion_clearance over all transitions (certified mode, at least one transition):
  /// the link stays farther than this from every obstacle along the whole motion.
  std::optional<double> min_motion_clearance;
  int motion_step = 0;  ///< the step that ends the transition where it occurs
};

struct VerificationResult {
  double tolerance = 0.0;
  ResolutionMode mode = ResolutionMode::kCertified;
  Verdict verdict = Verdict::kClear;
  std::string path_file_label;  ///< printed in "... INPUT FROM FILE <label>"
  /// "joint trajectory T, linear interpolation, N waypoints, t0..tn s" for a planner's joint
  /// trajectory (docs/trajectories.md#verifying-a-trajectory); empty for a path program.
  std::string motion_model;
  std::vector<SegmentRecord> segments;
  /// The configuration the path starts from (home), evaluated like every step; index 0.
  /// Not part of `steps`, whose indices run 1, 2, ... as the thesis numbers them.
  std::optional<StepRecord> start;
  std::vector<StepRecord> steps;
  std::vector<PathError> errors;
  std::vector<LinkClearanceSummary> link_clearances;
  /// Every run of steps in which a pair interferes, ordered by first step, then pair.
  std::vector<InterferenceEpisode> interference_episodes;
  /// Every run of steps in which two hulls of the robot meet, ordered by first step, then pair.
  std::vector<SelfCollisionEpisode> self_collision_episodes;
  std::optional<int> collision_step;  ///< the step whose unexpanded robot intersects
  double total_cycle_time = 0.0;
  /// The run's claim (certified mode; thesis mode claims nothing).
  ClearClaim claim = ClearClaim::kMotion;
  /// Claim `motion`: the first transition with g < Delta on a run that is otherwise CLEAR (the
  /// verdict is then WITHIN_TOLERANCE); unset otherwise.
  std::optional<ToleranceShortfall> tolerance_shortfall;
};

const char* to_string(ResolutionMode mode);
const char* to_string(Verdict verdict);
std::optional<ResolutionMode> resolution_mode_from_string(std::string_view text);
std::optional<Verdict> verdict_from_string(std::string_view text);
const char* to_string(GoverningTerm term);
/// "motion" or "steps".
const char* to_string(ClearClaim claim);
std::optional<ClearClaim> clear_claim_from_string(std::string_view text);

}  // namespace grpvss::certify

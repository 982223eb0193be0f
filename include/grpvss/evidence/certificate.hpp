#pragma once
/// \file
/// \brief The certificate of a certified verification: per step the configuration, every
/// hull's proven radius with its evidence (separating slabs, broadphase margin), per
/// transition every hull's motion bound, the allowance it was compared with and the term that
/// governed. check_certificate() re-verifies all of it exactly from the input files alone.
/// Format: docs/certificate.md.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "grpvss/evidence/certificate_names.hpp"
#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/geometry/offset_shape.hpp"
#include "grpvss/geometry/separation_witness.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/motion/motion_model.hpp"
#include "grpvss/motion/trajectory.hpp"

namespace grpvss::certify {

struct EvidenceRecord {
  int obstacle = 0;
  bool expanded = true;    ///< slab about the placed offset (true) or the raw hull (false)
  bool separated = false;  ///< false: the pair interferes (no slab)
  geometry::SeparationWitness witness;
  double lower_bound = 0.0;
};

struct HullRecord {
  int link = 0;
  int hull = 0;
  double radius = 0.0;             ///< claimed certified radius r_h
  double broadphase_margin = 0.0;  ///< obstacles without evidence are farther (inf: none)
  std::vector<EvidenceRecord> evidence;
};

/// \brief One self-collision pair's proof at one step (Certificate::self_collision_pairs order).
struct SelfPairRecord {
  bool separated = false;  ///< false: no distance proven (the hulls meet, or the gap is ~0)
  geometry::SeparationWitness witness;  ///< about the two placed raw hulls, from a to b
  double lower_bound = 0.0;
  /// > 0 when hull a has a solid of revolution about joint a+1: the distance the same normal proves from
  /// the placed solid to placed hull b (witness.offset_b on b's side).
  /// proof: proofs/two-ball-cover.md#revolution-route
  double revolution_lower_bound = 0.0;
};

struct TransitionRecord {
  bool certified = false;
  /// M_h, or on certified CP steps min(M_h, L_h) with the chord bound L_h
  /// (proofs/motion-bound.md#lemma-joint-linear-chord); same order as StepCertificate::hulls
  std::vector<double> hull_motion_bounds;
  std::vector<double> hull_allowances;     ///< r_k + r_{k+1}
  std::vector<GoverningTerm> governing;
  /// Per self pair: M_a + M_b (rounded up) and d_k + d_{k+1} (rounded down), held to
  /// M_a + M_b < d_k + d_{k+1} (proofs/two-ball-cover.md#lemma-relative-motion). Empty without
  /// self pairs.
  std::vector<double> self_pair_motion_bounds;
  std::vector<double> self_pair_allowances;
  /// Per self pair, 1 when the bound and allowance above are the revolution route's (joint
  /// a+1 frozen, distances from hull a's solid of revolution: proofs/two-ball-cover.md#revolution-route),
  /// 0 for the relative bound's. Empty when no pair has the route.
  std::vector<int> self_pair_by_revolution;
};

struct StepCertificate {
  int step = 0;            ///< global step index (0 = the path's start configuration)
  double parameter = 0.0;  ///< PTP: time since segment start; CP: path length from start
  Eigen::VectorXd q;
  std::vector<HullRecord> hulls;
  std::vector<SelfPairRecord> self_pairs;  ///< one per self pair; empty without them
  TransitionRecord to_next;  ///< transition to the next step of the same segment
};

/// The largest radius the probe reports (obstacle-free surroundings). The checker accepts it
/// without evidence only when the environment has no obstacle at all.
constexpr double kUnboundedRadius = 1e9;

struct SegmentCertificate {
  int number = 0;
  motion::SegmentKind kind = motion::SegmentKind::kPtpJoint;
  double parameter_end = 0.0;
  std::vector<StepCertificate> steps;  ///< first at parameter 0, last at parameter_end
};

struct Certificate {
  ResolutionMode mode = ResolutionMode::kCertified;  ///< a checker accepts certified only
  double tolerance = 0.0;
  geometry::OffsetShape offset_shape = geometry::OffsetShape::kRhombicuboctahedron;
  motion::PtpTiming timing = motion::PtpTiming::kIndependent;
  double cp_speed = 0.0;
  double cp_deviation_fraction = 0.0;
  double placement_error = 0.0;
  double expansion_radius = 0.0;
  Verdict claim = Verdict::kError;  ///< the verdict it supports
  /// What its CLEAR means (docs/certificate.md#claim): `motion` (g >= Delta in every
  /// transition, checked) or `steps`. A certificate without the field ("clear_claim") was made
  /// before the claim existed, with today's `steps`, and reads as `steps`.
  ClearClaim clear_claim = ClearClaim::kSteps;
  int collision_step = 0;
  /// Robot hull / obstacle pairs never verified (a cell's allowed contacts), sorted; the
  /// checker rejects a certificate whose list differs from the inputs'. Written only when
  /// non-empty (thesis certificates are unchanged).
  std::vector<AllowedContactPair> allowed_contacts;
  /// The inputs' link and obstacle names (docs/certificate.md#names): informative, re-derived
  /// and compared by the checker. Written only when non-empty.
  CertificateNames names;
  /// Robot hull pairs verified for self-collision (the robot's self_collision_pairs), sorted;
  /// the checker rejects a certificate whose list differs from the inputs'. Written only when
  /// non-empty.
  std::vector<SelfCollisionPair> self_collision_pairs;
  /// The motion certified was a planner's joint trajectory (one "trajectory-piece" segment per
  /// piece; a step's time is its piece's waypoint time + parameter): its interpolation,
  /// "linear" or "cubic-hermite". Empty for a path program; written only when set.
  std::string trajectory_interpolation;
  /// The path's start configuration (library units) when the run was given one (`--start`);
  /// empty: the robot's home (a cell's `home`). The checker rejects a certificate whose start
  /// differs from the one it is given (docs/certificate.md#start). Written only when set.
  std::optional<Eigen::VectorXd> start;
  std::vector<SegmentCertificate> segments;
  std::vector<PathError> errors;
  /// What the certificate was made from (the file's "inputs": SHA-256 digests of the robot,
  /// environment and path files, the IK's name); read from a file, written by the report stage.
  std::map<std::string, std::string> inputs;
};

nlohmann::json certificate_to_json(const Certificate& certificate);
/// One element of a segment's "steps" in certificate_to_json().
nlohmann::json certificate_step_to_json(const StepCertificate& step);
/// One element of "segments" in certificate_to_json(), its steps included.
nlohmann::json certificate_segment_to_json(const SegmentCertificate& segment);
/// \throws InputError (file = `file_name`) when the document is not a well-formed certificate.
Certificate certificate_from_json(const nlohmann::json& document, const std::string& file_name);
/// Everything but the segments (`segments` must be present; it is not read).
/// \throws InputError as certificate_from_json().
Certificate certificate_header_from_json(const nlohmann::json& document,
                                         const std::string& file_name);
/// One element of `segments`. \throws InputError as certificate_from_json().
SegmentCertificate segment_certificate_from_json(const nlohmann::json& segment,
                                                 const std::string& file_name);

}  // namespace grpvss::certify

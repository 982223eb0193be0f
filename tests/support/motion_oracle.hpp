#pragma once
/// \file
/// \brief A brute-force reference for the verifier's soundness tests
/// (tests/certify/oracle_soundness_test.cpp). It shares no code with src/certify nor with the
/// library's contact code (src/geometry): forward kinematics is the test reference
/// (kinematics_reference.hpp); the motion is the motion stage's PtpMotion and CpLine (which
/// DEFINE the motion being verified); contact of the UNEXPANDED placed hull points with the
/// obstacle points is decided by an exact rational LP (exact_hull_lp.hpp). A float pre-filter
/// (bounding spheres, then a separating plane proposed by Gilbert's iteration or, failing
/// that, by the best of the float facet-normal and edge-cross-product axes, and verified over
/// every point with a margin far above rounding) skips only pairs that are provably apart.
///
/// Sampling: consecutive samples are chosen so that every point of every hull moves at most
/// `spacing` between them, from the joint increments and a reach bound
/// \f$ R_j = \sum_{m \ge j} (|a_m| + d^{\max}_m) + \max_{p \in \text{links} \ge j} |p_L| \f$
/// (revolute joint j moves a point at most \f$ |\Delta q_j| R_j \f$, a prismatic joint at most
/// \f$ |\Delta q_j| \f$; each joint of a PTP move, or of a joint-linear piece, is monotone, so
/// the sum bounds the path). Where the clearance at a sample is large, the next sample may be
/// farther (kReserveSpacings): the skipped motion provably stays clear. What the oracle reports as contact is real (at a sampled
/// configuration); contacts shallower than spacing/2 that exist only between samples can be
/// missed (the oracle is one-sided).

#include <limits>
#include <vector>

#include <Eigen/Core>

#include "grpvss/model/environment.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/kinematics_access.hpp"

namespace grpvss::test {

/// Result of one configuration (exact contact) or one whole path (sampled).
struct OracleContact {
  bool contact = false;  ///< some raw hull meets (touches or overlaps) some obstacle, exactly
  int link = -1;
  int hull = -1;
  int obstacle = -1;
  /// Smallest hull-obstacle distance seen: a float lower bound from the verified separating
  /// plane (statistics only; never used for a contact decision). 0 on contact (or when only
  /// the exact test could separate); +inf without obstacles.
  double min_distance_estimate = std::numeric_limits<double>::infinity();
  /// Smallest hull-obstacle distance seen, from ABOVE: the norm of Gilbert's iterate, a point
  /// of conv(hull - obstacle), over the pairs evaluated (a pair skipped by the sphere test is
  /// farther than the lower estimate; the minimum stays an upper bound of the configuration's
  /// clearance). 0 on contact; +inf without obstacles. A float reference for the claim
  /// `motion` property (docs/soundness-oracle.md), compared with a relative margin of 1e-6.
  double min_distance_upper = std::numeric_limits<double>::infinity();
};

struct OraclePathResult {
  OracleContact first_contact;  ///< contact == true: the first sample that collides
  int contact_segment = 0;      ///< 1-based
  double contact_parameter = 0.0;  ///< PTP: s since the segment's start; CP: arc length
  Eigen::VectorXd contact_q;
  /// The oracle could not follow a CP line continuously (IK failed within the limits, or the
  /// IK solution jumped) at `stopped_segment`; the rest of the path was not sampled.
  bool line_not_followed = false;
  int stopped_segment = 0;
  long long samples = 0;
  long long exact_checks = 0;  ///< pairs decided by the exact LP (the rest by the pre-filter)
  double min_distance_estimate = std::numeric_limits<double>::infinity();
  /// OracleContact::min_distance_upper's minimum over the samples, and per segment (index
  /// segment - 1; a segment's first sample is the previous one's last; sample_joint_linear:
  /// one entry).
  double min_distance_upper = std::numeric_limits<double>::infinity();
  std::vector<double> segment_min_distance_upper;
};

/// \brief Exact contact oracle for one robot in one environment.
class MotionOracle {
 public:
  /// Samples are `spacing` apart wherever the clearance may be below kReserveSpacings *
  /// spacing (2 Delta for spacing = Delta/20); farther out a step may move every point up to
  /// the last sample's clearance lower bound minus that reserve (provably contact-free).
  static constexpr double kReserveSpacings = 40.0;

  MotionOracle(const RobotModel& robot, const Environment& environment);

  /// Exact contact of the unexpanded robot at q, with the smallest distance estimate.
  /// `stop_at_contact`: return at the first colliding pair.
  OracleContact check(const Eigen::VectorXd& q, bool stop_at_contact = true) const;

  /// Samples the commanded path from the robot's home with every hull point moving at most
  /// `spacing` between samples; stops at the first contact. PTP joint segments: the motion
  /// stage's PtpMotion (independent timing, as the verifier's trajectory). CP lines: the
  /// oracle's own samples of the commanded line (motion::CpLine, IK nearest the previous
  /// sample through `kinematics`, accepted within the limits), dense enough that consecutive
  /// IK solutions move every point at most `spacing` (joint-linear in between, at that scale)
  /// and at most max(spacing, 0.05) of path length apart (IK checked along the whole line).
  /// \throws std::invalid_argument for a PTP(WCS) segment.
  OraclePathResult sample_path(const PathProgram& program, double spacing,
                               const motion::KinematicsAccess& kinematics) const;

  /// Samples the joint-linear motion through `q_samples` (the CP model a certificate covers,
  /// proofs/cp-joint-path.md#model) with every point moving at most `spacing` between samples.
  /// Reports the first contact; `segment` is copied into the result.
  OraclePathResult sample_joint_linear(const std::vector<Eigen::VectorXd>& q_samples,
                                       double spacing, int segment) const;

  /// \f$ \sum_j |\Delta q_j| R_j \f$: bound on the path length of any hull point for a
  /// joint-monotone motion with increments dq.
  double motion_bound(const Eigen::VectorXd& dq) const;

 private:
  struct Shape {
    std::vector<Eigen::Vector3d> points;
    Eigen::Vector3d center;
    double radius = 0.0;  ///< covers every point from center (inflated for rounding)
    /// Float facet normals and edge directions of the hull (brute force over point triples
    /// and pairs): candidate separating axes for the pre-filter only.
    std::vector<Eigen::Vector3d> face_normals;
    std::vector<Eigen::Vector3d> edge_directions;
  };
  /// Samples q(t), t in [0, 1], monotone in every joint, adaptively; calls `visit` per sample
  /// after the first (returns true to stop). Returns true if stopped.
  template <typename Motion, typename Visit>
  bool march(const Motion& next, double spacing, Visit&& visit, const double& clearance, double max_h) const;

  const RobotModel* robot_;
  std::vector<std::vector<Shape>> hulls_L_;  ///< [link][hull], in the link frame
  std::vector<Shape> obstacles_W_;
  std::vector<double> reach_;  ///< R_j per joint (1 for prismatic)
  mutable long long exact_checks_ = 0;
};

}  // namespace grpvss::test

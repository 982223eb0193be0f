#pragma once
/// \file
/// \brief A brute-force reference for the verifier's soundness tests
/// (tests/certify/oracle_soundness_test.cpp). It shares no code with src/certify: forward
/// kinematics is the test reference (kinematics_reference.hpp), the motion is the motion
/// stage's PtpMotion (which DEFINES the motion being verified), and contact is decided by
/// geometry::classify_exact on the UNEXPANDED placed hull points against the obstacle points.
///
/// Sampling: consecutive samples are chosen so that every point of every hull moves at most
/// `spacing` between them, from the joint increments and a reach bound
/// \f$ R_j = \sum_{m \ge j} (|a_m| + d^{\max}_m) + \max_{p \in \text{links} \ge j} |p_L| \f$
/// (revolute joint j moves a point at most \f$ |\Delta q_j| R_j \f$, a prismatic joint at most
/// \f$ |\Delta q_j| \f$; each joint of a PTP move is monotone, so the sum bounds the path).
/// What the oracle reports as contact is real; contacts shallower than spacing/2 that exist
/// only between samples can be missed (the oracle is one-sided).

#include <limits>
#include <vector>

#include <Eigen/Core>

#include "grpvss/geometry/convex_polytope.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::test {

/// Result of one configuration (exact contact) or one whole path (sampled).
struct OracleContact {
  bool contact = false;  ///< some raw hull meets (touches or overlaps) some obstacle, exactly
  int link = -1;
  int hull = -1;
  int obstacle = -1;
  /// Smallest hull-obstacle distance seen, from double GJK (statistics only; never used for
  /// a contact decision). 0 on contact; +inf without obstacles.
  double min_distance_estimate = std::numeric_limits<double>::infinity();
};

struct OraclePathResult {
  OracleContact first_contact;  ///< contact == true: the first sample that collides
  int contact_segment = 0;      ///< 1-based
  double contact_time = 0.0;    ///< s since the segment's start
  Eigen::VectorXd contact_q;
  long long samples = 0;
  long long exact_checks = 0;  ///< pairs decided by classify_exact (the rest by a verified plane)
  double min_distance_estimate = std::numeric_limits<double>::infinity();
};

/// \brief Exact contact oracle for one robot in one environment.
class MotionOracle {
 public:
  MotionOracle(const RobotModel& robot, const Environment& environment);

  /// Exact contact of the unexpanded robot at q, with the (GJK-estimated) smallest distance.
  /// `stop_at_contact`: return at the first colliding pair.
  OracleContact check(const Eigen::VectorXd& q, bool stop_at_contact = true) const;

  /// Samples the path (PTP joint segments only; planned with motion::PtpMotion, independent
  /// timing, from the robot's home) with every hull point moving at most `spacing` between
  /// samples. Stops at the first contact.
  /// \throws std::invalid_argument for a segment that is not a PTP joint segment.
  OraclePathResult sample_path(const PathProgram& program, double spacing) const;

  /// \f$ \sum_j |\Delta q_j| R_j \f$: bound on the path length of any hull point for a
  /// joint-monotone motion with increments dq.
  double motion_bound(const Eigen::VectorXd& dq) const;

 private:
  struct PlacedHull {
    std::vector<Eigen::Vector3d> points_L;
    Eigen::Vector3d center_L;
    double radius = 0.0;  ///< covers every point from center_L (inflated for rounding)
  };
  const RobotModel* robot_;
  std::vector<std::vector<PlacedHull>> hulls_;  ///< [link][hull]
  std::vector<std::vector<Eigen::Vector3d>> obstacles_W_;
  std::vector<geometry::ConvexPolytope> obstacle_polytopes_;
  std::vector<Eigen::Vector3d> obstacle_centers_W_;
  std::vector<double> obstacle_radii_;
  std::vector<double> reach_;  ///< R_j per joint (1 for prismatic)
  mutable long long exact_checks_ = 0;
};

}  // namespace grpvss::test

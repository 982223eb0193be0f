#pragma once
/// \file
/// \brief A brute-force contact oracle for cells with a URDF robot (UR5e, Panda of
/// ../shared/robots), independent of the verifier (tests/certify/urdf_oracle_soundness_test.cpp,
/// docs/soundness-oracle.md#urdf-cells):
/// - forward kinematics: support/urdf_reference.hpp (tinyxml2, the URDF's origin/axis rules,
///   written in the tests), the cell's base pose composed by hand;
/// - geometry: each `<collision>`'s points in its own frame (mesh vertices, box corners,
///   the circumscribing polytope of a cylinder or sphere: the model the verifier verifies),
///   placed by that FK; obstacles: the cell's world points;
/// - contact: bounding spheres, a plane proposed by Gilbert's 1966 iteration and verified over
///   every point with a margin far above rounding, else the exact rational LP
///   (exact_hull_lp.hpp); robot/obstacle pairs except allowed contacts, and the self-collision
///   pairs the cell keeps;
/// - sampling: a configuration-independent reach per hull and joint (hull_motion_bound(),
///   relative_motion_bound()); each pair is decided again only when the motion bound
///   accumulated since its last decision comes within `spacing` of its last proven gap, and between
///   two decisions of a pair its hulls move at most max(spacing, that gap).
/// It calls nothing of src/kinematics' chain, src/geometry's contact code or src/certify.

#include <limits>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/motion/motion_model.hpp"
#include "support/urdf_reference.hpp"

namespace grpvss::test {

struct UrdfOracleContact {
  bool contact = false;
  bool self = false;     ///< a self-collision pair (else robot / obstacle)
  int link = -1, hull = -1;
  int other_link = -1, other_hull = -1;  ///< self pairs
  int obstacle = -1;                     ///< obstacle pairs
  /// Float lower bounds of the smallest distances (statistics and step length only).
  double obstacle_distance = std::numeric_limits<double>::infinity();
  double self_distance = std::numeric_limits<double>::infinity();
  /// Float lower bound of each self pair's distance (the cell's order; empty after a contact
  /// cut the check short).
  std::vector<double> self_pair_distances;
  /// The self pair of self_distance: link_a, hull_a, link_b, hull_b (-1 when none).
  int nearest_self[4] = {-1, -1, -1, -1};
};

struct UrdfOraclePath {
  UrdfOracleContact first_contact;  ///< contact == true: the first sample that touches
  int contact_segment = 0;          ///< 1-based
  Eigen::VectorXd contact_q;
  long long samples = 0;
  long long exact_checks = 0;
  long long decisions = 0;  ///< pair decisions (sphere, plane or exact LP)
  double min_obstacle_distance = std::numeric_limits<double>::infinity();
  double min_self_distance = std::numeric_limits<double>::infinity();
  int nearest_self[4] = {-1, -1, -1, -1};  ///< the self pair of min_self_distance
};

class UrdfCellOracle {
 public:
  /// Reads the cell's URDF on its own (support/urdf_reference) and takes each collision's
  /// frame points from the URDF description the cell stage read.
  explicit UrdfCellOracle(const cell::LoadedCell& cell);

  /// World points of every hull [link][hull] at q, placed by the reference FK.
  std::vector<std::vector<std::vector<Eigen::Vector3d>>> place(const Eigen::VectorXd& q) const;

  /// Exact contact at q (obstacles except allowed pairs, and the cell's self pairs).
  UrdfOracleContact check(const Eigen::VectorXd& q, bool stop_at_contact = true) const;

  /// Samples the PTP joint segments of `program` from home with the motion stage's PtpMotion
  /// (`timing`); every hull point moves at most `spacing` between samples where the clearance
  /// may be small. Stops at the first contact.
  UrdfOraclePath sample_path(const PathProgram& program, motion::PtpTiming timing, double spacing) const;

  /// \f$\sum_j |\Delta q_j| r_{h,j}\f$: a bound on the world path length of any point of hull
  /// (link, hull) for a motion monotone in every joint with increments dq. r_{h,j} bounds the
  /// distance of the hull's vertices to joint j's axis (exact for the link joint j carries,
  /// plus the joint origins' offsets above it).
  double hull_motion_bound(int link, int hull, const Eigen::VectorXd& dq) const;

  /// The largest hull_motion_bound over every hull.
  double motion_bound(const Eigen::VectorXd& dq) const;

  /// \f$\sum_{j=a}^{b-1} |\Delta q_j| r_{h_b,j}\f$: a bound on the path of any point of hull
  /// (link_b, hull_b) in link_a's frame (only joints a..b-1 move it there; a point's distance to
  /// a joint's axis does not depend on the frame).
  double relative_motion_bound(int link_a, int link_b, int hull_b, const Eigen::VectorXd& dq) const;

  /// World pose of every hull's collision frame [link][hull] at q (reference FK).
  std::vector<std::vector<Pose<double>>> hull_poses(const Eigen::VectorXd& q) const;

 private:
  struct Hull {
    std::string urdf_link;
    Pose<double> X_LC;  ///< collision origin in its URDF link (reference rules)
    std::vector<Eigen::Vector3d> points_C;
  };
  struct Shape {
    std::vector<Eigen::Vector3d> points;
    Eigen::Vector3d center;
    double radius = 0.0;
  };
  struct PairState;
  /// Decides a pair: false with `distance` a proven lower bound of the distance, or true (exact
  /// contact). `direction`, when given, starts Gilbert's iteration and receives its result.
  bool decide(const Shape& a, const Shape& b, double& distance, Eigen::Vector3d* direction = nullptr) const;
  std::map<std::string, Pose<double>> link_poses(const Eigen::VectorXd& q) const;
  Shape placed_shape(const std::map<std::string, Pose<double>>& poses, int link, int hull) const;
  std::vector<PairState> pair_states() const;
  void compute_reach();

  const cell::LoadedCell* cell_;
  ReferenceUrdf urdf_;
  Pose<double> X_W_root_ = Pose<double>::Identity();
  std::vector<std::string> chain_joints_;                   ///< model joint i -> URDF joint
  std::map<std::string, double> side_values_;              ///< side joints, fixed
  std::vector<std::vector<Hull>> hulls_;                   ///< [link][hull]
  std::vector<Shape> obstacles_;
  std::vector<std::vector<Eigen::VectorXd>> reach_;  ///< r_{h,j}: [link][hull](model joint)
  mutable long long exact_checks_ = 0;
};

}  // namespace grpvss::test

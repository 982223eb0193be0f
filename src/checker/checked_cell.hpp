#pragma once
// The checker's own model of the cell, rebuilt from the inputs and the certificate's header
// alone: every hull's offset (verified to contain the ball sum), the exact axis radii, the
// obstacles' exact hulls and boxes, and the check that the recorded placement error covers the
// forward-kinematics rounding bound.

#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <gmpxx.h>

#include "check_ledger.hpp"
#include "exact_rational.hpp"
#include "grpvss/evidence/certificate.hpp"
#include "grpvss/geometry/revolution_solid.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::certify {

/// One link hull as the checker rebuilds it.
struct CheckedHull {
  int link = 0;
  int hull = 0;
  std::vector<Eigen::Vector3d> raw_L;
  std::vector<Eigen::Vector3d> expanded_L;  ///< the offset, verified to contain the ball sum
  std::vector<Rational> axis_radius;        ///< R_{jh} for joints 1..link, exact
  /// A ball containing raw_L: its box's midpoint and a double >= its largest vertex distance
  /// (proofs/motion-bound.md#lemma-axis-distance-along-step).
  Eigen::Vector3d ball_center_L = Eigen::Vector3d::Zero();
  Rational ball_radius = 0;
  /// The hull's solid of revolution about the axis of joint link + 1 when the verifier's rule proposes one
  /// and it contains the hull exactly with its margin (revolution_check.hpp); the revolution
  /// route of its self pairs is accepted only then. proof: proofs/two-ball-cover.md#revolution-route
  std::optional<geometry::RevolutionSolid> revolution_L;
};

/// The smallest double whose square is at least `square` (>= 0), exactly: an upper bound on
/// its root.
double root_up(const Rational& square);

/// Axis-aligned box of a point set (min/max of doubles: exact).
struct Box {
  Eigen::Vector3d lo, hi;
};
Box box_of(const std::vector<Eigen::Vector3d>& points);
/// Exact box separation: some axis has a gap > margin between the two boxes.
bool boxes_farther_than(const Box& a, const Box& b, double margin);

class CheckedCell {
 public:
  /// L: the largest |coordinate| of any raw hull vertex (<= the FK bound's coordinate bound).
  double hull_coordinate_limit() const { return hull_coordinate_limit_; }
  /// The cell of `robot` and `environment` for the certificate's tolerance, offset shape,
  /// expansion radius and placement error; nullopt (and the reason in `ledger`) when the
  /// header's numbers cannot be trusted.
  static std::optional<CheckedCell> build(const RobotModel& robot, const Environment& environment,
                                          const Certificate& header, CheckLedger& ledger);

  const RobotModel& robot() const { return *robot_; }
  const Environment& environment() const { return *environment_; }
  const kinematics::KinematicChain& chain() const { return chain_; }
  const std::vector<CheckedHull>& hulls() const { return hulls_; }
  const std::vector<std::vector<Eigen::Vector3d>>& obstacles() const { return obstacles_; }
  const std::vector<Box>& obstacle_boxes() const { return obstacle_boxes_; }
  /// True when the inputs allow hull `hull` of link `link` to touch obstacle `obstacle`: the
  /// pair is not checked (the certificate must list the same pairs, build() decides it).
  bool contact_allowed(int link, int hull, int obstacle) const {
    return environment_->contact_allowed(link, hull, obstacle);
  }
  /// The inputs' self-collision pairs (robot().self_collision_pairs, the certificate's list:
  /// build() decides it) as (hull a, hull b) indices into hulls().
  const std::vector<std::pair<int, int>>& self_pairs() const { return self_pairs_; }

 private:
  double hull_coordinate_limit_ = 0.0;
  explicit CheckedCell(const RobotModel& robot);
  bool build_hulls(const Certificate& header, CheckLedger& ledger, double& largest_coordinate);
  /// Sets hull.revolution_L when the hull is round about the next joint's axis and its
  /// solid contains it exactly.
  void enclose_if_round(CheckedHull& hull) const;
  /// Drops every solid whose points the header's placement error does not cover.
  void keep_covered_solids(const Certificate& header, const Environment& environment,
                              double largest_coordinate);
  void build_obstacles(const Environment& environment);
  bool index_self_pairs(CheckLedger& ledger);

  const RobotModel* robot_;
  const Environment* environment_ = nullptr;
  kinematics::KinematicChain chain_;
  std::vector<CheckedHull> hulls_;
  std::vector<std::vector<Eigen::Vector3d>> obstacles_;
  std::vector<Box> obstacle_boxes_;
  std::vector<std::pair<int, int>> self_pairs_;
};

}  // namespace grpvss::certify

#include "checked_cell.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "exact_axis_radius.hpp"
#include "revolution_check.hpp"
#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/minkowski_offset.hpp"
#include "grpvss/geometry/directed_rounding.hpp"
#include "grpvss/kinematics/fk_error_bound.hpp"

namespace grpvss::certify {
namespace {

// x > y + m for doubles x, y, m (m >= 0), decided exactly without big numbers: RD(y + m) and
// RU(y + m) are the doubles around the exact sum (equal when it is a double), so x exceeds it
// iff x > RU, or x == RU with RU != RD (proofs/fast-path.md#directed-rounding, TwoSum).
bool exceeds_sum(double x, double y, double m) {
  const double up = geometry::rounding::nearest_mode_add_up(y, m);
  const double down = geometry::rounding::nearest_mode_add_down(y, m);
  return x > up || (x == up && up != down);
}

double largest_abs_coordinate(const std::vector<Eigen::Vector3d>& points) {
  double largest = 0.0;
  for (const auto& p : points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  return largest;
}

}  // namespace

Box box_of(const std::vector<Eigen::Vector3d>& points) {
  Box box{points.front(), points.front()};
  for (const auto& p : points) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  }
  return box;
}

bool boxes_farther_than(const Box& a, const Box& b, double margin) {
  for (int axis = 0; axis < 3; ++axis) {
    if (exceeds_sum(b.lo[axis], a.hi[axis], margin)) return true;
    if (exceeds_sum(a.lo[axis], b.hi[axis], margin)) return true;
  }
  return false;
}

double root_up(const Rational& square) {
  double root = std::sqrt(square.get_d());
  while (Rational(root) * Rational(root) < square) {
    root = std::nextafter(root, std::numeric_limits<double>::infinity());
  }
  return root;
}

namespace {

// The box midpoint (as the verifier takes it: any centre is sound) and the exact largest
// vertex distance, rounded up to a double. proof: proofs/motion-bound.md#lemma-axis-distance-along-step
void enclose_in_ball(CheckedHull& hull) {
  if (hull.raw_L.empty()) return;
  const Box box = box_of(hull.raw_L);
  hull.ball_center_L = (box.lo + box.hi) * 0.5;
  Rational largest = 0;
  for (const Eigen::Vector3d& u : hull.raw_L) {
    Rational square = 0;
    for (int k = 0; k < 3; ++k) {
      const Rational d = exact(u[k]) - exact(hull.ball_center_L[k]);
      square += d * d;
    }
    if (square > largest) largest = square;
  }
  hull.ball_radius = Rational(root_up(largest));
}

}  // namespace

CheckedCell::CheckedCell(const RobotModel& robot)
    : robot_(&robot), chain_(kinematics::make_chain(robot)) {}

std::optional<CheckedCell> CheckedCell::build(const RobotModel& robot,
                                              const Environment& environment,
                                              const Certificate& header, CheckLedger& ledger) {
  CheckedCell cell(robot);
  double largest_coordinate = 0.0;
  if (!cell.build_hulls(header, ledger, largest_coordinate)) return std::nullopt;
  // proof: proofs/fk-rounding.md#fk-rounding (the verifier doubles the bound: strictness)
  const double bound = kinematics::forward_kinematics_error_bound(cell.chain_, largest_coordinate);
  ledger.decided();
  // proof: proofs/cell-geometry.md#lemma-geometry-error (the stored geometry's own error)
  if (!(exact(header.placement_error) >= 2 * (exact(bound) + exact(robot.hull_point_error) +
                                               exact(environment.point_error)))) {
    ledger.fail(
        "placement_error is smaller than twice the forward-kinematics rounding bound plus the "
        "geometry's point errors");
    return std::nullopt;
  }
  cell.keep_covered_solids(header, environment, largest_coordinate);
  // The pairs the verifier skipped are the inputs' allowed contacts, no more and no fewer.
  ledger.decided();
  if (header.allowed_contacts != environment.allowed_contacts) {
    ledger.fail("the certificate's allowed contacts differ from the inputs' (" +
                std::to_string(header.allowed_contacts.size()) + " pairs certified, " +
                std::to_string(environment.allowed_contacts.size()) + " in the inputs)");
    return std::nullopt;
  }
  // Names are informative: the certificate's must be the inputs' (docs/certificate.md#names).
  // Counted as a decision only where there are names (thesis files' counts are unchanged).
  const CertificateNames input_names = certificate_names(robot, environment);
  if (!header.names.empty() || !input_names.empty()) ledger.decided();
  if (header.names != input_names) {
    ledger.fail("the certificate's link or obstacle names differ from the inputs'");
    return std::nullopt;
  }
  // The pairs verified for self-collision are the inputs', no more and no fewer (counted only
  // when there are some: two empty lists are no inequality, and thesis checks keep their count).
  const bool any_self_pairs =
      !header.self_collision_pairs.empty() || !robot.self_collision_pairs.empty();
  if (any_self_pairs) ledger.decided();
  if (header.self_collision_pairs != robot.self_collision_pairs) {
    ledger.fail("the certificate's self-collision pairs differ from the inputs' (" +
                std::to_string(header.self_collision_pairs.size()) + " pairs certified, " +
                std::to_string(robot.self_collision_pairs.size()) + " in the inputs)");
    return std::nullopt;
  }
  if (!cell.index_self_pairs(ledger)) return std::nullopt;
  cell.environment_ = &environment;
  cell.build_obstacles(environment);
  return cell;
}

// Every hull's offset is rebuilt from the header's expansion radius and shape and verified to
// contain the ball sum. proof: proofs/offset-containment.md#rounded-placement
bool CheckedCell::build_hulls(const Certificate& header, CheckLedger& ledger,
                              double& largest_coordinate) {
  const RobotModel& robot = *robot_;
  for (int link = 0; link < static_cast<int>(robot.links.size()); ++link) {
    for (int hull = 0; hull < static_cast<int>(robot.links[link].hulls.size()); ++hull) {
      const HullPoints& points = robot.links[link].hulls[hull];
      const geometry::ConvexPolytope raw = geometry::ConvexPolytope::from_points(points.points);
      const geometry::ConvexPolytope expanded =
          geometry::minkowski_offset(raw, header.expansion_radius, header.offset_shape);
      ledger.decided();
      if (!geometry::contains_ball_sum_exactly(expanded, raw, header.expansion_radius)) {
        ledger.fail("link " + std::to_string(link) + " hull " + std::to_string(hull) +
                    ": the offset does not contain the ball sum");
        return false;
      }
      CheckedHull checked;
      checked.link = link;
      checked.hull = hull;
      checked.raw_L = raw.vertices();
      checked.expanded_L = expanded.vertices();
      for (int joint = 1; joint <= link; ++joint) {
        checked.axis_radius.push_back(exact_axis_radius(robot, link, points, joint));
      }
      enclose_in_ball(checked);
      enclose_if_round(checked);
      hull_coordinate_limit_ = std::max(hull_coordinate_limit_, largest_abs_coordinate(checked.raw_L));
      largest_coordinate = std::max({largest_coordinate, largest_abs_coordinate(checked.raw_L),
                                     largest_abs_coordinate(checked.expanded_L)});
      hulls_.push_back(std::move(checked));
    }
  }
  return true;
}

// The verifier's solid-of-revolution rule (deterministic), its containment decided exactly; the FK bound
// must then cover the solid's points too. proof: proofs/two-ball-cover.md#revolution-solid
void CheckedCell::enclose_if_round(CheckedHull& hull) const {
  if (hull.link >= chain_.joint_count()) return;
  const kinematics::ChainJoint& next = chain_.joints[static_cast<std::size_t>(hull.link)];
  if (next.type != JointType::kRevolute) return;
  const geometry::JointAxisLine_L axis =
      geometry::joint_axis_line(next.X_PJ, next.X_PJ_error.rotation, next.X_PJ_error.translation);
  const auto solid =
      geometry::enclosing_revolution_solid(hull.raw_L, axis, robot_->hull_point_error);
  if (!solid || !solid_encloses_exactly(*solid, hull.raw_L, axis, robot_->hull_point_error)) {
    return;
  }
  hull.revolution_L = solid;
}

// A solid whose points the header's placement error does not cover (beyond the FK bound's
// coordinate box) is dropped: its route proves nothing here.
void CheckedCell::keep_covered_solids(const Certificate& header, const Environment& environment,
                                         double largest_coordinate) {
  for (CheckedHull& hull : hulls_) {
    if (!hull.revolution_L) continue;
    const double extent =
        std::max(largest_coordinate, geometry::revolution_solid_extent(*hull.revolution_L));
    const double bound = kinematics::forward_kinematics_error_bound(chain_, extent);
    if (!(exact(header.placement_error) >= 2 * (exact(bound) + exact(robot_->hull_point_error) +
                                                 exact(environment.point_error)))) {
      hull.revolution_L.reset();
    }
  }
}

bool CheckedCell::index_self_pairs(CheckLedger& ledger) {
  const auto index_of = [this](int link, int hull) {
    for (std::size_t i = 0; i < hulls_.size(); ++i) {
      if (hulls_[i].link == link && hulls_[i].hull == hull) return static_cast<int>(i);
    }
    return -1;
  };
  for (const SelfCollisionPair& pair : robot_->self_collision_pairs) {
    const int a = index_of(pair.link_a, pair.hull_a);
    const int b = index_of(pair.link_b, pair.hull_b);
    if (a < 0 || b < 0) {
      ledger.fail("a self-collision pair names a hull the robot does not have");
      return false;
    }
    self_pairs_.emplace_back(a, b);
  }
  return true;
}

void CheckedCell::build_obstacles(const Environment& environment) {
  for (const HullPoints& obstacle : environment.obstacles) {
    obstacles_.push_back(geometry::ConvexPolytope::from_points(obstacle.points).vertices());
    obstacle_boxes_.push_back(box_of(obstacles_.back()));
  }
}

}  // namespace grpvss::certify

#include "support/motion_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <variant>

#include <Eigen/Geometry>

#include "grpvss/geometry/exact_contact.hpp"
#include "grpvss/geometry/gjk.hpp"
#include "grpvss/motion/ptp_motion.hpp"
#include "support/kinematics_reference.hpp"

namespace grpvss::test {
namespace {

// Margins far above double rounding (coordinates here are < 10^3, rounding ~10^-13): a
// plane or sphere gap larger than this separates exactly.
double rounding_margin(double scale) { return 1e-9 * (1.0 + scale); }

double max_abs(const std::vector<Eigen::Vector3d>& points) {
  double largest = 0.0;
  for (const auto& p : points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  return largest;
}

}  // namespace

MotionOracle::MotionOracle(const RobotModel& robot, const Environment& environment)
    : robot_(&robot) {
  for (const Link& link : robot.links) {
    hulls_.emplace_back();
    for (const HullPoints& hull : link.hulls) {
      PlacedHull placed;
      placed.points_L = hull.points;
      Eigen::Vector3d center = Eigen::Vector3d::Zero();
      for (const auto& p : hull.points) center += p;
      center /= static_cast<double>(hull.points.size());
      double radius = 0.0;
      for (const auto& p : hull.points) radius = std::max(radius, (p - center).norm());
      placed.center_L = center;
      placed.radius = radius * (1.0 + 1e-12);
      hulls_.back().push_back(std::move(placed));
    }
  }
  for (const HullPoints& obstacle : environment.obstacles) {
    obstacles_W_.push_back(obstacle.points);
    obstacle_polytopes_.push_back(geometry::ConvexPolytope::from_points(obstacle.points));
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    for (const auto& p : obstacle.points) center += p;
    center /= static_cast<double>(obstacle.points.size());
    double radius = 0.0;
    for (const auto& p : obstacle.points) radius = std::max(radius, (p - center).norm());
    obstacle_centers_W_.push_back(center);
    obstacle_radii_.push_back(radius * (1.0 + 1e-12));
  }
  // R_j: a point of link i >= j is at most sum_{m=j..i} |translation of A_m| + |p_L| from the
  // origin of frame j-1, which lies on axis j; |translation of A_m| <= |a_m| + max|d_m|.
  const int n = robot.joint_count();
  reach_.assign(n, 1.0);
  for (int j = 1; j <= n; ++j) {
    const Joint& joint = robot.joints[j - 1];
    if (joint.type == JointType::kPrismatic) continue;
    double chain = 0.0;
    double farthest_point = 0.0;
    for (int m = j; m <= n; ++m) {
      const Joint& joint_m = robot.joints[m - 1];
      double d_max = std::abs(joint_m.dh.d);
      if (joint_m.type == JointType::kPrismatic) {
        d_max = std::max(std::abs(joint_m.dh.d + joint_m.minimum),
                         std::abs(joint_m.dh.d + joint_m.maximum));
      }
      chain += std::abs(joint_m.dh.a) + d_max;
      for (const HullPoints& hull : robot.links[m].hulls) {
        for (const auto& p : hull.points) farthest_point = std::max(farthest_point, p.norm());
      }
    }
    reach_[j - 1] = (chain + farthest_point) * (1.0 + 1e-9);
  }
}

double MotionOracle::motion_bound(const Eigen::VectorXd& dq) const {
  double bound = 0.0;
  for (int j = 0; j < dq.size(); ++j) bound += std::abs(dq[j]) * reach_[j];
  return bound;
}

OracleContact MotionOracle::check(const Eigen::VectorXd& q, bool stop_at_contact) const {
  OracleContact result;
  std::vector<Eigen::Vector3d> placed;
  for (int link = 0; link < static_cast<int>(hulls_.size()); ++link) {
    if (hulls_[link].empty()) continue;
    const Eigen::Matrix4d X_WL = reference_link_pose<double>(*robot_, q, link);
    const Eigen::Matrix3d R_WL = X_WL.topLeftCorner<3, 3>();
    const Eigen::Vector3d t_WL = X_WL.topRightCorner<3, 1>();
    for (int h = 0; h < static_cast<int>(hulls_[link].size()); ++h) {
      const PlacedHull& hull = hulls_[link][h];
      const Eigen::Vector3d center_W = R_WL * hull.center_L + t_WL;
      bool placed_ready = false;
      for (int o = 0; o < static_cast<int>(obstacles_W_.size()); ++o) {
        const double scale = center_W.cwiseAbs().maxCoeff() + hull.radius +
                             obstacle_centers_W_[o].cwiseAbs().maxCoeff() + obstacle_radii_[o];
        const double sphere_gap = (center_W - obstacle_centers_W_[o]).norm() - hull.radius -
                                  obstacle_radii_[o] - rounding_margin(scale);
        // The spheres prove separation, and the gap bounds the distance from below.
        if (sphere_gap > 0.0 && sphere_gap >= result.min_distance_estimate) continue;
        if (!placed_ready) {
          placed.resize(hull.points_L.size());
          for (std::size_t k = 0; k < placed.size(); ++k) placed[k] = R_WL * hull.points_L[k] + t_WL;
          placed_ready = true;
        }
        const geometry::GjkResult gjk = geometry::gjk(placed, obstacles_W_[o]);
        bool separated = false;
        if (gjk.status == geometry::GjkStatus::kSeparated) {
          // GJK only proposes the direction v (from the obstacle to the hull); the plane is
          // verified here over every point with a margin beyond rounding.
          const Eigen::Vector3d& v = gjk.closest_vector;
          double hull_low = std::numeric_limits<double>::infinity();
          double obstacle_high = -std::numeric_limits<double>::infinity();
          for (const auto& p : placed) hull_low = std::min(hull_low, v.dot(p));
          for (const auto& p : obstacles_W_[o]) obstacle_high = std::max(obstacle_high, v.dot(p));
          const double margin = rounding_margin(std::max(max_abs(placed), max_abs(obstacles_W_[o]))) *
                                v.lpNorm<1>();
          separated = hull_low - obstacle_high > margin;
        }
        if (!separated) {
          ++exact_checks_;
          const geometry::Contact contact = geometry::classify_exact(
              geometry::ConvexPolytope::from_points(placed), obstacle_polytopes_[o]);
          separated = contact == geometry::Contact::kSeparated;
        }
        if (separated) {
          result.min_distance_estimate = std::min(result.min_distance_estimate, gjk.distance);
          continue;
        }
        result.min_distance_estimate = 0.0;
        if (!result.contact) {
          result.contact = true;
          result.link = link;
          result.hull = h;
          result.obstacle = o;
        }
        if (stop_at_contact) return result;
      }
    }
  }
  return result;
}

OraclePathResult MotionOracle::sample_path(const PathProgram& program, double spacing) const {
  const RobotModel& robot = *robot_;
  const long long exact_before = exact_checks_;
  OraclePathResult result;
  Eigen::VectorXd q_start(robot.joint_count());
  for (int j = 0; j < robot.joint_count(); ++j) q_start[j] = robot.joints[j].home;

  auto visit = [&](const Eigen::VectorXd& q, int segment, double t) {
    ++result.samples;
    const OracleContact contact = check(q);
    result.min_distance_estimate = std::min(result.min_distance_estimate, contact.min_distance_estimate);
    if (!contact.contact) return false;
    result.first_contact = contact;
    result.contact_segment = segment;
    result.contact_time = t;
    result.contact_q = q;
    return true;
  };

  bool done = visit(q_start, 1, 0.0);
  for (int s = 0; s < static_cast<int>(program.segments.size()) && !done; ++s) {
    const auto* ptp = std::get_if<PtpJointSegment>(&program.segments[s].spec);
    if (ptp == nullptr) throw std::invalid_argument("MotionOracle: PTP joint segments only");
    const motion::PtpMotion motion = motion::PtpMotion::plan(
        robot, q_start, ptp->target, ptp->velocity, motion::PtpTiming::kIndependent);
    const double duration = motion.duration();
    double t = 0.0;
    Eigen::VectorXd q = motion.joints_at(0.0);
    double h = duration / 64.0;
    while (t < duration && !done) {
      const double t1 = std::min(duration, t + h);
      const Eigen::VectorXd q1 = motion.joints_at(t1);
      const double bound = motion_bound(q1 - q);
      if (bound > spacing && h > duration * 1e-12) {
        h *= 0.5;
        continue;
      }
      if (bound < 0.5 * spacing) h *= 1.5;
      t = t1;
      q = q1;
      done = visit(q, s + 1, t);
    }
    q_start = ptp->target;  // the motion stage starts the next segment at the target
  }
  result.exact_checks = exact_checks_ - exact_before;
  if (done) result.min_distance_estimate = 0.0;
  return result;
}

}  // namespace grpvss::test

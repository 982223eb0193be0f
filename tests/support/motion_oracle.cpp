#include "support/motion_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <variant>

#include <Eigen/Geometry>

#include "grpvss/motion/cp_line.hpp"
#include "grpvss/motion/ptp_motion.hpp"
#include "support/exact_hull_lp.hpp"
#include "support/oracle_margins.hpp"
#include "support/kinematics_reference.hpp"

namespace grpvss::test {
namespace {

// The smallest distance from above, overall and for the 1-based `segment`.
void keep_upper(OraclePathResult& result, int segment, double upper) {
  result.min_distance_upper = std::min(result.min_distance_upper, upper);
  const auto index = static_cast<std::size_t>(segment - 1);
  if (result.segment_min_distance_upper.size() <= index) {
    result.segment_min_distance_upper.resize(index + 1, std::numeric_limits<double>::infinity());
  }
  double& kept = result.segment_min_distance_upper[index];
  kept = std::min(kept, upper);
}

// Gilbert's original iteration (Frank-Wolfe on conv(A - B), 1966): v moves towards the
// origin along the segment to the support point of -v. Only PROPOSES a direction; the caller
// verifies the plane over every point. Start: the centroid difference (a point of A - B).
Eigen::Vector3d gilbert_direction(const std::vector<Eigen::Vector3d>& a, const Eigen::Vector3d& a_center,
                                  const std::vector<Eigen::Vector3d>& b, const Eigen::Vector3d& b_center) {
  Eigen::Vector3d v = a_center - b_center;
  if (v.squaredNorm() == 0.0) v = Eigen::Vector3d::UnitX();
  for (int iteration = 0; iteration < 64; ++iteration) {
    const Eigen::Vector3d* a_low = &a.front();
    for (const auto& p : a) {
      if (v.dot(p) < v.dot(*a_low)) a_low = &p;
    }
    const Eigen::Vector3d* b_high = &b.front();
    for (const auto& p : b) {
      if (v.dot(p) > v.dot(*b_high)) b_high = &p;
    }
    const Eigen::Vector3d w = *a_low - *b_high;
    const double vv = v.squaredNorm();
    const double vw = v.dot(w);
    // Converged: the lower bound vw/|v| is within 0.1% of the upper bound |v|.
    if (vw > 0.0 && vv - vw <= 2e-3 * vv) break;
    const Eigen::Vector3d d = w - v;
    const double dd = d.squaredNorm();
    if (dd == 0.0) break;
    const double t = std::clamp(-v.dot(d) / dd, 0.0, 1.0);
    if (t == 0.0) break;  // no progress: v is (numerically) the closest point
    v += t * d;
    if (v.squaredNorm() < 1e-24) break;  // the hulls (nearly) meet: the exact test decides
  }
  return v;
}

// Float facet normals (outward, unit) and edge directions (unit) of conv(points), by brute
// force: a triple spans a facet plane when every point lies on one side (within `slack`); a
// pair is an edge when both points lie on two distinct facet planes. Approximate (proposals).
void float_features(const std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector3d>& normals,
                    std::vector<Eigen::Vector3d>& edges) {
  const std::size_t n = points.size();
  const double slack = 1e-9 * (1.0 + max_abs_coordinate(points));
  auto add_unique = [](std::vector<Eigen::Vector3d>& list, const Eigen::Vector3d& d, bool oriented) {
    for (const auto& e : list) {
      if (e.dot(d) > 1.0 - 1e-9 || (!oriented && e.dot(d) < -1.0 + 1e-9)) return;
    }
    list.push_back(d);
  };
  std::vector<std::pair<Eigen::Vector3d, double>> planes;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      for (std::size_t k = j + 1; k < n; ++k) {
        Eigen::Vector3d normal = (points[j] - points[i]).cross(points[k] - points[i]);
        if (normal.norm() <= slack) continue;
        normal.normalize();
        for (const double sign : {1.0, -1.0}) {
          const Eigen::Vector3d m = sign * normal;
          const double offset = m.dot(points[i]);
          bool facet = true;
          for (const auto& p : points) facet = facet && m.dot(p) <= offset + slack;
          if (facet) {
            add_unique(normals, m, true);
            planes.push_back({m, offset});
          }
        }
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      int containing = 0;
      const Eigen::Vector3d* first = nullptr;
      for (const auto& [m, offset] : planes) {
        if (std::abs(m.dot(points[i]) - offset) > slack || std::abs(m.dot(points[j]) - offset) > slack) continue;
        if (first != nullptr && first->dot(m) > 1.0 - 1e-9) continue;
        if (first == nullptr) first = &m;
        ++containing;
      }
      const Eigen::Vector3d d = points[j] - points[i];
      if (containing >= 2 && d.norm() > slack) add_unique(edges, d.normalized(), false);
    }
  }
}

// The separating-axis proposal: the axis (oriented from b towards a) with the largest float
// gap among facet normals of both and edge cross products.
Eigen::Vector3d best_float_axis(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& a_normals,
                                const std::vector<Eigen::Vector3d>& a_edges, const std::vector<Eigen::Vector3d>& b,
                                const std::vector<Eigen::Vector3d>& b_normals,
                                const std::vector<Eigen::Vector3d>& b_edges) {
  Eigen::Vector3d best = Eigen::Vector3d::UnitX();
  double best_gap = -std::numeric_limits<double>::infinity();
  auto consider = [&](const Eigen::Vector3d& axis) {
    double a_low = std::numeric_limits<double>::infinity(), a_high = -a_low;
    double b_low = a_low, b_high = -a_low;
    for (const auto& p : a) {
      const double s = axis.dot(p);
      a_low = std::min(a_low, s);
      a_high = std::max(a_high, s);
    }
    for (const auto& p : b) {
      const double s = axis.dot(p);
      b_low = std::min(b_low, s);
      b_high = std::max(b_high, s);
    }
    if (a_low - b_high > best_gap) {
      best_gap = a_low - b_high;
      best = axis;
    }
    if (b_low - a_high > best_gap) {
      best_gap = b_low - a_high;
      best = -axis;
    }
  };
  for (const auto& n : a_normals) consider(n);
  for (const auto& n : b_normals) consider(n);
  for (const auto& e : a_edges) {
    for (const auto& f : b_edges) {
      const Eigen::Vector3d axis = e.cross(f);
      const double norm = axis.norm();
      if (norm > 1e-9) consider(axis / norm);
    }
  }
  return best;
}

}  // namespace

MotionOracle::MotionOracle(const RobotModel& robot, const Environment& environment)
    : robot_(&robot) {
  auto make_shape = [](const std::vector<Eigen::Vector3d>& points) {
    Shape shape;
    shape.points = points;
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    for (const auto& p : points) center += p;
    center /= static_cast<double>(points.size());
    double radius = 0.0;
    for (const auto& p : points) radius = std::max(radius, (p - center).norm());
    shape.center = center;
    shape.radius = radius * (1.0 + 1e-12);
    float_features(points, shape.face_normals, shape.edge_directions);
    return shape;
  };
  for (const Link& link : robot.links) {
    hulls_L_.emplace_back();
    for (const HullPoints& hull : link.hulls) hulls_L_.back().push_back(make_shape(hull.points));
  }
  for (const HullPoints& obstacle : environment.obstacles) obstacles_W_.push_back(make_shape(obstacle.points));
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
  std::vector<Eigen::Vector3d> placed, rotated_normals, rotated_edges;
  Eigen::Matrix4d X_WL = Eigen::Matrix4d::Identity();
  for (int link = 0; link < static_cast<int>(hulls_L_.size()); ++link) {
    if (link > 0) X_WL = (X_WL * dh_matrix<double>(robot_->joints[link - 1], q[link - 1])).eval();
    if (hulls_L_[link].empty()) continue;
    const Eigen::Matrix3d R_WL = X_WL.topLeftCorner<3, 3>();
    const Eigen::Vector3d t_WL = X_WL.topRightCorner<3, 1>();
    for (int h = 0; h < static_cast<int>(hulls_L_[link].size()); ++h) {
      const Shape& hull = hulls_L_[link][h];
      const Eigen::Vector3d center_W = R_WL * hull.center + t_WL;
      bool placed_ready = false;
      for (int o = 0; o < static_cast<int>(obstacles_W_.size()); ++o) {
        const Shape& obstacle = obstacles_W_[o];
        const double scale = center_W.cwiseAbs().maxCoeff() + hull.radius +
                             obstacle.center.cwiseAbs().maxCoeff() + obstacle.radius;
        const double sphere_gap = (center_W - obstacle.center).norm() - hull.radius -
                                  obstacle.radius - 3.0 * oracle_rounding_margin(scale);
        // The spheres prove separation, and the gap bounds the distance from below: nothing
        // to learn from this pair.
        if (sphere_gap > 0.0 && sphere_gap >= result.min_distance_estimate) continue;
        if (!placed_ready) {
          placed.resize(hull.points.size());
          for (std::size_t k = 0; k < placed.size(); ++k) placed[k] = R_WL * hull.points[k] + t_WL;
          placed_ready = true;
        }
        // Pre-filter: a plane normal to v with a gap beyond rounding over EVERY point.
        const double scale_points = std::max(max_abs_coordinate(placed), max_abs_coordinate(obstacle.points));
        auto plane_gap = [&](const Eigen::Vector3d& v) {
          double hull_low = std::numeric_limits<double>::infinity();
          double obstacle_high = -std::numeric_limits<double>::infinity();
          for (const auto& p : placed) hull_low = std::min(hull_low, v.dot(p));
          for (const auto& p : obstacle.points) obstacle_high = std::max(obstacle_high, v.dot(p));
          return hull_low - obstacle_high - oracle_rounding_margin(scale_points) * v.lpNorm<1>();
        };
        const Eigen::Vector3d gilbert =
            gilbert_direction(placed, center_W, obstacle.points, obstacle.center);
        Eigen::Vector3d v = gilbert;
        double gap = plane_gap(v);
        // Gilbert's iteration converges slowly next to contact: unless its plane is within 1%
        // of its upper bound |v| on the distance, try the facet/edge axes too.
        if (!(gap > 0.0) || (gap < 0.99 * v.squaredNorm() && gap < result.min_distance_estimate * v.norm())) {
          rotated_normals.clear();
          rotated_edges.clear();
          for (const auto& n : hull.face_normals) rotated_normals.push_back(R_WL * n);
          for (const auto& e : hull.edge_directions) rotated_edges.push_back(R_WL * e);
          const Eigen::Vector3d axis = best_float_axis(placed, rotated_normals, rotated_edges, obstacle.points,
                                                       obstacle.face_normals, obstacle.edge_directions);
          const double axis_gap = plane_gap(axis);
          if (axis_gap > gap) {
            v = axis;
            gap = axis_gap;
          }
        }
        bool separated = gap > 0.0;
        if (!separated) {
          ++exact_checks_;
          separated = !hulls_intersect_exact_lp(placed, obstacle.points);
        }
        if (separated) {
          const double distance = std::max(0.0, gap / v.norm());
          result.min_distance_estimate = std::min(result.min_distance_estimate, distance);
          // Gilbert's iterate is a point of conv(hull - obstacle): |iterate| >= the distance.
          result.min_distance_upper = std::min(result.min_distance_upper, gilbert.norm());
          continue;
        }
        result.min_distance_estimate = 0.0;
        result.min_distance_upper = 0.0;
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

// Marches t over [0, 1]: `next(t_from, q_from, t_to)` gives the configuration at t_to (or
// nothing: the motion cannot be followed). A step is accepted when its motion bound is at
// most max(spacing, clearance - reserve), `clearance` being the (float, conservative) lower
// bound on the distance at the last sample: every configuration in between is then farther
// than `reserve` from every obstacle (no contact skipped; and wherever the clearance is below
// `reserve` the samples are `spacing` apart). Steps are at most `max_h`. A step that still
// moves too far at 1e-9 of the range is a jump: visit(nullptr, t). Returns true if stopped.
template <typename Motion, typename Visit>
bool MotionOracle::march(const Motion& next, double spacing, Visit&& visit, const double& clearance,
                         double max_h) const {
  const double reserve = kReserveSpacings * spacing;
  double t = 0.0;
  std::optional<Eigen::VectorXd> q = next(0.0, Eigen::VectorXd(), 0.0);
  if (!q) return visit(nullptr, 0.0);
  double h = std::min(max_h, 1.0 / 64.0);
  while (t < 1.0) {
    const double allowed = std::max(spacing, clearance - reserve);
    const double t1 = std::min(1.0, t + h);
    const std::optional<Eigen::VectorXd> q1 = next(t, *q, t1);
    const double bound = q1 ? motion_bound(*q1 - *q) : std::numeric_limits<double>::infinity();
    if (bound > allowed) {
      if (h > 1e-9) {
        h *= 0.5;
        continue;
      }
      return visit(nullptr, t1);  // a jump or an unreachable stretch
    }
    if (bound < 0.5 * allowed) h = std::min(max_h, h * 1.5);
    t = t1;
    q = q1;
    if (visit(&*q, t)) return true;
  }
  return false;
}

OraclePathResult MotionOracle::sample_path(const PathProgram& program, double spacing,
                                           const motion::KinematicsAccess& kinematics) const {
  const RobotModel& robot = *robot_;
  const long long exact_before = exact_checks_;
  OraclePathResult result;
  Eigen::VectorXd q_start(robot.joint_count());
  for (int j = 0; j < robot.joint_count(); ++j) q_start[j] = robot.joints[j].home;

  // Returns true to stop: at a contact, or (q == nullptr) where a line cannot be followed.
  int segment = 1;
  double parameter_scale = 0.0;
  Eigen::VectorXd last_q = q_start;
  double clearance = 0.0;
  auto visit = [&](const Eigen::VectorXd* q, double t) {
    if (q == nullptr) {
      result.line_not_followed = true;
      result.stopped_segment = segment;
      return true;
    }
    last_q = *q;
    ++result.samples;
    const OracleContact contact = check(*q);
    clearance = contact.min_distance_estimate;
    result.min_distance_estimate = std::min(result.min_distance_estimate, contact.min_distance_estimate);
    keep_upper(result, segment, contact.min_distance_upper);
    if (!contact.contact) return false;
    result.first_contact = contact;
    result.contact_segment = segment;
    result.contact_parameter = t * parameter_scale;
    result.contact_q = *q;
    return true;
  };

  bool done = visit(&q_start, 0.0);
  for (int s = 0; s < static_cast<int>(program.segments.size()) && !done; ++s) {
    segment = s + 1;
    if (const auto* ptp = std::get_if<PtpJointSegment>(&program.segments[s].spec)) {
      const motion::PtpMotion motion = motion::PtpMotion::plan(
          robot, q_start, ptp->target, ptp->velocity, motion::PtpTiming::kIndependent);
      const double duration = motion.duration();
      parameter_scale = duration;
      auto next = [&](double, const Eigen::VectorXd&, double t) {
        return std::optional<Eigen::VectorXd>(motion.joints_at(t * duration));
      };
      done = march(next, spacing, visit, clearance, 0.25);
      q_start = ptp->target;  // the motion stage starts the next segment at the target
    } else if (const auto* cp = std::get_if<CpLineSegment>(&program.segments[s].spec)) {
      const motion::CpLine line(kinematics.forward(q_start), cp->target);
      if (line.is_zero_length()) {
        done = visit(nullptr, 0.0);
        break;
      }
      parameter_scale = line.length();
      const Eigen::VectorXd q_line_start = q_start;
      auto next = [&](double, const Eigen::VectorXd& q_from, double t) -> std::optional<Eigen::VectorXd> {
        if (t == 0.0) return q_line_start;
        return motion::solve_within_limits(robot, kinematics, line.pose_at(t * line.length()), q_from);
      };
      // IK is checked at least every max(spacing, 0.05) of path length, also far from obstacles:
      // an unreachable stretch or a jump there stops the oracle ("line not followed").
      done = march(next, spacing, visit, clearance, std::max(spacing, 0.05) / line.length());
      q_start = last_q;
    } else {
      throw std::invalid_argument("MotionOracle: PTP(JCS) and CP segments only");
    }
  }
  result.exact_checks = exact_checks_ - exact_before;
  if (result.first_contact.contact) result.min_distance_estimate = 0.0;
  return result;
}

OraclePathResult MotionOracle::sample_joint_linear(const std::vector<Eigen::VectorXd>& q_samples,
                                                   double spacing, int segment) const {
  const long long exact_before = exact_checks_;
  OraclePathResult result;
  double piece = 0.0;
  double clearance = 0.0;
  auto visit = [&](const Eigen::VectorXd* q, double t) {
    if (q == nullptr) throw std::logic_error("sample_joint_linear: a joint-linear piece is continuous");
    ++result.samples;
    const OracleContact contact = check(*q);
    clearance = contact.min_distance_estimate;
    result.min_distance_estimate = std::min(result.min_distance_estimate, contact.min_distance_estimate);
    keep_upper(result, 1, contact.min_distance_upper);
    if (!contact.contact) return false;
    result.first_contact = contact;
    result.contact_segment = segment;
    result.contact_parameter = piece + t;
    result.contact_q = *q;
    return true;
  };
  bool done = !q_samples.empty() && visit(&q_samples.front(), 0.0);
  for (std::size_t k = 1; k < q_samples.size() && !done; ++k) {
    piece = static_cast<double>(k - 1);
    const Eigen::VectorXd& q0 = q_samples[k - 1];
    const Eigen::VectorXd& q1 = q_samples[k];
    auto next = [&](double, const Eigen::VectorXd&, double t) {
      return std::optional<Eigen::VectorXd>(q0 + t * (q1 - q0));
    };
    done = march(next, spacing, visit, clearance, 0.25);
  }
  result.exact_checks = exact_checks_ - exact_before;
  if (result.first_contact.contact) result.min_distance_estimate = 0.0;
  return result;
}

}  // namespace grpvss::test

#include "support/urdf_cell_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <variant>

#include <Eigen/Geometry>

#include "grpvss/exact/circumscribed_shapes.hpp"
#include "grpvss/io/urdf_file.hpp"
#include "grpvss/kinematics/urdf_chain.hpp"
#include "grpvss/motion/ptp_motion.hpp"
#include "support/exact_hull_lp.hpp"

namespace grpvss::test {
namespace {

// A plane or sphere gap beyond this separates exactly (coordinates < 10 m here, a dot
// product's rounding ~1e-15 |v|_1 (1 + scale)).
double rounding_margin(double scale) { return 1e-9 * (1.0 + scale); }

double max_abs(const std::vector<Eigen::Vector3d>& points) {
  double largest = 0.0;
  for (const auto& p : points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  return largest;
}

// Gilbert's 1966 iteration (Frank-Wolfe on conv(A - B)): proposes a direction only.
Eigen::Vector3d gilbert_direction(const std::vector<Eigen::Vector3d>& a, const Eigen::Vector3d& a_center,
                                  const std::vector<Eigen::Vector3d>& b, const Eigen::Vector3d& b_center) {
  Eigen::Vector3d v = a_center - b_center;
  if (v.squaredNorm() == 0.0) v = Eigen::Vector3d::UnitX();
  for (int iteration = 0; iteration < 256; ++iteration) {
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
    if (vw > 0.0 && vv - vw <= 1e-4 * vv) break;
    const Eigen::Vector3d d = w - v;
    const double dd = d.squaredNorm();
    if (dd == 0.0) break;
    const double t = std::clamp(-v.dot(d) / dd, 0.0, 1.0);
    if (t == 0.0) break;
    v += t * d;
    if (v.squaredNorm() < 1e-30) break;
  }
  return v;
}

Pose<double> base_pose(const CellDescription& description) {
  const CellPose& base = description.robot.base;
  Pose<double> X = Pose<double>::Identity();
  if (base.quaternion) {
    const Eigen::Vector4d& w = *base.quaternion;
    X.topLeftCorner<3, 3>() = Eigen::Quaterniond(w[0], w[1], w[2], w[3]).normalized().toRotationMatrix();
  } else {
    X.topLeftCorner<3, 3>() = rpy_matrix<double>(base.rpy);
  }
  X.topRightCorner<3, 1>() = base.xyz * description.metres_per_unit;
  return X;
}

// The collision's points in its own frame: what the cell stage makes of it (mesh vertices,
// box corners, a circumscribing polytope of a cylinder or sphere).
std::vector<Eigen::Vector3d> collision_points_C(const CollisionDescription& c) {
  if (c.shape == CollisionShape::kCylinder) return geometry::circumscribed_cylinder(c.radius, c.length);
  if (c.shape == CollisionShape::kSphere) return geometry::circumscribed_sphere(c.radius);
  return kinematics::collision_frame_points(c).points;
}

}  // namespace

UrdfCellOracle::UrdfCellOracle(const cell::LoadedCell& cell) : cell_(&cell) {
  const CellDescription& description = cell.description;
  if (description.robot.source != CellRobot::Source::kUrdf) throw std::invalid_argument("a URDF cell");
  io::UrdfReadOptions options;
  options.tip = description.robot.tip;
  options.package_paths = description.robot.package_paths;
  options.use_ros_package_path = false;
  const RobotDescription robot = io::read_urdf_file(description.robot.file, options).description;
  urdf_ = read_reference_urdf(description.robot.file);
  X_W_root_ = base_pose(description);
  for (const ChainJointDescription& joint : robot.joints) chain_joints_.push_back(joint.name);
  for (const SideJointDescription& side : robot.side_joints) {
    if (side.mimics.empty()) side_values_[side.name] = side.value;
  }
  for (const ChainLinkDescription& link : robot.links) {
    hulls_.emplace_back();
    for (const CollisionDescription& c : link.collisions) {
      const ReferenceCollision& rc = urdf_.collisions.at(c.link).at(static_cast<std::size_t>(c.index));
      hulls_.back().push_back({c.link, origin_pose<double>(rc.xyz, rc.rpy), collision_points_C(c)});
    }
  }
  for (const HullPoints& obstacle : cell.environment.obstacles) {
    Shape shape;
    shape.points = obstacle.points;
    shape.center = Eigen::Vector3d::Zero();
    for (const auto& p : obstacle.points) shape.center += p;
    shape.center /= static_cast<double>(obstacle.points.size());
    for (const auto& p : obstacle.points) shape.radius = std::max(shape.radius, (p - shape.center).norm());
    shape.radius *= 1.0 + 1e-12;
    obstacles_.push_back(shape);
  }
  // R_j: rotating joint j moves a point p carried by it at most |dq| |p - o_j|, o_j the
  // origin of joint j's frame (on its axis). Walking from p's URDF link up to joint j,
  // |p - o_j| <= sum of |xyz| of the joint origins below j (+ the travel of prismatic ones)
  // + |xyz of the collision origin| + max |p_C|. A prismatic chain joint moves points by |dq|.
  reach_.assign(chain_joints_.size(), 0.0);
  for (const auto& link_hulls : hulls_) {
    for (const Hull& hull : link_hulls) {
      double below = hull.X_LC.topRightCorner<3, 1>().norm();
      double farthest = 0.0;
      for (const auto& p : hull.points_C) farthest = std::max(farthest, p.norm());
      below += farthest;
      for (std::string link = hull.urdf_link; urdf_.joint_to_child.count(link) > 0;) {
        const ReferenceJoint& joint = urdf_.joints[urdf_.joint_to_child.at(link)];
        const auto chain = std::find(chain_joints_.begin(), chain_joints_.end(), joint.name);
        if (chain != chain_joints_.end()) {
          const auto j = static_cast<std::size_t>(chain - chain_joints_.begin());
          reach_[j] = std::max(reach_[j], joint.type == "prismatic" ? 1.0 : below);
        }
        below += decimal3<double>(joint.xyz).norm();
        if (joint.type == "prismatic") below += std::max(std::abs(joint.lower), std::abs(joint.upper));
        link = joint.parent;
      }
    }
  }
  for (double& r : reach_) r *= 1.0 + 1e-9;
}

double UrdfCellOracle::motion_bound(const Eigen::VectorXd& dq) const {
  double bound = 0.0;
  for (int j = 0; j < dq.size(); ++j) bound += std::abs(dq[j]) * reach_[static_cast<std::size_t>(j)];
  return bound;
}

double UrdfCellOracle::relative_motion_bound(int link_a, int link_b, const Eigen::VectorXd& dq) const {
  double bound = 0.0;
  for (int j = link_a; j < link_b; ++j) bound += std::abs(dq[j]) * reach_[static_cast<std::size_t>(j)];
  return bound;
}

std::vector<std::vector<std::vector<Eigen::Vector3d>>> UrdfCellOracle::place(const Eigen::VectorXd& q) const {
  std::map<std::string, double> set = side_values_;
  for (std::size_t j = 0; j < chain_joints_.size(); ++j) set[chain_joints_[j]] = q[static_cast<Eigen::Index>(j)];
  const std::map<std::string, double> values = joint_values<double>(urdf_, set);
  std::map<std::string, Pose<double>> link_poses;
  std::vector<std::vector<std::vector<Eigen::Vector3d>>> placed(hulls_.size());
  for (std::size_t i = 0; i < hulls_.size(); ++i) {
    for (const Hull& hull : hulls_[i]) {
      auto pose = link_poses.find(hull.urdf_link);
      if (pose == link_poses.end()) {
        pose = link_poses.emplace(hull.urdf_link, (X_W_root_ * link_pose<double>(urdf_, hull.urdf_link, values)).eval())
                   .first;
      }
      const Pose<double> X_WC = pose->second * hull.X_LC;
      const Eigen::Matrix3d R = X_WC.topLeftCorner<3, 3>();
      const Eigen::Vector3d t = X_WC.topRightCorner<3, 1>();
      std::vector<Eigen::Vector3d> points;
      points.reserve(hull.points_C.size());
      for (const auto& p : hull.points_C) points.push_back(R * p + t);
      placed[i].push_back(std::move(points));
    }
  }
  return placed;
}

bool UrdfCellOracle::decide(const Shape& a, const Shape& b, double& distance) const {
  const double scale = std::max(max_abs(a.points), max_abs(b.points));
  const double sphere_gap = (a.center - b.center).norm() - a.radius - b.radius - 3.0 * rounding_margin(scale);
  if (sphere_gap > 0.0) {
    distance = sphere_gap;
    return false;
  }
  const Eigen::Vector3d v = gilbert_direction(a.points, a.center, b.points, b.center);
  double a_low = std::numeric_limits<double>::infinity(), b_high = -a_low;
  for (const auto& p : a.points) a_low = std::min(a_low, v.dot(p));
  for (const auto& p : b.points) b_high = std::max(b_high, v.dot(p));
  const double gap = a_low - b_high - rounding_margin(scale) * v.lpNorm<1>();
  if (gap > 0.0) {
    distance = gap / v.norm();
    return false;
  }
  ++exact_checks_;
  distance = 0.0;
  return hulls_intersect_exact_lp(a.points, b.points);
}

UrdfOracleContact UrdfCellOracle::check(const Eigen::VectorXd& q, bool stop_at_contact) const {
  const auto placed = place(q);
  std::vector<std::vector<Shape>> shapes(placed.size());
  for (std::size_t i = 0; i < placed.size(); ++i) {
    for (const auto& points : placed[i]) {
      Shape shape;
      shape.points = points;
      shape.center = Eigen::Vector3d::Zero();
      for (const auto& p : points) shape.center += p;
      shape.center /= static_cast<double>(points.size());
      for (const auto& p : points) shape.radius = std::max(shape.radius, (p - shape.center).norm());
      shape.radius *= 1.0 + 1e-12;
      shapes[i].push_back(std::move(shape));
    }
  }
  UrdfOracleContact result;
  const Environment& environment = cell_->environment;
  for (int link = 0; link < static_cast<int>(shapes.size()); ++link) {
    for (int h = 0; h < static_cast<int>(shapes[link].size()); ++h) {
      for (int o = 0; o < static_cast<int>(obstacles_.size()); ++o) {
        if (environment.contact_allowed(link, h, o)) continue;
        double distance = 0.0;
        const bool contact = decide(shapes[link][h], obstacles_[o], distance);
        result.obstacle_distance = std::min(result.obstacle_distance, distance);
        if (!contact || result.contact) continue;
        result.contact = true;
        result.link = link;
        result.hull = h;
        result.obstacle = o;
        if (stop_at_contact) return result;
      }
    }
  }
  for (const SelfCollisionPair& pair : cell_->robot.self_collision_pairs) {
    double distance = 0.0;
    const bool contact = decide(shapes[pair.link_a][pair.hull_a], shapes[pair.link_b][pair.hull_b], distance);
    result.self_pair_distances.push_back(distance);
    if (distance < result.self_distance) {
      result.self_distance = distance;
      result.nearest_self[0] = pair.link_a;
      result.nearest_self[1] = pair.hull_a;
      result.nearest_self[2] = pair.link_b;
      result.nearest_self[3] = pair.hull_b;
    }
    if (!contact || result.contact) continue;
    result.contact = true;
    result.self = true;
    result.link = pair.link_a;
    result.hull = pair.hull_a;
    result.other_link = pair.link_b;
    result.other_hull = pair.hull_b;
    if (stop_at_contact) return result;
  }
  return result;
}

// Each PTP segment: t in [0, 1] of the segment's duration; a step is taken when its world
// motion bound (every joint is monotone on a PTP move) is at most max(spacing, obstacle
// clearance - reserve) and each self pair's relative bound at most max(spacing, its distance -
// reserve), distances at the last sample: the skipped motion stays `reserve` clear.
UrdfOraclePath UrdfCellOracle::sample_path(const PathProgram& program, motion::PtpTiming timing,
                                           double spacing) const {
  const RobotModel& robot = cell_->robot;
  const double reserve = 40.0 * spacing;
  const long long exact_before = exact_checks_;
  UrdfOraclePath result;
  Eigen::VectorXd q(robot.joint_count());
  for (int j = 0; j < robot.joint_count(); ++j) q[j] = robot.joints[static_cast<std::size_t>(j)].home;
  double clearance = 0.0;
  std::vector<double> self_distances;
  const auto& pairs = robot.self_collision_pairs;
  // Every hull point moves at most max(spacing, clearance - reserve) in the world, and every
  // self pair's hull b at most max(spacing, its distance - reserve) in link a's frame.
  auto step_ok = [&](const Eigen::VectorXd& dq) {
    if (motion_bound(dq) > std::max(spacing, clearance - reserve)) return false;
    for (std::size_t p = 0; p < pairs.size() && p < self_distances.size(); ++p) {
      if (relative_motion_bound(pairs[p].link_a, pairs[p].link_b, dq) > std::max(spacing, self_distances[p] - reserve)) {
        return false;
      }
    }
    return true;
  };
  auto visit = [&](const Eigen::VectorXd& at, int segment) {
    ++result.samples;
    const UrdfOracleContact contact = check(at);
    clearance = contact.obstacle_distance;
    self_distances = contact.self_pair_distances;
    result.min_obstacle_distance = std::min(result.min_obstacle_distance, contact.obstacle_distance);
    if (contact.self_distance < result.min_self_distance) {
      result.min_self_distance = contact.self_distance;
      std::copy(contact.nearest_self, contact.nearest_self + 4, result.nearest_self);
    }
    if (!contact.contact) return false;
    result.first_contact = contact;
    result.contact_segment = segment;
    result.contact_q = at;
    return true;
  };
  bool done = visit(q, 0);
  for (int s = 0; s < static_cast<int>(program.segments.size()) && !done; ++s) {
    const auto* ptp = std::get_if<PtpJointSegment>(&program.segments[static_cast<std::size_t>(s)].spec);
    if (ptp == nullptr) throw std::invalid_argument("UrdfCellOracle: PTP(JCS) segments only");
    const motion::PtpMotion motion = motion::PtpMotion::plan(robot, q, ptp->target, ptp->velocity, timing);
    const double duration = motion.duration();
    double t = 0.0, h = 1.0 / 64.0;
    Eigen::VectorXd q_t = q;
    while (t < 1.0 && !done) {
      const double t1 = std::min(1.0, t + h);
      const Eigen::VectorXd q1 = motion.joints_at(t1 * duration);
      if (!step_ok(q1 - q_t)) {
        h *= 0.5;
        if (h < 1e-12) throw std::logic_error("UrdfCellOracle: a PTP move does not shrink");
        continue;
      }
      if (step_ok(2.0 * (q1 - q_t))) h = std::min(0.25, h * 1.5);
      t = t1;
      q_t = q1;
      done = visit(q_t, s + 1);
    }
    q = ptp->target;
  }
  result.exact_checks = exact_checks_ - exact_before;
  return result;
}

}  // namespace grpvss::test

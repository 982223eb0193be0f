#include "support/urdf_cell_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>
#include <variant>

#include <Eigen/Geometry>

#include "grpvss/exact/circumscribed_shapes.hpp"
#include "grpvss/io/urdf_file.hpp"
#include "grpvss/kinematics/urdf_chain.hpp"
#include "grpvss/motion/ptp_motion.hpp"
#include "support/exact_hull_lp.hpp"
#include "support/oracle_margins.hpp"

namespace grpvss::test {
namespace {

// Gilbert's 1966 iteration (Frank-Wolfe on conv(A - B)): proposes a direction only.
// `v` starts at a point of conv(A - B).
Eigen::Vector3d gilbert_direction_from_start(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b,
                                  Eigen::Vector3d v) {
  if (v.squaredNorm() == 0.0) return Eigen::Vector3d::UnitX();
  // 256 iterations towards a near-optimal plane; nearly touching pairs (1e-8 m over hulls of a
  // metre) may need thousands before any plane clears the rounding margin, still far cheaper
  // than the exact LP: after 256, stop at a plane separating by half of |v|.
  for (int iteration = 0; iteration < 8192; ++iteration) {
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
    if (vw > 0.0 && (vv - vw <= 1e-4 * vv || (iteration >= 256 && vw >= 0.5 * vv))) break;
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

// Gilbert's start: the centres' difference, or (warm start) the support point of A - B along
// the pair's last direction.
template <typename Shape>
Eigen::Vector3d start_point(const Shape& a, const Shape& b, const Eigen::Vector3d* direction) {
  if (direction == nullptr || direction->squaredNorm() == 0.0) return a.center - b.center;
  const Eigen::Vector3d& v = *direction;
  const Eigen::Vector3d* a_low = &a.points.front();
  for (const auto& p : a.points) {
    if (v.dot(p) < v.dot(*a_low)) a_low = &p;
  }
  const Eigen::Vector3d* b_high = &b.points.front();
  for (const auto& p : b.points) {
    if (v.dot(p) > v.dot(*b_high)) b_high = &p;
  }
  return *a_low - *b_high;
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
  compute_reach();
}

// r_{h,j}: a revolute joint j moves a point p it carries at speed |dq_j| dist(p, axis_j), and
// that distance does not depend on q through joint j itself. Per vertex, walking from the
// hull's URDF link up to the root: through fixed joints p is carried exactly (their origin
// poses); at the first moving joint dist(p, axis) is exact in its frame; above it only
// |p - o| is known, bounded by |p| + the joint origins' |xyz| (+ prismatic travel). A
// prismatic chain joint moves points by |dq_j|.
void UrdfCellOracle::compute_reach() {
  const auto joint_count = static_cast<Eigen::Index>(chain_joints_.size());
  reach_.assign(hulls_.size(), {});
  for (std::size_t l = 0; l < hulls_.size(); ++l) {
    for (const Hull& hull : hulls_[l]) {
      Eigen::VectorXd reach = Eigen::VectorXd::Zero(joint_count);
      for (const auto& p_C : hull.points_C) {
        Eigen::Vector3d p = hull.X_LC.topLeftCorner<3, 3>() * p_C + hull.X_LC.topRightCorner<3, 1>();
        bool exact = true;  // p is this vertex in `link`'s frame (else only |p| bounds it)
        double norm = p.norm();
        for (std::string link = hull.urdf_link; urdf_.joint_to_child.count(link) > 0;) {
          const ReferenceJoint& joint = urdf_.joints[urdf_.joint_to_child.at(link)];
          const auto chain = std::find(chain_joints_.begin(), chain_joints_.end(), joint.name);
          if (chain != chain_joints_.end()) {
            const auto j = static_cast<Eigen::Index>(chain - chain_joints_.begin());
            double r = norm;
            if (joint.type == "prismatic") {
              r = 1.0;
            } else if (exact) {
              const Eigen::Vector3d n = decimal3<double>(joint.axis).normalized();
              r = std::min(norm, (p - p.dot(n) * n).norm());
            }
            reach[j] = std::max(reach[j], r);
          }
          if (joint.type == "fixed" && exact) {
            const Pose<double> X = origin_pose<double>(joint.xyz, joint.rpy);
            p = X.topLeftCorner<3, 3>() * p + X.topRightCorner<3, 1>();
            norm = p.norm();
          } else {
            exact = false;
            norm += decimal3<double>(joint.xyz).norm();
            if (joint.type == "prismatic") norm += std::max(std::abs(joint.lower), std::abs(joint.upper));
          }
          link = joint.parent;
        }
      }
      reach_[l].push_back(reach * (1.0 + 1e-9));
    }
  }
}

double UrdfCellOracle::hull_motion_bound(int link, int hull, const Eigen::VectorXd& dq) const {
  return reach_[static_cast<std::size_t>(link)][static_cast<std::size_t>(hull)].dot(dq.cwiseAbs());
}

double UrdfCellOracle::motion_bound(const Eigen::VectorXd& dq) const {
  double bound = 0.0;
  for (std::size_t l = 0; l < reach_.size(); ++l) {
    for (std::size_t h = 0; h < reach_[l].size(); ++h) {
      bound = std::max(bound, hull_motion_bound(static_cast<int>(l), static_cast<int>(h), dq));
    }
  }
  return bound;
}

double UrdfCellOracle::relative_motion_bound(int link_a, int link_b, int hull_b, const Eigen::VectorXd& dq) const {
  const Eigen::VectorXd& reach = reach_[static_cast<std::size_t>(link_b)][static_cast<std::size_t>(hull_b)];
  double bound = 0.0;
  for (int j = link_a; j < link_b; ++j) bound += std::abs(dq[j]) * reach[j];
  return bound;
}

std::map<std::string, Pose<double>> UrdfCellOracle::link_poses(const Eigen::VectorXd& q) const {
  std::map<std::string, double> set = side_values_;
  for (std::size_t j = 0; j < chain_joints_.size(); ++j) set[chain_joints_[j]] = q[static_cast<Eigen::Index>(j)];
  const std::map<std::string, double> values = joint_values<double>(urdf_, set);
  std::map<std::string, Pose<double>> poses;
  for (const auto& link_hulls : hulls_) {
    for (const Hull& hull : link_hulls) {
      if (poses.count(hull.urdf_link) == 0) {
        poses.emplace(hull.urdf_link, (X_W_root_ * link_pose<double>(urdf_, hull.urdf_link, values)).eval());
      }
    }
  }
  return poses;
}

std::vector<std::vector<Pose<double>>> UrdfCellOracle::hull_poses(const Eigen::VectorXd& q) const {
  const auto poses = link_poses(q);
  std::vector<std::vector<Pose<double>>> X_WC(hulls_.size());
  for (std::size_t l = 0; l < hulls_.size(); ++l) {
    for (const Hull& h : hulls_[l]) X_WC[l].push_back((poses.at(h.urdf_link) * h.X_LC).eval());
  }
  return X_WC;
}

UrdfCellOracle::Shape UrdfCellOracle::placed_shape(const std::map<std::string, Pose<double>>& poses, int link,
                                                   int hull) const {
  const Hull& h = hulls_[static_cast<std::size_t>(link)][static_cast<std::size_t>(hull)];
  const Pose<double> X_WC = poses.at(h.urdf_link) * h.X_LC;
  const Eigen::Matrix3d R = X_WC.topLeftCorner<3, 3>();
  const Eigen::Vector3d t = X_WC.topRightCorner<3, 1>();
  Shape shape;
  shape.points.reserve(h.points_C.size());
  for (const auto& p : h.points_C) shape.points.push_back(R * p + t);
  shape.center = Eigen::Vector3d::Zero();
  for (const auto& p : shape.points) shape.center += p;
  shape.center /= static_cast<double>(shape.points.size());
  for (const auto& p : shape.points) shape.radius = std::max(shape.radius, (p - shape.center).norm());
  shape.radius *= 1.0 + 1e-12;
  return shape;
}

std::vector<std::vector<std::vector<Eigen::Vector3d>>> UrdfCellOracle::place(const Eigen::VectorXd& q) const {
  const auto poses = link_poses(q);
  std::vector<std::vector<std::vector<Eigen::Vector3d>>> placed(hulls_.size());
  for (std::size_t i = 0; i < hulls_.size(); ++i) {
    for (std::size_t h = 0; h < hulls_[i].size(); ++h) {
      placed[i].push_back(placed_shape(poses, static_cast<int>(i), static_cast<int>(h)).points);
    }
  }
  return placed;
}

bool UrdfCellOracle::decide(const Shape& a, const Shape& b, double& distance, Eigen::Vector3d* direction) const {
  const double scale = std::max(max_abs_coordinate(a.points), max_abs_coordinate(b.points));
  const double sphere_gap = (a.center - b.center).norm() - a.radius - b.radius - 3.0 * oracle_rounding_margin(scale);
  if (sphere_gap > 0.0) {
    distance = sphere_gap;
    return false;
  }
  const Eigen::Vector3d v = gilbert_direction_from_start(a.points, b.points, start_point(a, b, direction));
  if (direction != nullptr) *direction = v;
  double a_low = std::numeric_limits<double>::infinity(), b_high = -a_low;
  for (const auto& p : a.points) a_low = std::min(a_low, v.dot(p));
  for (const auto& p : b.points) b_high = std::max(b_high, v.dot(p));
  const double gap = a_low - b_high - oracle_rounding_margin(scale) * v.lpNorm<1>();
  if (gap > 0.0) {
    distance = gap / v.norm();
    return false;
  }
  ++exact_checks_;
  distance = 0.0;
  return hulls_intersect_exact_lp(a.points, b.points);
}

UrdfOracleContact UrdfCellOracle::check(const Eigen::VectorXd& q, bool stop_at_contact) const {
  const auto poses = link_poses(q);
  std::vector<std::vector<Shape>> shapes(hulls_.size());
  for (std::size_t i = 0; i < hulls_.size(); ++i) {
    for (std::size_t h = 0; h < hulls_[i].size(); ++h) {
      shapes[i].push_back(placed_shape(poses, static_cast<int>(i), static_cast<int>(h)));
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

// One decided pair: its proven gap at its last decision and the motion bound accumulated since.
struct UrdfCellOracle::PairState {
  bool self = false;
  int link = -1, hull = -1, other_link = -1, other_hull = -1, obstacle = -1;
  Eigen::VectorXd reach;  ///< motion bound per |dq_j| of the pair's moving hull (relative for self)
  double gap = -1.0;      ///< proven distance lower bound at the last decision (-1: never decided)
  double moved = 0.0;     ///< motion bound accumulated since the last decision
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  ///< Gilbert's last direction
};

std::vector<UrdfCellOracle::PairState> UrdfCellOracle::pair_states() const {
  std::vector<PairState> pairs;
  for (int link = 0; link < static_cast<int>(hulls_.size()); ++link) {
    for (int h = 0; h < static_cast<int>(hulls_[static_cast<std::size_t>(link)].size()); ++h) {
      for (int o = 0; o < static_cast<int>(obstacles_.size()); ++o) {
        if (cell_->environment.contact_allowed(link, h, o)) continue;
        PairState pair;
        pair.link = link;
        pair.hull = h;
        pair.obstacle = o;
        pair.reach = reach_[static_cast<std::size_t>(link)][static_cast<std::size_t>(h)];
        pairs.push_back(pair);
      }
    }
  }
  for (const SelfCollisionPair& self : cell_->robot.self_collision_pairs) {
    PairState pair;
    pair.self = true;
    pair.link = self.link_a;
    pair.hull = self.hull_a;
    pair.other_link = self.link_b;
    pair.other_hull = self.hull_b;
    // Hull b in link a's frame: joints a..b-1 only (relative_motion_bound).
    pair.reach = reach_[static_cast<std::size_t>(self.link_b)][static_cast<std::size_t>(self.hull_b)];
    for (int j = 0; j < pair.reach.size(); ++j) {
      if (j < self.link_a || j >= self.link_b) pair.reach[j] = 0.0;
    }
    pairs.push_back(pair);
  }
  return pairs;
}

// Each PTP segment: t in [0, 1] of the segment's duration (every joint is monotone on a PTP
// move, so the reach bounds apply). A pair is decided again only when the motion bound
// accumulated since its last decision comes within `spacing` of its last proven gap (until
// then the pair is proven apart, and one more step of `spacing` keeps it so); a step is taken only if, for every pair, that accumulated bound stays at most
// max(spacing, gap): between two decisions a pair's hulls move at most `spacing` unless its
// gap proves the motion clear. Contact is claimed only by decide()'s exact LP.
UrdfOraclePath UrdfCellOracle::sample_path(const PathProgram& program, motion::PtpTiming timing,
                                           double spacing) const {
  const RobotModel& robot = cell_->robot;
  const long long exact_before = exact_checks_;
  UrdfOraclePath result;
  Eigen::VectorXd q(robot.joint_count());
  for (int j = 0; j < robot.joint_count(); ++j) q[j] = robot.joints[static_cast<std::size_t>(j)].home;
  std::vector<PairState> pairs = pair_states();
  auto step_ok = [&](const Eigen::VectorXd& dq) {
    const Eigen::VectorXd motion = dq.cwiseAbs();
    for (const PairState& pair : pairs) {
      if (pair.moved + pair.reach.dot(motion) > std::max(spacing, pair.gap)) return false;
    }
    return true;
  };
  auto visit = [&](const Eigen::VectorXd& at, const Eigen::VectorXd& dq, int segment) {
    ++result.samples;
    const auto poses = link_poses(at);
    std::map<std::pair<int, int>, Shape> shapes;
    auto shape = [&](int link, int hull) -> const Shape& {
      auto found = shapes.find({link, hull});
      if (found == shapes.end()) found = shapes.emplace(std::make_pair(link, hull), placed_shape(poses, link, hull)).first;
      return found->second;
    };
    const Eigen::VectorXd motion = dq.cwiseAbs();
    for (PairState& pair : pairs) {
      pair.moved += pair.reach.dot(motion);
      // Still proven apart (moved < gap), and the next step may move it by spacing: skip.
      if (pair.gap >= 0.0 && (pair.moved == 0.0 || pair.moved + spacing <= pair.gap)) continue;
      ++result.decisions;
      const Shape& other = pair.self ? shape(pair.other_link, pair.other_hull) : obstacles_[static_cast<std::size_t>(pair.obstacle)];
      const bool contact = decide(shape(pair.link, pair.hull), other, pair.gap, &pair.direction);
      pair.moved = 0.0;
      double& smallest = pair.self ? result.min_self_distance : result.min_obstacle_distance;
      if (pair.gap < smallest) {
        smallest = pair.gap;
        if (pair.self) {
          const int nearest[4] = {pair.link, pair.hull, pair.other_link, pair.other_hull};
          std::copy(nearest, nearest + 4, result.nearest_self);
        }
      }
      if (!contact) continue;
      UrdfOracleContact& found = result.first_contact;
      found.contact = true;
      found.self = pair.self;
      found.link = pair.link;
      found.hull = pair.hull;
      found.other_link = pair.other_link;
      found.other_hull = pair.other_hull;
      found.obstacle = pair.obstacle;
      result.contact_segment = segment;
      result.contact_q = at;
      return true;
    }
    return false;
  };
  bool done = visit(q, Eigen::VectorXd::Zero(q.size()), 0);
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
      done = visit(q1, q1 - q_t, s + 1);
      q_t = q1;
    }
    q = ptp->target;
  }
  result.exact_checks = exact_checks_ - exact_before;
  return result;
}

}  // namespace grpvss::test

#include "support/oracle_cases.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "grpvss/motion/ptp_motion.hpp"
#include "support/kinematics_reference.hpp"
#include "support/random_shapes.hpp"  // random_rotation

namespace grpvss::test {
namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

int uniform_int(std::mt19937_64& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

Eigen::Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector3d v(normal(rng), normal(rng), normal(rng));
  return v.normalized();
}

// A box with half extents h and orientation `rotation`, centred at c (8 points: cheap exact
// offsets in the verifier).
std::vector<Eigen::Vector3d> oracle_box(const Eigen::Vector3d& c, const Eigen::Vector3d& h,
                                 const Eigen::Matrix3d& rotation) {
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d p_L((k & 1 ? 1 : -1) * h.x(), (k & 2 ? 1 : -1) * h.y(),
                              (k & 4 ? 1 : -1) * h.z());
    points.push_back(c + rotation * p_L);
  }
  return points;
}

std::vector<Eigen::Vector3d> random_box(std::mt19937_64& rng, const Eigen::Vector3d& c,
                                        const Eigen::Vector3d& h) {
  return oracle_box(c, h, random_rotation(rng));
}

// A box from behind the frame origin along a random direction to length `length` (a tool
// sticking out far beyond the link skeleton), cross-section half-width w.
std::vector<Eigen::Vector3d> random_tool(std::mt19937_64& rng, double length, double w) {
  const Eigen::Matrix3d rotation = random_rotation(rng);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d p_L(k & 1 ? length : -w, (k & 2 ? 1 : -1) * w, (k & 4 ? 1 : -1) * w);
    points.push_back(rotation * p_L);
  }
  return points;
}

// Tiny (0.02) to large (2), log-uniform.
double random_tolerance(std::mt19937_64& rng) {
  return std::exp(uniform(rng, std::log(0.02), std::log(2.0)));
}

Eigen::Vector3d point_W(const RobotModel& robot, const Eigen::VectorXd& q, int link,
                        const Eigen::Vector3d& p_L) {
  const Eigen::Matrix4d X_WL = reference_link_pose<double>(robot, q, link);
  return X_WL.topLeftCorner<3, 3>() * p_L + X_WL.topRightCorner<3, 1>();
}

// Obstacles: 1-3 boxes or thin plates next to the sweep. Mostly (80%) "support" placement: a
// random direction u, the sweep's farthest hull vertex p along u over the configurations
// `visited` (an approximation of the swept volume), and a face (normal -u) centred at
// p + gap u: the sweep stays about `gap` away from the obstacle (or cuts `-gap` into it).
// Otherwise "local" placement: the same face at a random hull vertex of a random visited
// configuration, which the rest of the sweep usually hits. Gap in [-1, 3] Delta (a third of
// them in [0, 1.5] Delta: within the tolerance). Then 0-2 boxes far outside the reach.
void add_obstacles(std::mt19937_64& rng, const std::vector<Eigen::VectorXd>& visited, OracleCase& c) {
  const RobotModel& robot = c.robot;
  std::vector<Eigen::Vector3d> swept_W;
  for (const Eigen::VectorXd& q : visited) {
    for (int link = 0; link <= robot.joint_count(); ++link) {
      for (const HullPoints& hull : robot.links[link].hulls) {
        for (const auto& p_L : hull.points) swept_W.push_back(point_W(robot, q, link, p_L));
      }
    }
  }
  const int near = uniform_int(rng, 1, 3);
  const int far = uniform_int(rng, 0, 2);
  double smallest_thickness = 10.0;
  for (int k = 0; k < near; ++k) {
    const Eigen::Vector3d u = random_unit(rng);
    Eigen::Vector3d p_W;
    if (uniform(rng, 0, 1) < 0.8) {
      p_W = *std::max_element(swept_W.begin(), swept_W.end(),
                              [&](const Eigen::Vector3d& x, const Eigen::Vector3d& y) { return u.dot(x) < u.dot(y); });
    } else {
      p_W = swept_W[std::uniform_int_distribution<std::size_t>(0, swept_W.size() - 1)(rng)];
    }
    const double gap = (uniform(rng, 0, 1) < 0.33 ? uniform(rng, 0.0, 1.5) : uniform(rng, -1.0, 3.0)) * c.tolerance;
    // Local z = u; the face z = -half.z faces the vertex.
    Eigen::Matrix3d rotation;
    const Eigen::Vector3d x = u.unitOrthogonal();
    rotation.col(0) = x;
    rotation.col(1) = u.cross(x);
    rotation.col(2) = u;
    const double spin = uniform(rng, 0.0, 2.0 * M_PI);
    rotation = rotation * Eigen::AngleAxisd(spin, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    Eigen::Vector3d half;
    if (uniform(rng, 0, 1) < 0.4) {
      // A thin plate (what the thesis rule's steps can jump over).
      const double thickness = uniform(rng, 0.05, 0.3);
      half = Eigen::Vector3d(uniform(rng, 1.0, 4.0), uniform(rng, 1.0, 4.0), 0.5 * thickness);
    } else {
      half = Eigen::Vector3d(uniform(rng, 0.3, 2.0), uniform(rng, 0.3, 2.0), uniform(rng, 0.3, 2.0));
    }
    smallest_thickness = std::min(smallest_thickness, 2.0 * half.minCoeff());
    c.environment.obstacles.push_back({oracle_box(p_W + u * (gap + half.z()), half, rotation), 0});
  }
  double reach = 10.0;
  for (const Joint& joint : robot.joints) reach += std::abs(joint.dh.a) + std::abs(joint.dh.d) + std::abs(joint.maximum);
  reach += 10.0;  // tools and bodies: at most 8.5 beyond their frame
  for (int k = 0; k < far; ++k) {
    const Eigen::Vector3d half(uniform(rng, 1.0, 4.0), uniform(rng, 1.0, 4.0), uniform(rng, 1.0, 4.0));
    c.environment.obstacles.push_back(
        {random_box(rng, random_unit(rng) * (reach + half.norm() + uniform(rng, 1.0, 20.0)), half), 0});
    smallest_thickness = std::min(smallest_thickness, 2.0 * half.minCoeff());
  }
  c.environment.smallest_angle = M_PI / 2.0;
  c.environment.smallest_thickness = smallest_thickness;
}

// Hulls of link `link` (frame at the distal end of a link of length a): a body box along the
// link and, with probability 0.6, a tool.
void add_link_hulls(std::mt19937_64& rng, RobotModel& robot, int link, double a) {
  robot.links[link].thickness = 1.0;
  const Eigen::Vector3d body_center(-0.5 * a, 0.0, 0.0);
  const Eigen::Vector3d body_half(0.5 * a + uniform(rng, 0.2, 0.6), uniform(rng, 0.2, 0.6), uniform(rng, 0.2, 0.6));
  robot.links[link].hulls.push_back({random_box(rng, body_center, body_half), 0});
  if (uniform(rng, 0, 1) < 0.6) {
    robot.links[link].hulls.push_back({random_tool(rng, uniform(rng, 3.0, 8.0), uniform(rng, 0.1, 0.5)), 0});
  }
}

Eigen::VectorXd random_joint_move(std::mt19937_64& rng, const RobotModel& robot, const Eigen::VectorXd& from,
                                  double fraction) {
  Eigen::VectorXd target(robot.joint_count());
  for (int j = 0; j < robot.joint_count(); ++j) {
    const Joint& joint = robot.joints[j];
    const double span = joint.maximum - joint.minimum;
    target[j] = std::clamp(from[j] + uniform(rng, -fraction, fraction) * span, joint.minimum, joint.maximum);
  }
  return target;
}

PtpJointSegment random_ptp(std::mt19937_64& rng, const RobotModel& robot, const Eigen::VectorXd& target) {
  PtpJointSegment segment;
  segment.target = target;
  segment.velocity.resize(robot.joint_count());
  for (int j = 0; j < robot.joint_count(); ++j) {
    segment.velocity[j] =
        robot.joints[j].type == JointType::kRevolute ? uniform(rng, 0.3, 1.5) : uniform(rng, 0.5, 2.0);
  }
  return segment;
}

// Configurations along a joint-linear move from q0 to q1 (a CP line's neighbourhood).
void add_visited(std::vector<Eigen::VectorXd>& visited, const Eigen::VectorXd& q0, const Eigen::VectorXd& q1) {
  for (int k = 1; k <= 16; ++k) visited.push_back(q0 + (k / 16.0) * (q1 - q0));
}

// Configurations along the PTP motion (independent timing, as the verifier plans it).
void add_visited(std::vector<Eigen::VectorXd>& visited, const RobotModel& robot, const Eigen::VectorXd& q0,
                 const PtpJointSegment& segment) {
  const motion::PtpMotion motion =
      motion::PtpMotion::plan(robot, q0, segment.target, segment.velocity, motion::PtpTiming::kIndependent);
  for (int k = 1; k <= 16; ++k) visited.push_back(motion.joints_at(motion.duration() * k / 16.0));
}

}  // namespace

OracleCase random_ptp_case(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  OracleCase c;
  RobotModel& robot = c.robot;
  robot.name = "random";
  const int joints = uniform_int(rng, 2, 5);
  const double alphas[] = {0.0, M_PI / 2, -M_PI / 2, uniform(rng, -M_PI, M_PI)};
  for (int j = 0; j < joints; ++j) {
    Joint joint;
    joint.type = (j > 0 && uniform(rng, 0, 1) < 0.3) ? JointType::kPrismatic : JointType::kRevolute;
    joint.dh.a = uniform(rng, 0.0, 4.0);
    joint.dh.d = uniform(rng, 0.0, 3.0);
    joint.dh.alpha = alphas[uniform_int(rng, 0, 3)];
    if (joint.type == JointType::kRevolute) {
      joint.minimum = -uniform(rng, 1.0, M_PI);
      joint.maximum = uniform(rng, 1.0, M_PI);
      joint.acceleration = uniform(rng, 1.0, 4.0);
      joint.deceleration = uniform(rng, 1.0, 4.0);
    } else {
      joint.minimum = 0.0;
      joint.maximum = uniform(rng, 1.0, 4.0);
      joint.acceleration = uniform(rng, 2.0, 6.0);
      joint.deceleration = uniform(rng, 2.0, 6.0);
    }
    joint.home = uniform(rng, joint.minimum, joint.maximum);
    robot.joints.push_back(joint);
  }
  robot.links.resize(joints + 1);
  for (int link = 1; link <= joints; ++link) add_link_hulls(rng, robot, link, robot.joints[link - 1].dh.a);
  if (uniform(rng, 0, 1) < 0.5) {
    robot.links[0].hulls.push_back({random_box(rng, Eigen::Vector3d(0, 0, -1.5), Eigen::Vector3d(1.0, 1.0, 0.5)), 0});
  }
  c.tolerance = random_tolerance(rng);
  // Small tolerances get shorter moves (the oracle samples at Delta/20, and after a collision
  // the verifier goes on at 2 Delta per step: the cost grows like path length / Delta).
  const double fraction = c.tolerance < 0.1 ? 0.05 : (c.tolerance < 0.3 ? 0.15 : 0.3);
  const int segments = uniform_int(rng, 1, 2);
  Eigen::VectorXd q(joints);
  for (int j = 0; j < joints; ++j) q[j] = robot.joints[j].home;
  std::vector<Eigen::VectorXd> visited{q};
  for (int s = 0; s < segments; ++s) {
    const Eigen::VectorXd target = random_joint_move(rng, robot, q, fraction);
    const PtpJointSegment segment = random_ptp(rng, robot, target);
    add_visited(visited, robot, q, segment);
    c.program.segments.push_back({segment, s + 2});
    q = target;
  }
  add_obstacles(rng, visited, c);
  return c;
}

OracleCase random_scara_cp_case(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  OracleCase c;
  c.ik = {kinematics::IkMethod::kIbm7545, {}};
  RobotModel& robot = c.robot;
  robot.name = "random SCARA";
  auto revolute = [&](double alpha, double a, double d, double lo, double hi) {
    Joint joint;
    joint.type = JointType::kRevolute;
    joint.dh.alpha = alpha;
    joint.dh.a = a;
    joint.dh.d = d;
    joint.minimum = lo;
    joint.maximum = hi;
    joint.acceleration = uniform(rng, 1.0, 3.0);
    joint.deceleration = uniform(rng, 1.0, 3.0);
    return joint;
  };
  const double deg = M_PI / 180.0;
  robot.joints.push_back(revolute(0.0, uniform(rng, 8.0, 20.0), uniform(rng, 10.0, 30.0),
                                  -uniform(rng, 90.0, 170.0) * deg, uniform(rng, 90.0, 170.0) * deg));
  // Elbow on one side only (0 < theta2 < 150 deg): the closed-form IK stays on its branch.
  robot.joints.push_back(revolute(M_PI, uniform(rng, 5.0, 14.0), 0.0, uniform(rng, 5.0, 20.0) * deg,
                                  uniform(rng, 120.0, 150.0) * deg));
  Joint slide;
  slide.type = JointType::kPrismatic;
  slide.minimum = 0.0;
  slide.maximum = uniform(rng, 4.0, 12.0);
  slide.acceleration = uniform(rng, 0.5, 2.0);
  slide.deceleration = uniform(rng, 0.5, 2.0);
  robot.joints.push_back(slide);
  robot.joints.push_back(revolute(0.0, 0.0, uniform(rng, 5.0, 18.0), -M_PI, M_PI));
  for (Joint& joint : robot.joints) joint.home = 0.5 * (joint.minimum + joint.maximum) + uniform(rng, -0.2, 0.2) * (joint.maximum - joint.minimum);
  robot.links.resize(5);
  for (int link = 1; link <= 4; ++link) add_link_hulls(rng, robot, link, robot.joints[link - 1].dh.a);
  // The base column under joint 1.
  robot.links[0].hulls.push_back({oracle_box(Eigen::Vector3d(0, 0, 0.5 * robot.joints[0].dh.d - 1.0),
                                      Eigen::Vector3d(2.0, 2.0, 0.5 * robot.joints[0].dh.d - 1.0),
                                      Eigen::Matrix3d::Identity()), 0});
  c.tolerance = random_tolerance(rng);
  const double fraction = c.tolerance < 0.1 ? 0.04 : (c.tolerance < 0.3 ? 0.12 : 0.2);
  const int segments = uniform_int(rng, 1, 3);
  Eigen::VectorXd q(4);
  for (int j = 0; j < 4; ++j) q[j] = robot.joints[j].home;
  std::vector<Eigen::VectorXd> visited{q};
  const int n = robot.joint_count();
  for (int s = 0; s < segments; ++s) {
    // One move in ten is long (half the joint ranges): its line may leave the workspace, wrap
    // joint 4 or pass the elbow singularity (errors 5, 7, 8: never CLEAR).
    const bool long_move = uniform(rng, 0, 1) < 0.1;
    const Eigen::VectorXd target = random_joint_move(rng, robot, q, long_move ? 0.5 : fraction);
    // At least one CP line; otherwise CP with probability 0.7.
    if (s == 0 || uniform(rng, 0, 1) < 0.7) {
      add_visited(visited, q, target);  // the line's neighbourhood, roughly
      const Eigen::Matrix4d X_s = reference_link_pose<double>(robot, q, n);
      const Eigen::Matrix4d X_f = reference_link_pose<double>(robot, target, n);
      const Eigen::AngleAxisd change(Eigen::Matrix3d(X_f.topLeftCorner<3, 3>() * X_s.topLeftCorner<3, 3>().transpose()));
      CpLineSegment cp;
      cp.target.position_W = X_f.topRightCorner<3, 1>();
      cp.target.axis_W = change.axis();
      cp.target.angle = change.angle();
      c.program.segments.push_back({cp, s + 2});
    } else {
      const PtpJointSegment segment = random_ptp(rng, robot, target);
      add_visited(visited, robot, q, segment);
      c.program.segments.push_back({segment, s + 2});
    }
    q = target;
  }
  add_obstacles(rng, visited, c);
  return c;
}

}  // namespace grpvss::test

#include "bench/robots/bench_cells.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <unistd.h>

#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"

namespace grpvss::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;
const std::string kSource = GRPVSS_SOURCE_DIR;

struct RobotEntry {
  const char* name;
  std::string robot_yaml;  ///< the cell's `robot:` mapping, absolute paths
  double reach_m;          ///< radius of the region the inner obstacles are placed in
  std::string tail_yaml;   ///< appended after the obstacles (the robot's allowed self-contacts)
};

RobotEntry robot_entry(BenchRobot robot) {
  const std::string shared = kSource + "/../shared/robots/";
  switch (robot) {
    case BenchRobot::kUr5e:
      return {"ur5e",
              fmt::format("  urdf: {0}ur5e/ur5e.urdf\n  package_paths: [{0}ur5e]\n  tip: tool0\n"
                          "  home: [0, -1.5708, 1.5708, 0, 0, 0]\n",
                          shared),
              0.85, ""};
    case BenchRobot::kPanda:
      return {"panda",
              fmt::format("  urdf: {0}franka_panda/panda_arm_only.urdf\n"
                          "  package_paths: [{0}franka_panda]\n  tip: panda_link8\n"
                          "  home: [0, -0.785, 0, -2.356, 0, 1.571, 0.785]\n",
                          shared),
              0.85,
              // The Franka's self-collision capsules (`_sc`) of links two apart overlap in
              // every configuration (its SRDF disables them; tests/data/cells/panda-self.yaml).
              "allowed_contacts:\n  - [panda_link1, panda_link3_sc]\n"
              "  - [panda_link1_sc, panda_link3_sc]\n  - [panda_link3, panda_link5_sc]\n"
              "  - [panda_link5, panda_link7_sc]\n"};
    case BenchRobot::kSixAxis:
      return {"sixaxis",
              fmt::format("  urdf: {}/data/sixaxis/sixaxis.urdf\n  home: [0, 0, 0, 0, 0, 0]\n"
                          "  acceleration: {{default: 4.0}}\n",
                          kSource),
              0.75,
              // The forearm starts inside the upper arm's hull (data/sixaxis/cell.yaml).
              "allowed_contacts:\n  - [link_2, link_4]\n"};
  }
  throw std::logic_error("bench: unknown robot");
}

std::string write_temporary(const std::string& text, const std::string& stem) {
  const auto file = std::filesystem::temp_directory_path() /
                    fmt::format("grpvss-bench-{}-{}.yaml", stem, ::getpid());
  std::ofstream(file) << text;
  return file.string();
}

// Every hull vertex of the robot at home, world frame: obstacles keep 8 cm away from them.
std::vector<Eigen::Vector3d> home_points(const RobotEntry& entry) {
  const std::string file = write_temporary("units: m\nrobot:\n" + entry.robot_yaml, "robot");
  const cell::LoadedCell loaded = cell::load_cell(file);
  std::filesystem::remove(file);
  const kinematics::KinematicChain chain = kinematics::make_chain(loaded.robot);
  kinematics::Workspace workspace(loaded.robot);
  kinematics::forward_kinematics(chain, chain.home(), workspace);
  kinematics::place_hull_points(loaded.robot, workspace);
  std::vector<Eigen::Vector3d> points;
  for (const auto& link : workspace.hull_points_W) {
    for (const auto& hull : link) points.insert(points.end(), hull.begin(), hull.end());
  }
  return points;
}

double distance_to(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& p) {
  double best = INFINITY;
  for (const auto& q : points) best = std::min(best, (q - p).squaredNorm());
  return std::sqrt(best);
}

// One obstacle's YAML entry; `bound` is a radius around its centre that contains it.
std::string obstacle_yaml(int index, bool thin, std::mt19937& rng, double& bound) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int kind = index % 3;
  if (thin) {  // a 2 mm plate or a 3 mm rod: what sampling steps over
    bound = 0.21;
    if (kind == 0) return "box: [0.3, 0.2, 0.002]";
    return "cylinder: {radius: 0.0015, length: 0.4}";
  }
  if (kind == 0) {
    const double x = 0.03 + 0.09 * unit(rng), y = 0.03 + 0.09 * unit(rng),
                 z = 0.03 + 0.09 * unit(rng);
    bound = 0.5 * std::sqrt(x * x + y * y + z * z);
    return fmt::format("box: [{:.4f}, {:.4f}, {:.4f}]", x, y, z);
  }
  if (kind == 1) {
    const double radius = 0.01 + 0.04 * unit(rng), length = 0.05 + 0.25 * unit(rng);
    bound = std::hypot(radius, 0.5 * length);
    return fmt::format("cylinder: {{radius: {:.4f}, length: {:.4f}}}", radius, length);
  }
  bound = 0.17;
  return fmt::format("mesh: {}/tests/data/bench/gate.stl, decompose: parts", kSource);
}

// A centre in the cylinder shell r in [r0, r1] about the base's z axis, z in [0, height].
Eigen::Vector3d shell_point(std::mt19937& rng, double r0, double r1, double height) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r = r0 + (r1 - r0) * unit(rng), angle = 2 * kPi * unit(rng);
  return {r * std::cos(angle), r * std::sin(angle), height * unit(rng)};
}

}  // namespace

const char* robot_name(BenchRobot robot) { return robot_entry(robot).name; }

BenchRobot robot_from_name(const std::string& name) {
  for (BenchRobot robot : {BenchRobot::kUr5e, BenchRobot::kPanda, BenchRobot::kSixAxis}) {
    if (name == robot_name(robot)) return robot;
  }
  throw std::invalid_argument("unknown robot '" + name + "' (ur5e, panda, sixaxis)");
}

// Most obstacles of a large cell stand beyond the robot's reach (bins, fixtures, a
// neighbouring cell); 6 + n/20 stand within it, every fourth of those thin.
std::string bench_cell_yaml(BenchRobot robot, int obstacles, double tolerance_m,
                            int thin_every) {
  const RobotEntry entry = robot_entry(robot);
  const std::vector<Eigen::Vector3d> home = home_points(entry);
  std::mt19937 rng(1000u * static_cast<unsigned>(robot) + static_cast<unsigned>(obstacles));
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  const int inner = std::min(obstacles, 6 + obstacles / 20);
  std::string yaml = fmt::format("# generated by tests/bench/robots/bench_cells.cpp\nunits: m\n"
                                 "robot:\n{}obstacles:\n", entry.robot_yaml);
  for (int i = 0; i < obstacles; ++i) {
    const bool near = i < inner;
    double bound = 0.0;
    const std::string shape = obstacle_yaml(i, near && i % thin_every == thin_every - 1, rng, bound);
    Eigen::Vector3d centre;
    do {
      centre = near ? shell_point(rng, 0.25 * entry.reach_m, entry.reach_m, 1.1 * entry.reach_m)
                    : shell_point(rng, 1.15 * entry.reach_m, 3.0 * entry.reach_m,
                                  1.5 * entry.reach_m);
    } while (distance_to(home, centre) < bound + 0.08);
    const double roll = angle(rng), pitch = angle(rng), yaw = angle(rng);
    yaml += fmt::format("  - {{name: o{}, {}, pose: {{xyz: [{:.4f}, {:.4f}, {:.4f}], rpy: "
                        "[{:.4f}, {:.4f}, {:.4f}]}}}}\n",
                        i, shape, centre.x(), centre.y(), centre.z(), roll,
                        pitch, yaw);
  }
  yaml += entry.tail_yaml;
  yaml += fmt::format("tolerance: {}\n", tolerance_m);
  return yaml;
}

std::unique_ptr<BenchCell> make_bench_cell(BenchRobot robot, int obstacles, double tolerance_m,
                                           int thin_every) {
  auto bench = std::make_unique<BenchCell>();
  const std::string file = write_temporary(
      bench_cell_yaml(robot, obstacles, tolerance_m, thin_every), robot_name(robot));
  bench->loaded = cell::load_cell(file);
  std::filesystem::remove(file);
  certify::SetupRequest request;
  request.tolerance = bench->loaded.tolerance;
  bench->setup = certify::resolve_setup(request);
  bench->kinematics = motion::make_kinematics_access(
      bench->loaded.robot, motion::select_ik({}, bench->loaded.robot, "bench.yaml"));
  bench->cell = std::make_unique<certify::RobotCell>(bench->loaded.robot,
                                                     bench->loaded.environment, bench->setup.cell);
  return bench;
}

namespace {

constexpr double kSpeed = 60.0 * kPi / 180.0;  // every joint's desired speed, rad/s

Eigen::VectorXd random_step(const RobotModel& robot, const Eigen::VectorXd& from,
                            double max_step, std::mt19937& rng) {
  std::uniform_real_distribution<double> step(-max_step, max_step);
  Eigen::VectorXd to = from;
  for (int j = 0; j < to.size(); ++j) {
    const Joint& joint = robot.joints[j];
    to[j] = std::clamp(from[j] + step(rng), joint.minimum + 0.05, joint.maximum - 0.05);
  }
  return to;
}

PathSegment ptp_to(const Eigen::VectorXd& target) {
  PathSegment segment;
  segment.spec = PtpJointSegment{target, Eigen::VectorXd::Constant(target.size(), kSpeed)};
  return segment;
}

Eigen::VectorXd home_of(const RobotModel& robot) {
  Eigen::VectorXd q(robot.joint_count());
  for (int j = 0; j < q.size(); ++j) q[j] = robot.joints[j].home;
  return q;
}

void set_home(RobotModel& robot, const Eigen::VectorXd& q) {
  for (int j = 0; j < q.size(); ++j) robot.joints[j].home = q[j];
}

}  // namespace

// The verifier plans from the robot's home, so each candidate segment is verified alone with
// the home moved to the previous waypoint (the RobotCell does not depend on the home).
PathProgram clear_program(BenchCell& bench, int waypoints, std::uint32_t seed) {
  RobotModel& robot = bench.loaded.robot;
  const Eigen::VectorXd home = home_of(robot);
  std::mt19937 rng(seed);
  PathProgram program;
  Eigen::VectorXd at = home;
  for (int k = 0; k < waypoints; ++k) {
    double max_step = 40.0 * kPi / 180.0;
    for (int attempt = 0;; ++attempt) {
      if (attempt == 400) throw std::runtime_error("bench: no clear segment found");
      if (attempt % 50 == 49) max_step *= 0.5;
      PathProgram single;
      single.segments.push_back(ptp_to(random_step(robot, at, max_step, rng)));
      set_home(robot, at);
      const auto run = certify::verify(*bench.cell, single, bench.kinematics, bench.setup.run);
      if (run.result.verdict != certify::Verdict::kClear || !run.result.errors.empty()) continue;
      at = std::get<PtpJointSegment>(single.segments[0].spec).target;
      program.segments.push_back(single.segments[0]);
      break;
    }
  }
  set_home(robot, home);
  return program;
}

PathProgram random_program(const BenchCell& bench, int waypoints, double max_step_deg,
                           std::uint32_t seed) {
  std::mt19937 rng(seed);
  PathProgram program;
  Eigen::VectorXd at = home_of(bench.loaded.robot);
  for (int k = 0; k < waypoints; ++k) {
    at = random_step(bench.loaded.robot, at, max_step_deg * kPi / 180.0, rng);
    program.segments.push_back(ptp_to(at));
  }
  return program;
}

std::string path_file_text(const PathProgram& program) {
  std::string text = fmt::format("{}\n", program.segments.size());
  for (const PathSegment& segment : program.segments) {
    const auto& ptp = std::get<PtpJointSegment>(segment.spec);
    text += "1\n";
    for (int j = 0; j < ptp.target.size(); ++j) {
      text += fmt::format("{:.17g},{:.17g}\n", ptp.target[j] * 180.0 / kPi,
                          ptp.velocity[j] * 180.0 / kPi);
    }
  }
  return text;
}

certify::VerificationRun verify_program(const BenchCell& bench, const PathProgram& program) {
  return certify::verify(*bench.cell, program, bench.kinematics, bench.setup.run);
}

}  // namespace grpvss::bench

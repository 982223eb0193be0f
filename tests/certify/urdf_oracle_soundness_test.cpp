// Soundness of the certified verifier in cells with URDF robots (issue 19, point 9), against
// the independent oracle of tests/support/urdf_cell_oracle.hpp: the UR5e and the Panda of
// ../shared/robots with their mesh collision hulls (the Panda's `_sc` capsules as
// circumscribing polytopes), random obstacles of the cell kinds (box, cylinder, mesh) placed at
// the sweep with gaps of -1..3 tolerances, the self-collision pairs the cell stage keeps, and
// random synchronized-PTP paths (the cells' default timing). Property on every case: certified
// mode never says CLEAR where the oracle finds contact (obstacle or self), a COLLISION's step
// really collides, and every certificate is accepted by check_certificate. Each shard must
// produce contact and clear cases. Counts: docs/soundness-oracle.md#urdf-cells.
// The suite runs kCiCasesPerShard cases per shard (shards other than Ur5eShard0 are labelled
// `heavy`: Release only); GRPVSS_LONG_URDF_ORACLE=1 runs kLongCasesPerShard (320 cases in all),
// GRPVSS_URDF_ORACLE_CASES_PER_SHARD=<n> sets the cases; GRPVSS_ORACLE_VERBOSE=1 prints each.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <string>

#include <Eigen/Geometry>
#include <fmt/core.h>
#include <gtest/gtest.h>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/ptp_motion.hpp"
#include "support/text_files.hpp"
#include "support/urdf_cell_oracle.hpp"

namespace grpvss::certify {
namespace {
// Named: the thesis-format oracle (oracle_soundness_test.cpp) has helpers of the same names,
// and a unity batch may bring the two files together.
namespace urdf_oracle {

const std::string kRobots = std::string(GRPVSS_SOURCE_DIR) + "/../shared/robots/";
const std::string kBracket = std::string(GRPVSS_SOURCE_DIR) + "/tests/data/cells/l-bracket.stl";
constexpr int kShards = 4;  // per robot
#ifdef __SANITIZE_ADDRESS__
// Under the sanitizers (~10x slower) only Ur5eShard0 runs (the others are `heavy`), fewer cases.
constexpr int kCiCasesPerShard = 2;
#else
constexpr int kCiCasesPerShard = 3;  // 2 robots x 4 shards x 3 = 24 cases
#endif
constexpr int kLongCasesPerShard = 40;  // 320 cases
constexpr double kSpacingFraction = 1.0 / 20.0;  // oracle spacing, of the tolerance

enum class Robot { kUr5e, kPanda };

std::string robot_yaml(Robot robot) {
  if (robot == Robot::kUr5e) {
    return "robot:\n  urdf: " + kRobots + "ur5e/ur5e.urdf\n  package_paths: [" + kRobots +
           "ur5e]\n  tip: tool0\n  base: {xyz: [0, 0, 0.8], rpy: [0, 0, 0.25]}\n"
           "  home: [0, -1.5708, 1.5708, 0, 0, 0]\n";
  }
  return "robot:\n  urdf: " + kRobots + "franka_panda/panda.urdf\n  package_paths: [" + kRobots +
         "franka_panda]\n  tip: panda_hand_tcp\n  base: {xyz: [0, 0, 0.8]}\n"
         "  home: [0, -0.785, 0, -2.356, 0, 1.571, 0.785]\n";
}

// The Panda's `_sc` capsules overlap the link two further on at every configuration (MoveIt's
// SRDF disables these pairs too; tests/data/cells/panda-shelf.yaml).
std::string allowed_yaml(Robot robot) {
  if (robot == Robot::kUr5e) return "";
  return "allowed_contacts:\n  - [panda_link1, panda_link3_sc]\n  - [panda_link1_sc, panda_link3_sc]\n"
         "  - [panda_link3, panda_link5_sc]\n  - [panda_link5, panda_link7_sc]\n";
}

std::string temporary_directory() {
  static const std::string directory = test::make_temporary_directory("urdf-oracle");
  return directory;
}

cell::LoadedCell load_cell_text(const std::string& name, const std::string& text) {
  const std::string file = temporary_directory() + "/" + name;
  std::ofstream(file) << text;
  return cell::load_cell(file);
}

// The robot alone (self pairs only), and its oracle: obstacles are placed with it.
struct FreeRobot {
  cell::LoadedCell cell;
  std::unique_ptr<test::UrdfCellOracle> oracle;
};
const FreeRobot& free_robot(Robot robot) {
  static std::map<Robot, std::unique_ptr<FreeRobot>> cache;
  auto& entry = cache[robot];
  if (!entry) {
    entry = std::make_unique<FreeRobot>();
    entry->cell = load_cell_text(robot == Robot::kUr5e ? "free-ur5e.yaml" : "free-panda.yaml",
                       "units: m\n" + robot_yaml(robot) + allowed_yaml(robot) + "tolerance: 0.005\n");
    entry->oracle = std::make_unique<test::UrdfCellOracle>(entry->cell);
  }
  return *entry;
}

struct UrdfCase {
  double tolerance = 0.0;
  std::string path_text;
  std::string cell_text;
};

std::string pose_yaml(const Eigen::Vector3d& xyz, const Eigen::Quaterniond& rotation) {
  return fmt::format("{{xyz: [{:.17g}, {:.17g}, {:.17g}], quaternion: {{w: {:.17g}, x: {:.17g}, y: {:.17g}, z: {:.17g}}}}}",
                     xyz.x(), xyz.y(), xyz.z(), rotation.w(), rotation.x(), rotation.y(), rotation.z());
}

// An obstacle whose face towards the robot lies `gap` beyond the sweep's farthest hull point
// along u (its lowest point along u at `lowest` + gap u).
std::string obstacle_yaml(int index, const Eigen::Vector3d& lowest, const Eigen::Vector3d& u, double gap,
                          std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int kind = static_cast<int>(unit(rng) * 3.0);
  const std::string name = fmt::format("  - {{name: o{}, ", index);
  if (kind == 0) {  // a box, its -z face at the gap
    const double depth = 0.02 + 0.2 * unit(rng);
    const Eigen::Quaterniond R = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), u);
    return name + fmt::format("box: [{:.6f}, {:.6f}, {:.6f}], pose: ", 0.05 + 0.3 * unit(rng), 0.05 + 0.3 * unit(rng), depth) +
           pose_yaml(lowest + (gap + depth / 2) * u, R) + "}\n";
  }
  if (kind == 1) {  // a cylinder, its axis across u
    const double radius = 0.02 + 0.08 * unit(rng);
    Eigen::Vector3d across = u.cross(Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
    across.normalize();
    const Eigen::Quaterniond R = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), across);
    return name + fmt::format("cylinder: {{radius: {:.6f}, length: {:.6f}}}, pose: ", radius, 0.1 + 0.5 * unit(rng)) +
           pose_yaml(lowest + (gap + radius) * u, R) + "}\n";
  }
  // The L-bracket (mm, corner at its origin, every vertex >= 0): (1,1,1) along u puts its
  // origin corner lowest along u.
  const Eigen::Quaterniond R = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d(1, 1, 1).normalized(), u);
  return name + "mesh: " + kBracket + ", units: mm, decompose: " + (unit(rng) < 0.5 ? "parts" : "hull") +
         ", pose: " + pose_yaml(lowest + gap * u, R) + "}\n";
}

UrdfCase random_case(Robot robot, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const FreeRobot& free = free_robot(robot);
  const RobotModel& model = free.cell.robot;
  UrdfCase c;
  c.tolerance = 0.002 * std::pow(10.0, unit(rng));  // 2-20 mm
  const int segments = unit(rng) < 0.6 ? 1 : 2;
  const double amplitude = unit(rng) < 0.25 ? 1.5 : 0.6;  // rad; large moves fold the arm
  Eigen::VectorXd q(model.joint_count());
  for (int j = 0; j < q.size(); ++j) q[j] = model.joints[static_cast<std::size_t>(j)].home;
  c.path_text = fmt::format("{}\n", segments);
  std::vector<Eigen::VectorXd> sweep;
  for (int s = 0; s < segments; ++s) {
    Eigen::VectorXd target = q, velocity(q.size());
    c.path_text += "1\n";
    for (int j = 0; j < q.size(); ++j) {
      const Joint& joint = model.joints[static_cast<std::size_t>(j)];
      target[j] = std::clamp(q[j] + amplitude * (2 * unit(rng) - 1), joint.minimum + 0.01, joint.maximum - 0.01);
      velocity[j] = (20.0 + 40.0 * unit(rng)) * M_PI / 180.0;
      c.path_text += fmt::format("{:.6f},{:.3f}\n", target[j] * 180.0 / M_PI, velocity[j] * 180.0 / M_PI);
    }
    // The path file rounds: plan the sweep from what it says.
    for (int j = 0; j < q.size(); ++j) target[j] = std::round(target[j] * 180.0 / M_PI * 1e6) / 1e6 * M_PI / 180.0;
    const motion::PtpMotion motion = motion::PtpMotion::plan(model, q, target, velocity, motion::PtpTiming::kSynchronized);
    for (int k = 0; k <= 16; ++k) sweep.push_back(motion.joints_at(motion.duration() * k / 16.0));
    q = target;
  }
  std::vector<std::vector<std::vector<std::vector<Eigen::Vector3d>>>> placed;
  for (const Eigen::VectorXd& at : sweep) placed.push_back(free.oracle->place(at));
  c.cell_text = "units: m\n" + robot_yaml(robot) + "obstacles:\n";
  const int obstacles = 1 + static_cast<int>(unit(rng) * 2.0);
  std::normal_distribution<double> normal;
  for (int o = 0; o < obstacles; ++o) {
    const Eigen::Vector3d u = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    Eigen::Vector3d lowest = Eigen::Vector3d::Zero();
    double farthest = -std::numeric_limits<double>::infinity();
    for (const auto& configuration : placed) {
      for (std::size_t link = 1; link < configuration.size(); ++link) {  // the moving links
        for (const auto& hull : configuration[link]) {
          for (const auto& p : hull) {
            if (u.dot(p) > farthest) {
              farthest = u.dot(p);
              lowest = p;
            }
          }
        }
      }
    }
    const double gap = (unit(rng) < 0.33 ? 1.5 * unit(rng) : 4.0 * unit(rng) - 1.0) * c.tolerance;
    c.cell_text += obstacle_yaml(o, lowest, u, gap, rng);
  }
  c.cell_text += allowed_yaml(robot) + fmt::format("tolerance: {:.17g}\n", c.tolerance);
  return c;
}

struct Statistics {
  int cases = 0, contact = 0, self_contact = 0, clear = 0;
  int verdicts[5] = {0, 0, 0, 0, 0};
  int misses = 0, false_collisions = 0, rejected = 0;
  long long samples = 0, exact_checks = 0, decisions = 0, steps = 0;
  double seconds[3] = {0, 0, 0};  // oracle, certified, checker
};

void run_case(Robot robot, int index, std::uint64_t seed, Statistics& stats) {
  const UrdfCase c = random_case(robot, seed);
  const cell::LoadedCell loaded = load_cell_text(fmt::format("case-{}.yaml", seed), c.cell_text);
  const PathProgram program = io::parse_path_file(c.path_text, "path.txt", loaded.robot);
  const test::UrdfCellOracle oracle(loaded);
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const test::UrdfOraclePath truth =
      oracle.sample_path(program, motion::PtpTiming::kSynchronized, kSpacingFraction * c.tolerance);
  const auto t1 = Clock::now();
  SetupRequest request;
  request.tolerance = loaded.tolerance;
  request.motion.timing = motion::PtpTiming::kSynchronized;
  request.limits.max_probes = 20000;
  const auto kinematics = motion::make_kinematics_access(loaded.robot, motion::select_ik({}, loaded.robot, "urdf"));
  const VerificationRun certified = verify(loaded.robot, loaded.environment, program, kinematics, resolve_setup(request));
  const auto t2 = Clock::now();
  const Verdict verdict = certified.result.verdict;
  ++stats.cases;
  ++stats.verdicts[static_cast<int>(verdict)];
  stats.samples += truth.samples;
  stats.exact_checks += truth.exact_checks;
  stats.decisions += truth.decisions;
  stats.steps += static_cast<long long>(certified.result.steps.size());
  const bool contact = truth.first_contact.contact;
  stats.contact += contact;
  stats.self_contact += contact && truth.first_contact.self;
  stats.clear += !contact;
  if (std::getenv("GRPVSS_ORACLE_VERBOSE")) {
    std::cout << fmt::format("[urdf-oracle-case] {} tol {:.4f} verdict {} steps {} contact {} self {} obstacle-d {:.3e} "
                             "self-d {:.3e} samples {} oracle {:.2f}s certified {:.2f}s\n",
                             index, c.tolerance, to_string(verdict), certified.result.steps.size(), contact,
                             truth.first_contact.self, truth.min_obstacle_distance, truth.min_self_distance,
                             truth.samples, std::chrono::duration<double>(t1 - t0).count(),
                             std::chrono::duration<double>(t2 - t1).count());
  }
  if (contact) {
    EXPECT_NE(verdict, Verdict::kClear)
        << "certified CLEAR but the oracle found " << (truth.first_contact.self ? "a self-contact" : "contact")
        << " at segment " << truth.contact_segment << " link " << truth.first_contact.link << " hull "
        << truth.first_contact.hull << " other " << truth.first_contact.other_link << "/"
        << truth.first_contact.other_hull << " obstacle " << truth.first_contact.obstacle << " q "
        << truth.contact_q.transpose() << "\ncell:\n" << c.cell_text << "path:\n" << c.path_text;
    stats.misses += verdict == Verdict::kClear;
  }
  if (verdict == Verdict::kCollision) {
    ASSERT_TRUE(certified.result.collision_step.has_value());
    const int step = *certified.result.collision_step;
    const StepRecord& record = step == 0 ? *certified.result.start : certified.result.steps.at(step - 1);
    const bool real = oracle.check(record.q).contact;
    EXPECT_TRUE(real) << "reported collision step " << step;
    stats.false_collisions += !real;
  }
  const auto t3 = Clock::now();
  const CheckReport report = check_certificate(loaded.robot, loaded.environment, program, kinematics, certified.certificate);
  stats.seconds[0] += std::chrono::duration<double>(t1 - t0).count();
  stats.seconds[1] += std::chrono::duration<double>(t2 - t1).count();
  stats.seconds[2] += std::chrono::duration<double>(Clock::now() - t3).count();
  EXPECT_EQ(report.claim, verdict);
  EXPECT_TRUE(report.accepted) << fmt::format("{} failure(s), first: {}", report.failures.size(),
                                              report.failures.empty() ? "" : report.failures.front());
  stats.rejected += !report.accepted;
}

int cases_per_shard() {
  if (const char* count = std::getenv("GRPVSS_URDF_ORACLE_CASES_PER_SHARD")) return std::max(1, std::atoi(count));
  if (const char* long_run = std::getenv("GRPVSS_LONG_URDF_ORACLE"); long_run && std::string(long_run) == "1") {
    return kLongCasesPerShard;
  }
  return kCiCasesPerShard;
}

void run_shard(Robot robot, int shard) {
  Statistics stats;
  const std::uint64_t base = robot == Robot::kUr5e ? 0x0e5e0000ULL : 0xba4da000ULL;
  // Past the shard's cases, up to three times as many until it has both a contact and a clear
  // case (deterministic: the same seeds every run).
  const int cases = cases_per_shard();
  for (int k = 0; k < cases || (k < 3 * cases && (stats.contact == 0 || stats.clear == 0)); ++k) {
    const int index = shard + k * kShards;
    const std::uint64_t seed = base + static_cast<std::uint64_t>(index);
    SCOPED_TRACE(fmt::format("case {} (seed {:#x})", index, seed));
    run_case(robot, index, seed, stats);
    if (::testing::Test::HasFatalFailure()) return;
  }
  const std::string label = fmt::format("{}-{}", robot == Robot::kUr5e ? "ur5e" : "panda", shard);
  std::cout << fmt::format(
      "[urdf-oracle] {} cases {} contact {} (self {}) clear {} certified CLEAR {} COLLISION {} WITHIN_TOLERANCE {} "
      "UNDECIDED {} ERROR {} misses {} false_collisions {} rejected {} samples {} decisions {} exact {} "
      "steps {} seconds oracle {:.2f} certified {:.2f} checker {:.2f}\n",
      label, stats.cases, stats.contact, stats.self_contact, stats.clear, stats.verdicts[0], stats.verdicts[1],
      stats.verdicts[2], stats.verdicts[3], stats.verdicts[4], stats.misses, stats.false_collisions, stats.rejected,
      stats.samples, stats.decisions, stats.exact_checks, stats.steps, stats.seconds[0], stats.seconds[1], stats.seconds[2]);
  EXPECT_GT(stats.contact, 0);
  EXPECT_GT(stats.clear, 0);
  EXPECT_EQ(stats.misses, 0);
  EXPECT_EQ(stats.false_collisions, 0);
  EXPECT_EQ(stats.rejected, 0);
}

TEST(UrdfOracleSoundness, Ur5eShard0) { run_shard(Robot::kUr5e, 0); }
TEST(UrdfOracleSoundness, Ur5eShard1) { run_shard(Robot::kUr5e, 1); }
TEST(UrdfOracleSoundness, Ur5eShard2) { run_shard(Robot::kUr5e, 2); }
TEST(UrdfOracleSoundness, Ur5eShard3) { run_shard(Robot::kUr5e, 3); }
TEST(UrdfOracleSoundness, PandaShard0) { run_shard(Robot::kPanda, 0); }
TEST(UrdfOracleSoundness, PandaShard1) { run_shard(Robot::kPanda, 1); }
TEST(UrdfOracleSoundness, PandaShard2) { run_shard(Robot::kPanda, 2); }
TEST(UrdfOracleSoundness, PandaShard3) { run_shard(Robot::kPanda, 3); }

// The sampling bound the oracle rests on: over random joint-monotone (joint-linear) moves,
// no hull point of either robot travels farther than motion_bound(dq) (path length measured
// by 200 sub-steps of the reference FK).
TEST(UrdfOracleSoundness, TheMotionBoundCoversEveryHullPointsPath) {
  for (Robot robot : {Robot::kUr5e, Robot::kPanda}) {
    const FreeRobot& free = free_robot(robot);
    const RobotModel& model = free.cell.robot;
    std::mt19937_64 rng(robot == Robot::kUr5e ? 3 : 4);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double tightest = 0.0;
    for (int trial = 0; trial < 10; ++trial) {
      Eigen::VectorXd q0(model.joint_count()), q1(model.joint_count());
      for (int j = 0; j < q0.size(); ++j) {
        const Joint& joint = model.joints[static_cast<std::size_t>(j)];
        q0[j] = joint.minimum + (joint.maximum - joint.minimum) * unit(rng);
        q1[j] = std::clamp(q0[j] + 0.4 * (2 * unit(rng) - 1), joint.minimum, joint.maximum);
      }
      const auto start = free.oracle->place(q0);
      auto previous = start;
      std::vector<std::vector<std::vector<double>>> length(start.size());
      for (std::size_t l = 0; l < start.size(); ++l) {
        for (const auto& hull : start[l]) length[l].emplace_back(hull.size(), 0.0);
      }
      for (int k = 1; k <= 200; ++k) {
        const auto now = free.oracle->place(q0 + (q1 - q0) * (k / 200.0));
        for (std::size_t l = 0; l < now.size(); ++l) {
          for (std::size_t h = 0; h < now[l].size(); ++h) {
            for (std::size_t v = 0; v < now[l][h].size(); ++v) length[l][h][v] += (now[l][h][v] - previous[l][h][v]).norm();
          }
        }
        previous = now;
      }
      const double bound = free.oracle->motion_bound(q1 - q0);
      double longest = 0.0;
      for (const auto& link : length) {
        for (const auto& hull : link) longest = std::max(longest, *std::max_element(hull.begin(), hull.end()));
      }
      EXPECT_LE(longest, bound) << "trial " << trial;
      tightest = std::max(tightest, longest / bound);
    }
    // Not vacuous: the bound is within a small factor of the longest path.
    EXPECT_GT(tightest, 0.3);
  }
}

// The per-hull and self-pair bounds the oracle's step and skip rules rest on: over random
// joint-linear moves, no vertex of a hull travels farther in the world than
// hull_motion_bound(), and no vertex of a self pair's hull b travels farther in hull a's frame
// than relative_motion_bound() (paths measured by 100 sub-steps of the reference FK); both
// bounds come within a small factor of some measured path (not vacuous).
TEST(UrdfOracleSoundness, TheHullAndSelfPairBoundsCoverTheMeasuredPaths) {
  for (Robot robot : {Robot::kUr5e, Robot::kPanda}) {
    const FreeRobot& free = free_robot(robot);
    const RobotModel& model = free.cell.robot;
    ASSERT_FALSE(model.self_collision_pairs.empty());
    std::mt19937_64 rng(robot == Robot::kUr5e ? 5 : 6);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double tightest_hull = 0.0, tightest_pair = 0.0;
    for (int trial = 0; trial < 4; ++trial) {
      Eigen::VectorXd q0(model.joint_count()), q1(model.joint_count());
      for (int j = 0; j < q0.size(); ++j) {
        const Joint& joint = model.joints[static_cast<std::size_t>(j)];
        q0[j] = joint.minimum + (joint.maximum - joint.minimum) * unit(rng);
        q1[j] = std::clamp(q0[j] + 0.4 * (2 * unit(rng) - 1), joint.minimum, joint.maximum);
      }
      const auto& pairs = model.self_collision_pairs;
      std::vector<std::vector<test::Pose<double>>> X_WC;
      Eigen::VectorXd posed_at;
      auto relative = [&](const Eigen::VectorXd& q, const SelfCollisionPair& pair,
                          const std::vector<std::vector<std::vector<Eigen::Vector3d>>>& placed) {
        if (posed_at.size() != q.size() || q != posed_at) {
          X_WC = free.oracle->hull_poses(q);
          posed_at = q;
        }
        const test::Pose<double> X_CW = X_WC[pair.link_a][pair.hull_a].inverse();
        std::vector<Eigen::Vector3d> points;
        for (const auto& p : placed[pair.link_b][pair.hull_b]) points.push_back(X_CW.topLeftCorner<3, 3>() * p + X_CW.topRightCorner<3, 1>());
        return points;
      };
      auto previous = free.oracle->place(q0);
      std::vector<std::vector<Eigen::Vector3d>> previous_relative;
      for (const auto& pair : pairs) previous_relative.push_back(relative(q0, pair, previous));
      std::vector<std::vector<std::vector<double>>> length(previous.size());
      for (std::size_t l = 0; l < previous.size(); ++l) {
        for (const auto& hull : previous[l]) length[l].emplace_back(hull.size(), 0.0);
      }
      std::vector<std::vector<double>> relative_length;
      for (const auto& points : previous_relative) relative_length.emplace_back(points.size(), 0.0);
      for (int k = 1; k <= 100; ++k) {
        const Eigen::VectorXd q = q0 + (q1 - q0) * (k / 100.0);
        const auto now = free.oracle->place(q);
        for (std::size_t l = 0; l < now.size(); ++l) {
          for (std::size_t h = 0; h < now[l].size(); ++h) {
            for (std::size_t v = 0; v < now[l][h].size(); ++v) length[l][h][v] += (now[l][h][v] - previous[l][h][v]).norm();
          }
        }
        for (std::size_t p = 0; p < pairs.size(); ++p) {
          const auto points = relative(q, pairs[p], now);
          for (std::size_t v = 0; v < points.size(); ++v) relative_length[p][v] += (points[v] - previous_relative[p][v]).norm();
          previous_relative[p] = points;
        }
        previous = now;
      }
      const Eigen::VectorXd dq = q1 - q0;
      for (std::size_t l = 0; l < length.size(); ++l) {
        for (std::size_t h = 0; h < length[l].size(); ++h) {
          const double longest = *std::max_element(length[l][h].begin(), length[l][h].end());
          const double bound = free.oracle->hull_motion_bound(static_cast<int>(l), static_cast<int>(h), dq);
          EXPECT_LE(longest, bound) << "trial " << trial << " hull " << l << "/" << h;
          if (bound > 0.0) tightest_hull = std::max(tightest_hull, longest / bound);
        }
      }
      for (std::size_t p = 0; p < pairs.size(); ++p) {
        const double longest = *std::max_element(relative_length[p].begin(), relative_length[p].end());
        const double bound = free.oracle->relative_motion_bound(pairs[p].link_a, pairs[p].link_b, pairs[p].hull_b, dq);
        EXPECT_LE(longest, bound) << "trial " << trial << " pair " << p;
        if (bound > 0.0) tightest_pair = std::max(tightest_pair, longest / bound);
      }
    }
    EXPECT_GT(tightest_hull, 0.6);
    EXPECT_GT(tightest_pair, 0.6);
    std::cout << fmt::format("[urdf-oracle-bounds] tightest hull {:.3f} pair {:.3f}\n", tightest_hull, tightest_pair);
  }
}

}  // namespace urdf_oracle
}  // namespace
}  // namespace grpvss::certify

// Soundness of the certified verifier against a brute-force oracle written independently of
// it (tests/support/motion_oracle.hpp, exact LP contact in tests/support/exact_hull_lp.hpp):
// random robots, cells and PTP / CP paths with fixed seeds (tests/support/oracle_cases.hpp).
// Property (must hold for every case): certified mode never says CLEAR where the oracle finds
// a real contact on the commanded path, nor where it finds one on the joint-linear path
// through the recorded CP samples (what a CP certificate covers); a reported COLLISION step
// really collides; every certificate is accepted by check_certificate (the three rejections
// the long run found are fixed; tests/certify/oracle_findings_test.cpp); with the claim
// `motion` (the default), no CLEAR where the sampled clearance of the motion (from above,
// OracleContact::min_distance_upper) is below Delta (1 - 1e-6). Statistics
// (thesis-mode misses, certified false alarms against the oracle's clearance) are printed as
// "[oracle]" lines and recorded in docs/soundness-oracle.md.
//
// The cases run in shards (separate ctest tests, so ctest -j runs them in parallel); shard s
// of a family takes the case indices s, s + S, s + 2S, ... Normal run: kCiCasesPerShard per
// shard. Long run: GRPVSS_LONG_ORACLE=1 (kLongCasesPerShard per shard) or
// GRPVSS_ORACLE_CASES_PER_SHARD=<n>; it contains the normal run's cases. One case:
// GRPVSS_ORACLE_CASE=<index> (with the shard index % 8); per-case lines: GRPVSS_ORACLE_VERBOSE=1.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>

#include <Eigen/Geometry>
#include <fmt/core.h>
#include <gtest/gtest.h>

#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "support/motion_oracle.hpp"
#include "support/oracle_cases.hpp"

namespace grpvss::certify {
namespace {

constexpr int kShards = 8;            // per family
#ifdef __SANITIZE_ADDRESS__
// Under the sanitizers (scripts/test-sanitizers.sh, ~10x slower) only shard 0 runs (the others
// are labelled `heavy`), with fewer cases.
constexpr int kCiCasesPerShard = 8;
#else
constexpr int kCiCasesPerShard = 20;  // 2 families x 8 shards x 20 = 320 cases
#endif
constexpr int kLongCasesPerShard = 250;  // 4000 cases
constexpr double kOracleSpacingFraction = 1.0 / 20.0;  // of the tolerance
constexpr std::uint64_t kPtpSeedBase = 0x5eed0000ULL;
constexpr std::uint64_t kCpSeedBase = 0xc0de0000ULL;

int cases_per_shard() {
  if (const char* count = std::getenv("GRPVSS_ORACLE_CASES_PER_SHARD")) return std::max(1, std::atoi(count));
  if (const char* long_run = std::getenv("GRPVSS_LONG_ORACLE"); long_run && std::string(long_run) == "1") {
    return kLongCasesPerShard;
  }
  return kCiCasesPerShard;
}

VerificationRun run_mode(const test::OracleCase& c, const motion::KinematicsAccess& kinematics,
                         ResolutionMode mode) {
  SetupRequest options;
  options.tolerance = c.tolerance;
  options.mode = mode;
  // Bounded time: near-touching steps can shrink without end (ERROR 9, never CLEAR).
  options.limits.max_probes = 20000;
  return verify(c.robot, c.environment, c.program, kinematics, resolve_setup(options));
}

// Oracle clearance / Delta bins of the cases without oracle contact.
constexpr std::array<double, 6> kClearanceBins = {0.5, 1.0, 1.1, 1.5, 2.0, 4.0};
int clearance_bin(double clearance_over_delta) {
  int bin = 0;
  while (bin < static_cast<int>(kClearanceBins.size()) && clearance_over_delta >= kClearanceBins[bin]) ++bin;
  return bin;
}

struct Statistics {
  int cases = 0;
  int oracle_contact = 0;
  int oracle_not_followed = 0;  // a CP line the oracle could not follow (IK fails or jumps)
  int oracle_clear = 0;         // no contact, whole path sampled
  int certified[5] = {0, 0, 0, 0, 0};  // by Verdict
  int thesis[5] = {0, 0, 0, 0, 0};
  int certified_misses = 0;        // certified CLEAR, oracle contact on the commanded path
  int certified_claim_misses = 0;  // certified CLEAR, contact on the recorded CP joint path
  int certified_clear_line_not_followed = 0;
  int error_when_clear = 0;  // verdict ERROR, oracle followed the whole path without contact
  int thesis_misses = 0;           // thesis CLEAR, oracle contact
  // Certified verdicts of the oracle-clear cases, by clearance / Delta bin: CLEAR or not.
  int clear_by_bin[7] = {0, 0, 0, 0, 0, 0, 0};
  int not_clear_by_bin[7] = {0, 0, 0, 0, 0, 0, 0};
  double largest_not_clear_ratio = 0.0;  // largest oracle clearance / Delta of a non-CLEAR case
  double smallest_clear_ratio = std::numeric_limits<double>::infinity();  // ... of a CLEAR case
  int certified_false_collisions = 0;
  // The claim `motion`: certified CLEAR where a segment's sampled clearance (from above) is
  // below Delta (1 - 1e-6); and the smallest such clearance / Delta over the CLEAR cases.
  int certified_tolerance_misses = 0;
  double smallest_clear_sampled_ratio = std::numeric_limits<double>::infinity();
  int certificates_rejected = 0;
  int cp_segments_checked = 0;  // CP segments whose recorded joint path the oracle sampled
  long long oracle_samples = 0;
  long long oracle_exact_checks = 0;
  long long certified_steps = 0;
  // Wall time (reported, never asserted): oracle, certified, thesis, checker.
  double seconds[4] = {0, 0, 0, 0};
};

void run_case(const test::OracleCase& c, const std::string& label, Statistics& stats) {
  const auto kinematics = motion::make_kinematics_access(c.robot, motion::select_ik(c.ik, c.robot, "random"));
  const test::MotionOracle oracle(c.robot, c.environment);
  const double spacing = kOracleSpacingFraction * c.tolerance;
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const test::OraclePathResult truth = oracle.sample_path(c.program, spacing, kinematics);
  const auto t1 = Clock::now();
  const VerificationRun certified = run_mode(c, kinematics, ResolutionMode::kCertified);
  const auto t2 = Clock::now();
  const VerificationRun thesis = run_mode(c, kinematics, ResolutionMode::kThesis);
  const auto t3 = Clock::now();
  stats.seconds[0] += std::chrono::duration<double>(t1 - t0).count();
  stats.seconds[1] += std::chrono::duration<double>(t2 - t1).count();
  stats.seconds[2] += std::chrono::duration<double>(t3 - t2).count();
  if (std::getenv("GRPVSS_ORACLE_VERBOSE")) {
    std::cout << fmt::format("[oracle-case] tol {:.3f} verdict {} steps {} contact {} oracle {:.2f}s certified {:.2f}s\n",
                             c.tolerance, to_string(certified.result.verdict), certified.result.steps.size(),
                             truth.first_contact.contact, std::chrono::duration<double>(t1 - t0).count(),
                             std::chrono::duration<double>(t2 - t1).count());
    for (const PathError& error : certified.result.errors) {
      std::cout << fmt::format("[oracle-case] error {} segment {} step {}: {}\n", error.code, error.segment,
                               error.step, error.message);
    }
    for (const SegmentRecord& segment : certified.result.segments) {
      std::cout << fmt::format("[oracle-case] segment {} simulated {} steps {}..{}\n", segment.number,
                               segment.simulated, segment.first_step, segment.last_step);
    }
  }
  const Verdict verdict = certified.result.verdict;

  ++stats.cases;
  stats.oracle_samples += truth.samples;
  stats.oracle_exact_checks += truth.exact_checks;
  stats.certified_steps += static_cast<long long>(certified.result.steps.size());
  ++stats.certified[static_cast<int>(verdict)];
  ++stats.thesis[static_cast<int>(thesis.result.verdict)];
  const bool contact = truth.first_contact.contact;
  stats.oracle_contact += contact;
  stats.oracle_not_followed += !contact && truth.line_not_followed;

  // The soundness property on the commanded path.
  if (contact) {
    EXPECT_NE(verdict, Verdict::kClear)
        << "certified CLEAR but the oracle found contact at segment " << truth.contact_segment
        << " parameter " << truth.contact_parameter << " link " << truth.first_contact.link << " hull "
        << truth.first_contact.hull << " obstacle " << truth.first_contact.obstacle << " q "
        << truth.contact_q.transpose();
    stats.certified_misses += verdict == Verdict::kClear;
    stats.thesis_misses += thesis.result.verdict == Verdict::kClear;
    if (thesis.result.verdict == Verdict::kClear) {
      std::cout << fmt::format("[oracle-thesis-miss] {} tolerance {:.4f} contact segment {} link {} hull {} obstacle {}\n",
                               label, c.tolerance, truth.contact_segment, truth.first_contact.link,
                               truth.first_contact.hull, truth.first_contact.obstacle);
    }
  } else if (!truth.line_not_followed && verdict == Verdict::kError) {
    // A path error (5, 7, 8, 9) on a path the oracle followed without contact: not CLEAR for
    // a reason other than clearance; kept out of the false-alarm bins.
    ++stats.oracle_clear;
    ++stats.error_when_clear;
  } else if (!truth.line_not_followed) {
    ++stats.oracle_clear;
    const double ratio = truth.min_distance_estimate / c.tolerance;
    ++(verdict == Verdict::kClear ? stats.clear_by_bin : stats.not_clear_by_bin)[clearance_bin(ratio)];
    if (verdict == Verdict::kClear) {
      stats.smallest_clear_ratio = std::min(stats.smallest_clear_ratio, ratio);
    } else {
      stats.largest_not_clear_ratio = std::max(stats.largest_not_clear_ratio, ratio);
      if (ratio >= 1.0) {
        std::cout << fmt::format("[oracle-false-alarm] {} tolerance {:.4f} clearance/Delta {:.4f} verdict {}\n", label,
                                 c.tolerance, ratio, to_string(verdict));
      }
    }
  } else {
    stats.certified_clear_line_not_followed += verdict == Verdict::kClear;
    if (verdict == Verdict::kClear) {
      std::cout << fmt::format("[oracle-clear-line-not-followed] {} segment {}\n", label, truth.stopped_segment);
    }
  }
  // ... and on what a CP certificate covers: the joint-linear motion through the recorded
  // samples (proofs/cp-joint-path.md#guarantee).
  std::vector<double> sampled_upper = truth.segment_min_distance_upper;  // per segment
  for (const SegmentRecord& segment : certified.result.segments) {
    if (!segment.simulated || !std::holds_alternative<CpLineSegment>(segment.input.spec)) continue;
    std::vector<Eigen::VectorXd> q_samples{segment.start_q};
    for (const StepRecord& step : certified.result.steps) {
      if (step.segment == segment.number) q_samples.push_back(step.q);
    }
    const test::OraclePathResult claim = oracle.sample_joint_linear(q_samples, spacing, segment.number);
    ++stats.cp_segments_checked;
    // What the claim `motion` covers on a CP line is this joint path (the commanded line may
    // lie up to the CP model's deviation away from it).
    if (sampled_upper.size() < static_cast<std::size_t>(segment.number)) {
      sampled_upper.resize(static_cast<std::size_t>(segment.number),
                           std::numeric_limits<double>::infinity());
    }
    sampled_upper[static_cast<std::size_t>(segment.number - 1)] = claim.min_distance_upper;
    stats.oracle_samples += claim.samples;
    stats.oracle_exact_checks += claim.exact_checks;
    if (claim.first_contact.contact) {
      EXPECT_NE(verdict, Verdict::kClear)
          << "certified CLEAR but the joint-linear path through the recorded CP samples of segment "
          << segment.number << " touches obstacle " << claim.first_contact.obstacle << " at q "
          << claim.contact_q.transpose();
      stats.certified_claim_misses += verdict == Verdict::kClear;
    }
  }
  // The claim `motion` (docs/verification.md#claim): no CLEAR where the sampled clearance of
  // a simulated segment's motion is below Delta.
  if (verdict == Verdict::kClear && !truth.line_not_followed) {
    for (const SegmentRecord& segment : certified.result.segments) {
      const auto index = static_cast<std::size_t>(segment.number - 1);
      if (!segment.simulated || index >= sampled_upper.size()) continue;
      const double ratio = sampled_upper[index] / c.tolerance;
      stats.smallest_clear_sampled_ratio = std::min(stats.smallest_clear_sampled_ratio, ratio);
      EXPECT_GE(ratio, 1.0 - 1e-6) << "certified CLEAR (claim motion) but segment "
                                   << segment.number << " comes within " << sampled_upper[index]
                                   << " of an obstacle, tolerance " << c.tolerance;
      stats.certified_tolerance_misses += ratio < 1.0 - 1e-6;
    }
  }
  // A reported collision is real.
  if (verdict == Verdict::kCollision) {
    ASSERT_TRUE(certified.result.collision_step.has_value());
    const int step = *certified.result.collision_step;
    const StepRecord& record = step == 0 ? *certified.result.start : certified.result.steps.at(step - 1);
    EXPECT_TRUE(oracle.check(record.q).contact) << "reported collision step " << step;
    stats.certified_false_collisions += !contact && !oracle.check(record.q).contact;
  }
  // Every certificate is accepted by the independent checker.
  const auto t4 = Clock::now();
  const CheckReport report =
      check_certificate(c.robot, c.environment, c.program, kinematics, certified.certificate);
  stats.seconds[3] += std::chrono::duration<double>(Clock::now() - t4).count();
  EXPECT_EQ(report.claim, verdict);
  EXPECT_TRUE(report.accepted) << fmt::format("{} failure(s), first: {}", report.failures.size(),
                                              report.failures.empty() ? "" : report.failures.front());
  for (const std::string& failure : report.failures) std::cout << "[oracle-rejected] " << failure << "\n";
  stats.certificates_rejected += !report.accepted;
}

std::string verdicts(const int* counts) {
  return fmt::format("CLEAR {} COLLISION {} WITHIN_TOLERANCE {} UNDECIDED {} ERROR {}", counts[0], counts[1],
                     counts[2], counts[3], counts[4]);
}

void print(const std::string& label, const Statistics& s) {
  auto bins = [](const int* counts) {
    return fmt::format("{} {} {} {} {} {} {}", counts[0], counts[1], counts[2], counts[3], counts[4], counts[5],
                       counts[6]);
  };
  std::cout << fmt::format(
      "[oracle] {} cases {} contact {} clear {} not_followed {} error_when_clear {} samples {} exact {} cp_segments {}\n"
      "[oracle] {} certified {} steps {} misses {} claim_misses {} clear_not_followed {} "
      "false_collisions {} rejected {}\n"
      "[oracle] {} claim_motion tolerance_misses {} sampled_ratio_min_clear {:.4f}\n"
      "[oracle] {} clear_by_bin {} not_clear_by_bin {} (bins of clearance/Delta: <0.5 <1 <1.1 <1.5 <2 <4 "
      ">=4) ratio_max_not_clear {:.4f} ratio_min_clear {:.4f}\n"
      "[oracle] {} thesis {} misses {}\n"
      "[oracle] {} seconds oracle {:.2f} certified {:.2f} thesis {:.2f} checker {:.2f}\n",
      label, s.cases, s.oracle_contact, s.oracle_clear, s.oracle_not_followed, s.error_when_clear, s.oracle_samples,
      s.oracle_exact_checks, s.cp_segments_checked, label, verdicts(s.certified), s.certified_steps,
      s.certified_misses, s.certified_claim_misses, s.certified_clear_line_not_followed,
      s.certified_false_collisions, s.certificates_rejected, label, s.certified_tolerance_misses,
      s.smallest_clear_sampled_ratio, label, bins(s.clear_by_bin),
      bins(s.not_clear_by_bin), s.largest_not_clear_ratio, s.smallest_clear_ratio, label, verdicts(s.thesis), s.thesis_misses, label, s.seconds[0],
      s.seconds[1], s.seconds[2], s.seconds[3]);
}

enum class Family { kPtp, kScaraCp };

void run_shard(Family family, int shard) {
  const char* only_case = std::getenv("GRPVSS_ORACLE_CASE");
  const int count = only_case != nullptr ? std::atoi(only_case) / kShards + 1 : cases_per_shard();
  Statistics stats;
  // GRPVSS_ORACLE_CASE=<index>: only that case (reproducing a report).
  for (int k = 0; k < count; ++k) {
    const int index = shard + k * kShards;
    if (only_case != nullptr && index != std::atoi(only_case)) continue;
    const std::uint64_t seed =
        (family == Family::kPtp ? kPtpSeedBase : kCpSeedBase) + static_cast<std::uint64_t>(index);
    const std::string label = fmt::format("case {} (seed {:#x})", index, seed);
    SCOPED_TRACE(label);
    const test::OracleCase c = family == Family::kPtp ? test::random_ptp_case(seed) : test::random_scara_cp_case(seed);
    run_case(c, label, stats);
    if (::testing::Test::HasFatalFailure()) return;
  }
  print(fmt::format("{}-{}", family == Family::kPtp ? "ptp" : "cp", shard), stats);
  // The generator must exercise both sides of the property in every shard.
  if (only_case == nullptr) {
    EXPECT_GT(stats.oracle_contact, 0);
    EXPECT_GT(stats.oracle_clear, 0);
  }
  EXPECT_EQ(stats.certified_misses, 0);
  EXPECT_EQ(stats.certified_claim_misses, 0);
  EXPECT_EQ(stats.certified_false_collisions, 0);
  EXPECT_EQ(stats.certified_tolerance_misses, 0);
  EXPECT_EQ(stats.certificates_rejected, 0);
  if (family == Family::kScaraCp && only_case == nullptr) EXPECT_GT(stats.cp_segments_checked, 0);
}

// Shard 0 of each family runs under the sanitizers too; the others carry the ctest label
// `heavy` (tests/ctest_properties.cmake) and run in the Release suite only.
TEST(OracleSoundness, RandomPtpShard0) { run_shard(Family::kPtp, 0); }
TEST(OracleSoundness, RandomPtpShard1) { run_shard(Family::kPtp, 1); }
TEST(OracleSoundness, RandomPtpShard2) { run_shard(Family::kPtp, 2); }
TEST(OracleSoundness, RandomPtpShard3) { run_shard(Family::kPtp, 3); }
TEST(OracleSoundness, RandomPtpShard4) { run_shard(Family::kPtp, 4); }
TEST(OracleSoundness, RandomPtpShard5) { run_shard(Family::kPtp, 5); }
TEST(OracleSoundness, RandomPtpShard6) { run_shard(Family::kPtp, 6); }
TEST(OracleSoundness, RandomPtpShard7) { run_shard(Family::kPtp, 7); }
TEST(OracleSoundness, ScaraCpShard0) { run_shard(Family::kScaraCp, 0); }
TEST(OracleSoundness, ScaraCpShard1) { run_shard(Family::kScaraCp, 1); }
TEST(OracleSoundness, ScaraCpShard2) { run_shard(Family::kScaraCp, 2); }
TEST(OracleSoundness, ScaraCpShard3) { run_shard(Family::kScaraCp, 3); }
TEST(OracleSoundness, ScaraCpShard4) { run_shard(Family::kScaraCp, 4); }
TEST(OracleSoundness, ScaraCpShard5) { run_shard(Family::kScaraCp, 5); }
TEST(OracleSoundness, ScaraCpShard6) { run_shard(Family::kScaraCp, 6); }
TEST(OracleSoundness, ScaraCpShard7) { run_shard(Family::kScaraCp, 7); }

// One revolute joint about the world z axis; the link's box reaches from the axis (x = -10)
// to radius 30 (x = +20) while frame 1 sits at radius 10: a tool sticking out 20 beyond the
// link-frame origin. A 0.2-thick plate at 60 degrees, radius 25..35, is reached only by the
// tool; the thesis rule's steps at the frame origin jump across it.
TEST(OracleSoundness, ThinPlateTheThesisRuleMissesIsFoundByOracleAndCertifiedMode) {
  const char* robot_text = R"(1
0
0.0,0.0,10.0,0.0,-180.0,180.0,60.,60.
0
1.0
1
HULL 8
-10,-0.5,-0.5
20,-0.5,-0.5
20,0.5,-0.5
-10,0.5,-0.5
-10,-0.5,0.5
20,-0.5,0.5
20,0.5,0.5
-10,0.5,0.5
)";
  std::string environment_text = "90.\n0.2\n1\nHULL 8\n";
  const double angle = 60.0 * M_PI / 180.0;
  const Eigen::Vector2d u(std::cos(angle), std::sin(angle)), v(-std::sin(angle), std::cos(angle));
  for (double r : {25.0, 35.0}) {
    for (double t : {-0.1, 0.1}) {
      for (double z : {-1.0, 1.0}) {
        const Eigen::Vector2d p = r * u + t * v;
        environment_text += fmt::format("{:.12f},{:.12f},{}\n", p.x(), p.y(), z);
      }
    }
  }
  test::OracleCase c;
  c.robot = io::parse_robot_file(robot_text, "robot.txt");
  c.environment = io::parse_environment_file(environment_text, "environment.txt");
  c.program = io::parse_path_file("1\n1\n120.,30.\n", "path.txt", c.robot);
  c.tolerance = 0.1;
  const auto kinematics = motion::make_kinematics_access(c.robot, motion::select_ik({kinematics::IkMethod::kNumeric, {}}, c.robot, "robot.txt"));
  const test::MotionOracle oracle(c.robot, c.environment);
  const test::OraclePathResult truth =
      oracle.sample_path(c.program, kOracleSpacingFraction * c.tolerance, kinematics);
  ASSERT_TRUE(truth.first_contact.contact);
  // The tool's half-width 0.5 at radius 25 meets the plate's 0.1 near 60 degrees.
  EXPECT_NEAR(truth.contact_q[0] * 180.0 / M_PI, 60.0, 2.0);
  EXPECT_EQ(run_mode(c, kinematics, ResolutionMode::kThesis).result.verdict, Verdict::kClear);
  const VerificationRun certified = run_mode(c, kinematics, ResolutionMode::kCertified);
  EXPECT_EQ(certified.result.verdict, Verdict::kCollision);
  const CheckReport report = check_certificate(c.robot, c.environment, c.program, kinematics, certified.certificate);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
}

}  // namespace
}  // namespace grpvss::certify

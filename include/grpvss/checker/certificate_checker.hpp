#pragma once
/// \file
/// \brief Re-verifies a certificate from the input files alone, deciding every inequality in
/// exact rational arithmetic. A separate code path, and a separate stage that the build keeps
/// apart from the verifier (docs/architecture.md): it never calls the verifier's step rule,
/// probe or cell; it recomputes the trajectory (motion stage), forward kinematics and the
/// tolerance offsets itself and checks each recorded number against them. The report it
/// returns is the decision: callers print it, they do not decide again.
/// proof: proofs/README.md (every lemma the check relies on)

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "grpvss/evidence/certificate.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/joint_trajectory_motion.hpp"
#include "grpvss/motion/kinematics_access.hpp"
#include "grpvss/motion/profile_table.hpp"

namespace grpvss::certify {

/// \brief How far a link provably stays from every obstacle along the whole motion, as the
/// checker derives it: the exact minimum, over every transition of the certificate and every
/// hull of the link, of g = max((r_k + r_k+1 - M)/2, max(r_k, r_k+1) - M) with the verified
/// radii and the exact motion bound M, rounded down (0 where it proves nothing).
/// proof: proofs/two-ball-cover.md#corollary-motion-clearance
struct CheckedMotionClearance {
  int link = 0;
  double lower_bound = 0.0;
  int step = 0;  ///< the step that ends the transition where the minimum occurs
};

struct CheckReport {
  bool accepted = false;
  Verdict claim = Verdict::kError;    ///< the verdict the certificate claims
  /// What its CLEAR means, as checked: `motion` (g >= Delta decided in every transition of a
  /// CLEAR certificate) or `steps` (docs/certificate.md#claim).
  ClearClaim clear_claim = ClearClaim::kSteps;
  /// The motion model the steps were checked against: the certificate's, replayed.
  motion::PtpTiming timing = motion::PtpTiming::kIndependent;
  double cp_speed = 0.0;
  std::string ik;  ///< the IK the certificate names (its "inputs"), empty when it names none
  std::vector<std::string> failures;  ///< every rejected inequality, with step and hull
  long long inequalities_checked = 0;
  /// Per link with at least one transition, in link order; empty unless accepted (a rejected
  /// certificate proves no clearance).
  std::vector<CheckedMotionClearance> motion_clearances;
};

struct CheckOptions {
  std::shared_ptr<const motion::ProfileTable> profile_table;  ///< when verify used one
  /// A planner's joint trajectory (joints matched to the robot's): the motion the steps are
  /// checked against instead of the path program's, with the exact variation bound
  /// (docs/certificate.md#joint-trajectories). Null: the path program.
  std::shared_ptr<const motion::JointTrajectoryMotion> joint_trajectory;
  /// The path program's start configuration (library units), as verify was given it
  /// (`--start`); unset: the robot's home. A certificate recording another start (or one
  /// recording a start when this is unset, or none when it is set) is rejected.
  std::optional<Eigen::VectorXd> start;
  /// SHA-256 of the files the check runs on ("robot", "environment", "path" or "trajectory"). When the
  /// certificate names its inputs, each must match, else the certificate is rejected.
  std::map<std::string, std::string> input_digests;
  std::size_t max_failures = 20;
};

CheckReport check_certificate(const RobotModel& robot, const Environment& environment,
                              const PathProgram& program,
                              const motion::KinematicsAccess& kinematics,
                              const Certificate& certificate, const CheckOptions& options = {});

/// \brief check_certificate() fed one segment at a time, so that a certificate file can be read
/// and checked in memory independent of its number of steps (`grpvss check-certificate`,
/// docs/reliability.md#resource-bounds). The same report as check_certificate() of the
/// certificate with those segments.
class CertificateCheck {
 public:
  /// `header`: the certificate without its segments (any it has are dropped); `segment_count`:
  /// how many add_segment() calls will follow. Checks the header at once.
  CertificateCheck(const RobotModel& robot, const Environment& environment,
                   const PathProgram& program, const motion::KinematicsAccess& kinematics,
                   Certificate header, std::size_t segment_count, const CheckOptions& options = {});
  CertificateCheck(const CertificateCheck&) = delete;
  CertificateCheck& operator=(const CertificateCheck&) = delete;
  ~CertificateCheck();

  /// The next segment in certificate order. \throws std::logic_error beyond `segment_count`.
  void add_segment(const SegmentCertificate& segment);

  /// The report, after the last segment. \throws std::logic_error if segments are missing.
  CheckReport finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace grpvss::certify

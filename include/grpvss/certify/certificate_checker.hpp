#pragma once
/// \file
/// \brief Re-verifies a certificate from the input files alone, deciding every inequality in
/// exact rational arithmetic. A separate code path: it never calls the verifier's step rule,
/// probe or cell; it recomputes the trajectory (motion stage), forward kinematics and the
/// tolerance offsets itself and checks each recorded number against them.
/// proof: proofs/README.md (every lemma the check relies on)

#include <string>
#include <vector>

#include "grpvss/certify/certificate.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/kinematics_access.hpp"
#include "grpvss/motion/profile_table.hpp"

namespace grpvss::certify {

struct CheckReport {
  bool accepted = false;
  std::string claim;                  ///< the verdict the certificate claims
  std::vector<std::string> failures;  ///< every rejected inequality, with step and hull
  long long inequalities_checked = 0;
};

struct CheckOptions {
  std::shared_ptr<const motion::ProfileTable> profile_table;  ///< when verify used one
  std::size_t max_failures = 20;
};

CheckReport check_certificate(const RobotModel& robot, const Environment& environment,
                              const PathProgram& program,
                              const motion::KinematicsAccess& kinematics,
                              const Certificate& certificate, const CheckOptions& options = {});

}  // namespace grpvss::certify

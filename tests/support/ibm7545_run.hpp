#pragma once
// One certified verification of the IBM 7545 sample robot (data/ibm7545/robot.txt) at the
// thesis's tolerance 0.5, with its inputs kept for the checks that follow.

#include <string>

#include "grpvss/certify/verifier.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/kinematics_access.hpp"

namespace grpvss::test {

inline constexpr double kIbm7545Tolerance = 0.5;

struct Ibm7545Run {
  RobotModel robot;
  Environment environment;
  PathProgram program;
  motion::KinematicsAccess kinematics;
  certify::VerificationSetup setup;  ///< certified, tolerance kIbm7545Tolerance
  certify::VerificationRun run;
};

/// data/ibm7545/<environment_file>, the path given as path-file text, certified mode.
Ibm7545Run verify_ibm7545(const std::string& environment_file, const std::string& path_text,
                          certify::ClearClaim claim = certify::ClearClaim::kMotion);

/// data/ibm7545/<environment_file> and data/ibm7545/<path_file>, certified mode.
Ibm7545Run verify_ibm7545_files(const std::string& environment_file, const std::string& path_file,
                                certify::ClearClaim claim = certify::ClearClaim::kMotion);

/// The Table 3 PTP operation (50 deg on joints 1, 2, 4 at 3 deg/s, 4 in. at 0.3 in/s).
inline const char* kTable3PtpPath = "1\n1\n50.,3.\n50.,3.\n4.,0.3\n50.,3.\n";

}  // namespace grpvss::test

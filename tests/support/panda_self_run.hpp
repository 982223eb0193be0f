#pragma once
/// \file
/// \brief A certified run of the Panda self-collision cell (tests/data/cells/panda-self.yaml),
/// as `grpvss verify --cell panda-self.yaml --path <path> [--claim <claim>]` makes it: the
/// cell's tolerance and synchronized PTP timing. Shared by the self-collision and claim tests.

#include <string>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/checker/certificate_checker.hpp"

namespace grpvss::test {

struct PandaSelfRun {
  cell::LoadedCell cell;
  PathProgram program;
  motion::KinematicsAccess kinematics;
  certify::VerificationRun verified;
};

/// `path` names a file in tests/data/cells/.
PandaSelfRun run_panda_self(const std::string& path,
                            certify::ClearClaim claim = certify::ClearClaim::kMotion);

/// check_certificate of `certificate` against the run's own inputs.
certify::CheckReport check_panda_self(const PandaSelfRun& run, const certify::Certificate& certificate);

}  // namespace grpvss::test

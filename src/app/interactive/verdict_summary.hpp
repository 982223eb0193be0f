#pragma once
/// \file
/// \brief The short verdict text printed after a verification (`grpvss verify` and the
/// interactive session print the same lines).

#include <string>

#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::app {

/// \brief Where the names of links and obstacles come from (indices when absent or unnamed).
struct ModelNames {
  const RobotModel* robot = nullptr;
  const Environment* environment = nullptr;
  std::string link(int index) const;
  std::string obstacle(int index) const;
  /// "3", or "3 (panda_leftfinger)" when hull 3 of the link came from another URDF link.
  std::string hull_suffix(int link, int hull) const;
};

/// "verdict: ...", the mode/tolerance/steps line, the first collision, each error and each
/// link's smallest certified clearance, one per line.
std::string verdict_summary(const certify::VerificationResult& result,
                            const ModelNames& names = {});

}  // namespace grpvss::app

#pragma once
/// \file
/// \brief The short verdict text printed after a verification (`grpvss verify` and the
/// interactive session print the same lines).

#include <string>

#include "grpvss/evidence/verification_result.hpp"

namespace grpvss::app {

/// "verdict: ...", the mode/tolerance/steps line, the first collision, each error and each
/// link's smallest certified clearance, one per line.
std::string verdict_summary(const certify::VerificationResult& result);

}  // namespace grpvss::app

#pragma once
// A probed configuration's verdict and findings, from its evidence alone.

#include "cell_probe.hpp"
#include "grpvss/certify/configuration_check.hpp"

namespace grpvss::certify {

/// \brief The verdict the evidence of `probed` proves (a probe of either ProbeNeed): every
/// offset-interfering pair a finding (collision, within tolerance, or undecided without a raw
/// witness), every self pair without a positive exact distance a finding (self-collision on a
/// contact, else undecided). proof: proofs/configuration-check.md#lemma-configuration-verdict
ConfigurationVerdict verdict_of(const RobotCell& cell, const ProbeResult& probed);

}  // namespace grpvss::certify

#pragma once
// The certificate's claim against what its checked steps established: CLEAR and
// WITHIN_TOLERANCE need every transition certified and the whole path covered; COLLISION is
// re-decided exactly from scratch at the named step.

#include "check_ledger.hpp"
#include "checked_cell.hpp"
#include "claim_facts.hpp"
#include "grpvss/evidence/certificate.hpp"

namespace grpvss::certify {

void check_claim(const Certificate& header, const ClaimFacts& facts, const CheckedCell& cell,
                 CheckLedger& ledger);

}  // namespace grpvss::certify

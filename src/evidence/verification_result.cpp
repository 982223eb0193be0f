#include "grpvss/evidence/verification_result.hpp"

namespace grpvss::certify {

const char* to_string(ResolutionMode mode) {
  switch (mode) {
    case ResolutionMode::kCertified: return "certified";
    case ResolutionMode::kThesis: return "thesis";
  }
  return "?";
}

const char* to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::kClear: return "CLEAR";
    case Verdict::kCollision: return "COLLISION";
    case Verdict::kWithinTolerance: return "WITHIN_TOLERANCE";
    case Verdict::kUndecided: return "UNDECIDED";
    case Verdict::kError: return "ERROR";
  }
  return "?";
}

std::optional<ResolutionMode> resolution_mode_from_string(std::string_view text) {
  for (ResolutionMode mode : {ResolutionMode::kCertified, ResolutionMode::kThesis}) {
    if (text == to_string(mode)) return mode;
  }
  return std::nullopt;
}

std::optional<Verdict> verdict_from_string(std::string_view text) {
  for (Verdict verdict : {Verdict::kClear, Verdict::kCollision, Verdict::kWithinTolerance,
                          Verdict::kUndecided, Verdict::kError}) {
    if (text == to_string(verdict)) return verdict;
  }
  return std::nullopt;
}

const char* to_string(ClearClaim claim) {
  return claim == ClearClaim::kSteps ? "steps" : "motion";
}

std::optional<ClearClaim> clear_claim_from_string(std::string_view text) {
  if (text == "motion") return ClearClaim::kMotion;
  if (text == "steps") return ClearClaim::kSteps;
  return std::nullopt;
}

const char* to_string(GoverningTerm term) {
  switch (term) {
    case GoverningTerm::kTolerance: return "tolerance";
    case GoverningTerm::kClearance: return "clearance";
    case GoverningTerm::kThesisRule: return "thesis-rule";
    case GoverningTerm::kSegmentEnd: return "segment-end";
    case GoverningTerm::kRawClearance: return "raw-clearance";
    case GoverningTerm::kUncertified: return "uncertified";
  }
  return "?";
}

}  // namespace grpvss::certify

#include "interactive/verdict_summary.hpp"

#include <algorithm>

#include <fmt/core.h>

namespace grpvss::app {
namespace {

// Also without the steps (VerifyOptions::keep_steps false): each segment records its last one.
int last_step_index(const certify::VerificationResult& result) {
  if (!result.steps.empty()) return result.steps.back().index;
  int last = 0;
  for (const certify::SegmentRecord& segment : result.segments) {
    last = std::max(last, segment.last_step);
  }
  return last;
}

}  // namespace

std::string verdict_summary(const certify::VerificationResult& result) {
  const bool certified = result.mode == certify::ResolutionMode::kCertified;
  std::string text = fmt::format("verdict: {}{}\n", certify::to_string(result.verdict),
                                 certified ? "" : " (thesis mode: NOT certified)");
  text += fmt::format("mode: {}  tolerance: {}  steps: {}  cycle time: {:.3f} s\n",
                      certify::to_string(result.mode), result.tolerance,
                      last_step_index(result),
                      result.total_cycle_time);
  if (result.collision_step) text += fmt::format("first collision at step {}\n", *result.collision_step);
  for (const certify::PathError& error : result.errors) {
    text += fmt::format("error {} (segment {}, step {}): {}\n", error.code, error.segment,
                        error.step, error.message);
  }
  for (const certify::LinkClearanceSummary& link : result.link_clearances) {
    if (link.link == 0) continue;
    text += fmt::format("link {}: smallest certified clearance {:.4f} at step {}{}\n", link.link,
                        link.min_clearance, link.step,
                        link.obstacle >= 0 ? fmt::format(" (obstacle {})", link.obstacle) : "");
  }
  return text;
}

}  // namespace grpvss::app

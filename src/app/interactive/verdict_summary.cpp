#include "interactive/verdict_summary.hpp"

#include <fmt/core.h>

namespace grpvss::app {

std::string verdict_summary(const certify::VerificationResult& result) {
  const bool certified = result.mode == certify::ResolutionMode::kCertified;
  std::string text = fmt::format("verdict: {}{}\n", certify::to_string(result.verdict),
                                 certified ? "" : " (thesis mode: NOT certified)");
  text += fmt::format("mode: {}  tolerance: {}  steps: {}  cycle time: {:.3f} s\n",
                      certify::to_string(result.mode), result.tolerance,
                      result.steps.empty() ? 0 : result.steps.back().index,
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

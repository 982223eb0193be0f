#include "interactive/verdict_summary.hpp"

#include <algorithm>

#include <fmt/core.h>

#include "grpvss/evidence/certificate.hpp"
#include "grpvss/report/lower_bound_text.hpp"

namespace grpvss::app {
namespace {

// Also without the steps (RunHooks::keep_steps false): each segment records its last one.
int last_step_index(const certify::VerificationResult& result) {
  if (!result.steps.empty()) return result.steps.back().index;
  int last = 0;
  for (const certify::SegmentRecord& segment : result.segments) {
    last = std::max(last, segment.last_step);
  }
  return last;
}

constexpr std::size_t kEpisodesShown = 10;

std::string step_range(int first, int last) {
  return first == last ? fmt::format("step {}", first) : fmt::format("steps {}-{}", first, last);
}

// "interference: link 4 hull 0 / obstacle 0, steps 2-3 (7.784-8.872 s, clear by 13.054 s),
// unexpanded collides at step 3"
std::string episode_line(const certify::InterferenceEpisode& episode, const ModelNames& names) {
  const std::string cleared =
      episode.cleared_time ? fmt::format(", clear by {:.3f} s", *episode.cleared_time) : "";
  std::string line =
      fmt::format("interference: {} hull {} / {}, {} ({:.3f}-{:.3f} s{}), ",
                  names.link(episode.link), names.hull_suffix(episode.link, episode.hull),
                  names.obstacle(episode.obstacle),
                  step_range(episode.first_step, episode.last_step), episode.first_time,
                  episode.last_time, cleared);
  if (episode.first_collision_step) {
    line += "unexpanded collides at " +
            step_range(*episode.first_collision_step, *episode.last_collision_step);
  } else {
    line += "expanded hull only";
  }
  return line + "\n";
}

// "self-collision: forearm_link / base_link_inertia, steps 5-7 (1.200-1.500 s)"
std::string self_episode_line(const certify::SelfCollisionEpisode& episode,
                              const ModelNames& names) {
  const std::string pair =
      names.robot != nullptr
          ? self_pair_label(*names.robot, episode.pair)
          : fmt::format("link {} hull {} / link {} hull {}", episode.pair.link_b,
                        episode.pair.hull_b, episode.pair.link_a, episode.pair.hull_a);
  return fmt::format("self-collision: {}, {} ({:.3f}-{:.3f} s)\n", pair,
                     step_range(episode.first_step, episode.last_step), episode.first_time,
                     episode.last_time);
}

// "self-collision not verified: base_link_inertia / shoulder_link (adjacent); ..."
std::string unverified_pairs_line(const RobotModel& robot) {
  if (robot.unverified_link_pairs.empty()) return "";
  std::string line = "self-collision not verified:";
  for (const UnverifiedLinkPair& pair : robot.unverified_link_pairs) {
    line += fmt::format(" {} / {} ({});", pair.first, pair.second, pair.reason);
  }
  line.back() = '\n';
  return line;
}

}  // namespace

std::string ModelNames::link(int index) const {
  return robot != nullptr ? link_label(*robot, index) : fmt::format("link {}", index);
}

std::string ModelNames::hull_suffix(int link, int hull) const {
  std::string text = std::to_string(hull);
  if (robot == nullptr || link < 0 || static_cast<std::size_t>(link) >= robot->links.size()) {
    return text;
  }
  const Link& owner = robot->links[static_cast<std::size_t>(link)];
  if (hull < 0 || static_cast<std::size_t>(hull) >= owner.hulls.size()) return text;
  const std::string& declared_by = owner.hulls[static_cast<std::size_t>(hull)].name;
  // A URDF link merged into this frame (fixed joint, side branch): name the one it came from.
  if (!declared_by.empty() && declared_by != owner.name) text += " (" + declared_by + ")";
  return text;
}

std::string ModelNames::obstacle(int index) const {
  return environment != nullptr ? obstacle_label(*environment, index)
                                : fmt::format("obstacle {}", index);
}

std::string verdict_summary(const certify::VerificationResult& result, const ModelNames& names) {
  const bool certified = result.mode == certify::ResolutionMode::kCertified;
  std::string text = fmt::format("verdict: {}{}\n", certify::to_string(result.verdict),
                                 certified ? "" : " (thesis mode: NOT certified)");
  text += fmt::format("mode: {}  tolerance: {}  steps: {}  cycle time: {:.3f} s\n",
                      certify::to_string(result.mode), result.tolerance,
                      last_step_index(result),
                      result.total_cycle_time);
  if (names.environment != nullptr && !names.environment->allowed_contacts.empty()) {
    text += "allowed contacts (not verified):";
    for (const AllowedContactPair& pair : names.environment->allowed_contacts) {
      text += fmt::format(" {} hull {} / {};", names.link(pair.link),
                          names.hull_suffix(pair.link, pair.hull), names.obstacle(pair.obstacle));
    }
    text.back() = '\n';
  }
  if (names.robot != nullptr) text += unverified_pairs_line(*names.robot);
  if (result.collision_step) text += fmt::format("first collision at step {}\n", *result.collision_step);
  if (result.tolerance_shortfall) {
    const certify::ToleranceShortfall& shortfall = *result.tolerance_shortfall;
    text += fmt::format("claim motion not met: {} / {} keeps only {} along steps {}-{} (tolerance "
                        "{}): the nominal robot is proven clear there, the robot + tolerance "
                        "is not\n",
                        names.link(shortfall.link),
                        shortfall.other_link >= 0   ? names.link(shortfall.other_link)
                        : shortfall.obstacle >= 0 ? names.obstacle(shortfall.obstacle)
                                                  : std::string("its nearest obstacle"),
                        report::format_lower_bound(shortfall.motion_clearance, 4),
                        shortfall.step - 1, shortfall.step, result.tolerance);
  }
  const std::size_t self_shown = std::min(result.self_collision_episodes.size(), kEpisodesShown);
  for (std::size_t i = 0; i < self_shown; ++i) {
    text += self_episode_line(result.self_collision_episodes[i], names);
  }
  if (result.self_collision_episodes.size() > self_shown) {
    text += fmt::format("... and {} more self-collision episodes (JSON report: "
                        "self_collision_episodes)\n",
                        result.self_collision_episodes.size() - self_shown);
  }
  const std::size_t shown = std::min(result.interference_episodes.size(), kEpisodesShown);
  for (std::size_t i = 0; i < shown; ++i) text += episode_line(result.interference_episodes[i], names);
  if (result.interference_episodes.size() > shown) {
    text += fmt::format("... and {} more interference episodes (JSON report: "
                        "interference_episodes)\n",
                        result.interference_episodes.size() - shown);
  }
  for (const certify::PathError& error : result.errors) {
    text += fmt::format("error {} (segment {}, step {}): {}\n", error.code, error.segment,
                        error.step, error.message);
  }
  const certify::LinkClearanceSummary* closest = nullptr;  // smallest motion clearance
  for (const certify::LinkClearanceSummary& link : result.link_clearances) {
    if (link.min_clearance >= certify::kUnboundedRadius) {
      text += fmt::format("{}: no obstacle to check against (none, or every pair with it is an "
                          "allowed contact)\n",
                          names.link(link.link));
      continue;
    }
    text += fmt::format("{}: smallest certified clearance {} at step {}{}", names.link(link.link),
                        report::format_lower_bound(link.min_clearance, 4), link.step,
                        link.obstacle >= 0 ? fmt::format(" ({})", names.obstacle(link.obstacle))
                                           : "");
    if (link.min_motion_clearance) {
      text += fmt::format("; along the motion > {} (steps {}-{})",
                          report::format_lower_bound(*link.min_motion_clearance, 4),
                          link.motion_step - 1, link.motion_step);
      if (closest == nullptr || *link.min_motion_clearance < *closest->min_motion_clearance) {
        closest = &link;
      }
    }
    text += "\n";
  }
  // proof: proofs/two-ball-cover.md#corollary-motion-clearance
  if (result.verdict == certify::Verdict::kClear && closest != nullptr) {
    if (*closest->min_motion_clearance >= result.tolerance) {
      text += fmt::format("along the whole motion every link stays farther than {} (>= the "
                          "tolerance) from every obstacle\n",
                          report::format_lower_bound(*closest->min_motion_clearance, 4));
    } else {
      text += fmt::format(
          "note: along the motion {} is only proven to stay farther than {} (steps "
          "{}-{}), less than the tolerance {}: the nominal path is clear, a robot deviating from "
          "it by the tolerance is not proven clear\n",
          names.link(closest->link), report::format_lower_bound(*closest->min_motion_clearance, 4),
          closest->motion_step - 1,
          closest->motion_step, result.tolerance);
    }
  }
  return text;
}

}  // namespace grpvss::app

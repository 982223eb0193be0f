#pragma once
/// \file
/// \brief Which (link hull, obstacle) pairs interfere at a step, and the runs of consecutive
/// steps in which each pair does (interference episodes: where a collision begins and ends).
#include <map>
#include <tuple>
#include <vector>

#include "cell_probe.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/evidence/verification_result.hpp"

namespace grpvss::certify {

/// \brief The pairs whose expanded hull interferes in \p probe, with whether the unexpanded
/// hull meets the obstacle too, in (link, hull, obstacle) order.
std::vector<PairContact> interfering_pairs(const RobotCell& cell, const ProbeResult& probe);

/// \brief Builds the episodes from the steps in path order (the start configuration first),
/// in memory independent of the number of steps (it keeps only the open runs).
class InterferenceEpisodeTracker {
 public:
  /// \pre steps arrive in path order, each with its `contacts`.
  void add(const StepRecord& step);
  /// Every episode so far, ordered by first step, then (link, hull, obstacle).
  const std::vector<InterferenceEpisode>& episodes() const { return episodes_; }

 private:
  using PairKey = std::tuple<int, int, int>;  ///< (link, hull, obstacle)
  std::vector<InterferenceEpisode> episodes_;
  std::map<PairKey, std::size_t> open_;  ///< pairs interfering at the last step -> episode
};

/// \brief The self-collision pairs whose hulls meet in \p probe, in the cell's pair order.
std::vector<SelfCollisionPair> self_contacts(const RobotCell& cell, const ProbeResult& probe);

/// \brief Builds the self-collision episodes (runs of consecutive steps at which one pair's
/// hulls meet) from the steps in path order.
class SelfCollisionEpisodeTracker {
 public:
  void add(const StepRecord& step);
  const std::vector<SelfCollisionEpisode>& episodes() const { return episodes_; }

 private:
  std::vector<SelfCollisionEpisode> episodes_;
  std::map<SelfCollisionPair, std::size_t> open_;
};

}  // namespace grpvss::certify

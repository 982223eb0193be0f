#include "interference_episodes.hpp"

#include <algorithm>

namespace grpvss::certify {

std::vector<PairContact> interfering_pairs(const RobotCell& cell, const ProbeResult& probe) {
  std::vector<PairContact> pairs;
  for (const PairEvidence& evidence : probe.evidence) {
    if (!evidence.expanded || evidence.separated) continue;
    const LinkHull& hull = cell.hulls()[static_cast<std::size_t>(evidence.hull_index)];
    PairContact contact;
    contact.link = hull.link;
    contact.hull = hull.hull;
    contact.obstacle = evidence.obstacle;
    // The probe records a raw pair that meets the obstacle as raw evidence without a witness.
    contact.unexpanded_collides = std::any_of(
        probe.evidence.begin(), probe.evidence.end(), [&evidence](const PairEvidence& raw) {
          return !raw.expanded && !raw.separated && raw.hull_index == evidence.hull_index &&
                 raw.obstacle == evidence.obstacle;
        });
    pairs.push_back(contact);
  }
  std::sort(pairs.begin(), pairs.end(), [](const PairContact& a, const PairContact& b) {
    return std::tie(a.link, a.hull, a.obstacle) < std::tie(b.link, b.hull, b.obstacle);
  });
  return pairs;
}

void InterferenceEpisodeTracker::add(const StepRecord& step) {
  std::map<PairKey, std::size_t> still_open;
  for (const PairContact& contact : step.contacts) {
    const PairKey key{contact.link, contact.hull, contact.obstacle};
    const auto open = open_.find(key);
    std::size_t index = 0;
    if (open != open_.end()) {
      index = open->second;
    } else {
      index = episodes_.size();
      InterferenceEpisode episode;
      episode.link = contact.link;
      episode.hull = contact.hull;
      episode.obstacle = contact.obstacle;
      episode.first_step = step.index;
      episode.first_segment = step.segment;
      episode.first_time = step.path_time;
      episodes_.push_back(episode);
    }
    InterferenceEpisode& episode = episodes_[index];
    episode.last_step = step.index;
    episode.last_segment = step.segment;
    episode.last_time = step.path_time;
    if (contact.unexpanded_collides) {
      if (!episode.first_collision_step) episode.first_collision_step = step.index;
      episode.last_collision_step = step.index;
    }
    still_open.emplace(key, index);
  }
  for (const auto& [key, index] : open_) {
    if (still_open.count(key) == 0) {
      episodes_[index].cleared_step = step.index;
      episodes_[index].cleared_time = step.path_time;
    }
  }
  open_ = std::move(still_open);
}

std::vector<SelfCollisionPair> self_contacts(const RobotCell& cell, const ProbeResult& probe) {
  std::vector<SelfCollisionPair> contacts;
  for (std::size_t p = 0; p < probe.self_pairs.size(); ++p) {
    if (probe.self_pairs[p].contact) contacts.push_back(cell.robot().self_collision_pairs[p]);
  }
  return contacts;
}

void SelfCollisionEpisodeTracker::add(const StepRecord& step) {
  std::map<SelfCollisionPair, std::size_t> still_open;
  for (const SelfCollisionPair& pair : step.self_contacts) {
    const auto open = open_.find(pair);
    std::size_t index = 0;
    if (open != open_.end()) {
      index = open->second;
    } else {
      index = episodes_.size();
      episodes_.push_back({pair, step.index, step.index, step.path_time, step.path_time});
    }
    episodes_[index].last_step = step.index;
    episodes_[index].last_time = step.path_time;
    still_open.emplace(pair, index);
  }
  open_ = std::move(still_open);
}

}  // namespace grpvss::certify

#include "cell_self_collision.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <utility>

#include "grpvss/io/srdf_file.hpp"

namespace grpvss::cell {
namespace {

using NamePair = std::pair<std::string, std::string>;

NamePair unordered(const std::string& a, const std::string& b) {
  return a < b ? NamePair{a, b} : NamePair{b, a};
}

bool names_a_hull(const RobotModel& robot, const std::string& name) {
  for (const Link& link : robot.links) {
    for (const HullPoints& hull : link.hulls) {
      if (hull.name == name) return true;
    }
  }
  return false;
}

// The link / link pairs of the cell's allowed_contacts (neither name an obstacle).
std::vector<NamePair> allowed_link_pairs(const CellDescription& cell, const RobotModel& robot) {
  std::set<std::string> obstacles;
  for (const CellObstacle& obstacle : cell.obstacles) obstacles.insert(obstacle.name);
  std::vector<NamePair> pairs;
  for (const AllowedContact& contact : cell.allowed_contacts) {
    if (obstacles.count(contact.first) != 0 || obstacles.count(contact.second) != 0) continue;
    if (names_a_hull(robot, contact.first) || names_a_hull(robot, contact.second)) {
      pairs.push_back(unordered(contact.first, contact.second));
    }
  }
  return pairs;
}

// The hull names of neighbouring chain links (a merged fixed link under its own name).
void list_adjacent(RobotModel& robot) {
  for (std::size_t a = 0; a + 1 < robot.links.size(); ++a) {
    std::set<NamePair> listed;
    for (std::size_t i = 0; i < robot.links[a].hulls.size(); ++i) {
      for (std::size_t j = 0; j < robot.links[a + 1].hulls.size(); ++j) {
        const NamePair names{hull_label(robot, static_cast<int>(a), static_cast<int>(i)),
                             hull_label(robot, static_cast<int>(a + 1), static_cast<int>(j))};
        if (!listed.insert(names).second) continue;
        robot.unverified_link_pairs.push_back({names.first, names.second, "adjacent"});
      }
    }
  }
}

// Every hull pair two or more chain links apart whose names are not disabled.
// proof: proofs/two-ball-cover.md#lemma-relative-motion (each pair is then held to it)
std::vector<SelfCollisionPair> verified_pairs(const RobotModel& robot,
                                              const std::set<NamePair>& disabled) {
  std::vector<SelfCollisionPair> pairs;
  const int links = static_cast<int>(robot.links.size());
  for (int a = 0; a < links; ++a) {
    const Link& link_a = robot.links[static_cast<std::size_t>(a)];
    for (int b = a + 2; b < links; ++b) {
      const Link& link_b = robot.links[static_cast<std::size_t>(b)];
      for (int i = 0; i < static_cast<int>(link_a.hulls.size()); ++i) {
        for (int j = 0; j < static_cast<int>(link_b.hulls.size()); ++j) {
          const NamePair names = unordered(hull_label(robot, a, i), hull_label(robot, b, j));
          if (disabled.count(names) == 0) pairs.push_back({a, i, b, j});
        }
      }
    }
  }
  return pairs;
}

}  // namespace

void resolve_self_collision(const CellDescription& cell, RobotModel& robot,
                            std::vector<io::InputWarning>& warnings) {
  robot.self_collision_pairs.clear();
  robot.unverified_link_pairs.clear();
  const std::vector<NamePair> allowed = allowed_link_pairs(cell, robot);
  if (cell.robot.source != CellRobot::Source::kUrdf) {
    if (!allowed.empty()) {
      warnings.push_back({cell.source, 0,
                          "link / link allowed contacts concern self-collision, which is not "
                          "verified for a thesis robot file: nothing to allow"});
    }
    return;
  }
  if (!cell.self_collision) return;  // the cell turned it off: no pairs, none listed
  std::set<NamePair> disabled;
  list_adjacent(robot);
  if (!cell.robot.srdf.empty()) {
    const io::SrdfFile srdf = io::read_srdf_file(cell.robot.srdf);
    warnings.insert(warnings.end(), srdf.warnings.begin(), srdf.warnings.end());
    for (const io::DisabledCollision& pair : srdf.disabled_collisions) {
      disabled.insert(unordered(pair.link1, pair.link2));
      robot.unverified_link_pairs.push_back(
          {pair.link1, pair.link2, pair.reason.empty() ? "SRDF" : "SRDF (" + pair.reason + ")"});
    }
  }
  for (const NamePair& pair : allowed) {
    disabled.insert(pair);
    robot.unverified_link_pairs.push_back({pair.first, pair.second, "allowed_contacts"});
  }
  robot.self_collision_pairs = verified_pairs(robot, disabled);
}

}  // namespace grpvss::cell

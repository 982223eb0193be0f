#include "cell_allowed_contacts.hpp"

#include <algorithm>
#include <string>

#include "grpvss/common/input_error.hpp"

namespace grpvss::cell {
namespace {

struct HullRef {
  int link = 0;
  int hull = 0;
};

// The hulls a link name stands for; `known` tells whether the name is a link at all.
std::vector<HullRef> hulls_named(const RobotModel& robot, const std::string& name, bool& known) {
  std::vector<HullRef> hulls;
  known = false;
  for (int link = 0; link < static_cast<int>(robot.links.size()); ++link) {
    const Link& chain_link = robot.links[static_cast<std::size_t>(link)];
    if (chain_link.name == name) known = true;
    for (int hull = 0; hull < static_cast<int>(chain_link.hulls.size()); ++hull) {
      if (chain_link.hulls[static_cast<std::size_t>(hull)].name == name) {
        known = true;
        hulls.push_back({link, hull});
      }
    }
  }
  return hulls;
}

std::vector<int> obstacles_named(const Environment& environment, const std::string& name) {
  std::vector<int> obstacles;
  for (int o = 0; o < static_cast<int>(environment.names.size()); ++o) {
    if (environment.names[static_cast<std::size_t>(o)] == name) obstacles.push_back(o);
  }
  return obstacles;
}

}  // namespace

std::vector<AllowedContactPair> resolve_allowed_contacts(const CellDescription& cell,
                                                         const RobotModel& robot,
                                                         const Environment& environment,
                                                         std::vector<io::InputWarning>& warnings) {
  std::vector<AllowedContactPair> pairs;
  for (const AllowedContact& contact : cell.allowed_contacts) {
    bool first_is_link = false, second_is_link = false;
    const std::vector<HullRef> first_hulls = hulls_named(robot, contact.first, first_is_link);
    const std::vector<HullRef> second_hulls = hulls_named(robot, contact.second, second_is_link);
    const std::vector<int> first_obstacles = obstacles_named(environment, contact.first);
    const std::vector<int> second_obstacles = obstacles_named(environment, contact.second);
    for (const std::string* name : {&contact.first, &contact.second}) {
      const bool is_link = name == &contact.first ? first_is_link : second_is_link;
      const bool is_obstacle =
          !(name == &contact.first ? first_obstacles : second_obstacles).empty();
      if (!is_link && !is_obstacle) {
        throw InputError(cell.source, contact.line, "a link or obstacle name of the cell",
                         "'" + *name + "'");
      }
    }
    const std::string pair = contact.first + " / " + contact.second;
    // Two links: a self-contact, resolved with the SRDF (cell_self_collision.hpp).
    if (first_obstacles.empty() && second_obstacles.empty()) continue;
    if (first_obstacles.empty() == second_obstacles.empty()) {
      warnings.push_back({cell.source, contact.line,
                          "allowed contact " + pair + " is between two obstacles: they "
                                                      "never move, nothing to allow"});
      continue;
    }
    const std::vector<HullRef>& hulls = first_obstacles.empty() ? first_hulls : second_hulls;
    const std::vector<int>& obstacles = first_obstacles.empty() ? second_obstacles : first_obstacles;
    if (hulls.empty()) {
      warnings.push_back({cell.source, contact.line,
                          "allowed contact " + pair + ": the link has no collision geometry, "
                                                      "nothing to allow"});
    }
    for (const HullRef& hull : hulls) {
      for (int obstacle : obstacles) pairs.push_back({hull.link, hull.hull, obstacle});
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace grpvss::cell

#include <set>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/core.h>

#include "cell_sections.hpp"
#include "did_you_mean.hpp"
#include "grpvss/io/cell_file.hpp"

namespace grpvss::io {
namespace {

bool is_obstacle(const std::vector<CellObstacle>& obstacles, const std::string& name) {
  for (const CellObstacle& obstacle : obstacles) {
    if (obstacle.name == name) return true;
  }
  return false;
}

// `{link: L, obstacle: O}`: O must be one of the cell's obstacles.
AllowedContact read_link_obstacle(const CellYaml& yaml, const YAML::Node& entry, const std::string& what,
                                  const std::vector<CellObstacle>& obstacles) {
  yaml.require_keys(entry, what, {"link", "obstacle"});
  AllowedContact contact;
  contact.first = yaml.name(yaml.required(entry, "link", what), what + ".link");
  const YAML::Node obstacle = yaml.required(entry, "obstacle", what);
  contact.second = yaml.name(obstacle, what + ".obstacle");
  if (!is_obstacle(obstacles, contact.second)) {
    std::vector<std::string_view> names;
    for (const CellObstacle& o : obstacles) names.emplace_back(o.name);
    yaml.fail(obstacle, what + ".obstacle",
              "the name of one of the cell's obstacles" + did_you_mean(contact.second, names));
  }
  return contact;
}

// `[A, B]`: link or obstacle names (links are checked when the robot is loaded).
AllowedContact read_name_pair(const CellYaml& yaml, const YAML::Node& entry, const std::string& what,
                              const std::vector<CellObstacle>& obstacles) {
  if (!entry.IsSequence() || entry.size() != 2) {
    yaml.fail(entry, what, "a pair [NAME, NAME] of link or obstacle names, or {link: L, obstacle: O}");
  }
  AllowedContact contact;
  contact.first = yaml.name(entry[0], what + "[0]");
  contact.second = yaml.name(entry[1], what + "[1]");
  if (is_obstacle(obstacles, contact.first) && is_obstacle(obstacles, contact.second)) {
    yaml.fail(entry, what, "at least one robot link (obstacles never move against each other)");
  }
  return contact;
}

}  // namespace

std::vector<AllowedContact> read_allowed_contacts(CellYaml& yaml, const YAML::Node& node,
                                                  const std::vector<CellObstacle>& obstacles) {
  if (!node.IsSequence() || node.size() > kMaxCellEntries) {
    yaml.fail(node, "allowed_contacts", fmt::format("a list of at most {} pairs", kMaxCellEntries));
  }
  std::vector<AllowedContact> contacts;
  std::set<std::pair<std::string, std::string>> seen;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node entry = node[i];
    const std::string what = fmt::format("allowed_contacts[{}]", i);
    AllowedContact contact = entry.IsMap() ? read_link_obstacle(yaml, entry, what, obstacles)
                                           : read_name_pair(yaml, entry, what, obstacles);
    contact.line = yaml_line(entry);
    if (contact.first == contact.second) {
      yaml.fail(entry, what, "two different names (a part always touches itself)");
    }
    const auto key = std::minmax(contact.first, contact.second);
    if (!seen.emplace(key.first, key.second).second) {
      yaml.warn(entry, fmt::format("allowed contact {} / {} is listed twice", contact.first, contact.second));
      continue;
    }
    contacts.push_back(std::move(contact));
  }
  return contacts;
}

}  // namespace grpvss::io

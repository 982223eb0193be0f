#include "grpvss/evidence/certificate_names.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "grpvss/common/input_error.hpp"

namespace grpvss::certify {
namespace {

using nlohmann::json;

std::vector<std::string> string_list(const json& object, const char* key, const std::string& file) {
  std::vector<std::string> list;
  if (!object.contains(key)) return list;
  const json& value = object.at(key);
  if (!value.is_array()) throw InputError(file, 0, std::string("a list of strings in names.") + key);
  for (const json& entry : value) {
    if (!entry.is_string()) {
      throw InputError(file, 0, std::string("a list of strings in names.") + key);
    }
    list.push_back(entry.get<std::string>());
  }
  return list;
}

}  // namespace

CertificateNames certificate_names(const RobotModel& robot, const Environment& environment) {
  CertificateNames names;
  const bool named_link = std::any_of(robot.links.begin(), robot.links.end(),
                                      [](const Link& link) { return !link.name.empty(); });
  if (named_link) {
    for (const Link& link : robot.links) names.links.push_back(link.name);
  }
  if (environment.has_names()) {
    for (std::size_t o = 0; o < environment.obstacles.size(); ++o) {
      names.obstacles.push_back(obstacle_label(environment, static_cast<int>(o)));
    }
  }
  return names;
}

json certificate_names_to_json(const CertificateNames& names) {
  json value = json::object();
  if (!names.links.empty()) value["links"] = names.links;
  if (!names.obstacles.empty()) value["obstacles"] = names.obstacles;
  return value;
}

CertificateNames certificate_names_from_json(const json& value, const std::string& file) {
  if (!value.is_object()) throw InputError(file, 0, "an object for 'names'");
  for (const auto& item : value.items()) {
    if (item.key() != "links" && item.key() != "obstacles") {
      throw InputError(file, 0, "'links' or 'obstacles' in 'names'", item.key());
    }
  }
  return {string_list(value, "links", file), string_list(value, "obstacles", file)};
}

}  // namespace grpvss::certify

#include "grpvss/io/srdf_file.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include <tinyxml2.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/text_file.hpp"

namespace grpvss::io {
namespace {

using LinkPair = std::pair<std::string, std::string>;

LinkPair unordered(const std::string& a, const std::string& b) {
  return a < b ? LinkPair{a, b} : LinkPair{b, a};
}

DisabledCollision read_pair(const tinyxml2::XMLElement& element, const std::string& file) {
  const char* link1 = element.Attribute("link1");
  const char* link2 = element.Attribute("link2");
  if (link1 == nullptr || link2 == nullptr || *link1 == '\0' || *link2 == '\0') {
    throw InputError(file, element.GetLineNum(),
                     "<" + std::string(element.Name()) + "> with attributes link1 and link2",
                     link1 == nullptr || *link1 == '\0' ? "no link1" : "no link2");
  }
  const char* reason = element.Attribute("reason");
  return {link1, link2, reason != nullptr ? reason : "", element.GetLineNum()};
}

const tinyxml2::XMLElement& robot_element(const tinyxml2::XMLDocument& document,
                                          const std::string& file) {
  const tinyxml2::XMLElement* robot = document.RootElement();
  if (robot == nullptr || std::string_view(robot->Name()) != "robot") {
    throw InputError(file, robot == nullptr ? 0 : robot->GetLineNum(), "a <robot> root element",
                     robot == nullptr ? "none" : "<" + std::string(robot->Name()) + ">");
  }
  return *robot;
}

}  // namespace

SrdfFile parse_srdf(std::string_view text, const std::string& file_name) {
  tinyxml2::XMLDocument document;
  if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    const char* reason = document.ErrorStr();
    throw InputError(file_name, document.ErrorLineNum(), "well-formed XML",
                     reason != nullptr ? reason : "a syntax error");
  }
  const tinyxml2::XMLElement& robot = robot_element(document, file_name);
  SrdfFile srdf;
  if (const char* name = robot.Attribute("name")) srdf.robot_name = name;
  std::set<LinkPair> enabled;
  std::set<LinkPair> seen;
  for (const auto* e = robot.FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    const std::string_view kind(e->Name());
    if (kind == "disable_collisions") {
      DisabledCollision pair = read_pair(*e, file_name);
      if (!seen.insert(unordered(pair.link1, pair.link2)).second) {
        srdf.warnings.push_back({file_name, pair.line, "duplicate <disable_collisions> of '" +
                                 pair.link1 + "' and '" + pair.link2 + "'"});
        continue;
      }
      srdf.disabled_collisions.push_back(std::move(pair));
    } else if (kind == "enable_collisions") {
      const DisabledCollision pair = read_pair(*e, file_name);
      enabled.insert(unordered(pair.link1, pair.link2));
    } else {
      srdf.warnings.push_back({file_name, e->GetLineNum(),
                               "ignored <" + std::string(kind) +
                                   "> (GRPVSS reads only <disable_collisions> and "
                                   "<enable_collisions>)"});
    }
  }
  auto& pairs = srdf.disabled_collisions;
  pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                             [&enabled](const DisabledCollision& p) {
                               return enabled.count(unordered(p.link1, p.link2)) > 0;
                             }),
              pairs.end());
  return srdf;
}

SrdfFile read_srdf_file(const std::string& path) { return parse_srdf(read_text_file(path), path); }

std::vector<InputWarning> srdf_links_not_in(const SrdfFile& srdf, const std::string& file_name,
                                            const std::vector<std::string>& link_names) {
  const std::set<std::string> known(link_names.begin(), link_names.end());
  std::vector<InputWarning> warnings;
  for (const DisabledCollision& pair : srdf.disabled_collisions) {
    for (const std::string* link : {&pair.link1, &pair.link2}) {
      if (known.count(*link) == 0) {
        warnings.push_back({file_name, pair.line, "<disable_collisions> names link '" + *link +
                                                      "', which the robot does not have"});
      }
    }
  }
  return warnings;
}

}  // namespace grpvss::io

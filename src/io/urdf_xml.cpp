#include "urdf_xml.hpp"

#include <charconv>
#include <cmath>
#include <utility>

#include "grpvss/common/input_error.hpp"

namespace grpvss::io {
namespace {

bool is_xml_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Splits off the next blank-separated token; empty when none is left.
std::string_view next_token(std::string_view& rest) {
  std::size_t begin = 0;
  while (begin < rest.size() && is_xml_space(rest[begin])) ++begin;
  std::size_t end = begin;
  while (end < rest.size() && !is_xml_space(rest[end])) ++end;
  const std::string_view token = rest.substr(begin, end - begin);
  rest.remove_prefix(end);
  return token;
}

// std::from_chars reads a decimal correctly rounded to the nearest double (C++17 [charconv]).
std::optional<double> parse_token(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, error] =
      std::from_chars(token.data(), token.data() + token.size(), value, std::chars_format::general);
  if (error != std::errc() || end != token.data() + token.size() || !is_accepted_magnitude(value)) {
    return std::nullopt;
  }
  return value;
}

std::string quoted_attribute(const char* text) { return std::string("\"") + text + "\""; }

}  // namespace

bool is_accepted_magnitude(double x) {
  const double magnitude = std::abs(x);
  return std::isfinite(x) && (x == 0.0 || (magnitude >= kSmallestDescriptionMagnitude &&
                                           magnitude <= kLargestDescriptionMagnitude));
}

std::optional<Eigen::Vector3d> parse_three_numbers(std::string_view text) {
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    const std::optional<double> x = parse_token(next_token(text));
    if (!x) return std::nullopt;
    v[i] = *x;
  }
  if (!next_token(text).empty()) return std::nullopt;
  return v;
}

std::optional<double> parse_one_number(std::string_view text) {
  const std::optional<double> x = parse_token(next_token(text));
  if (!x || !next_token(text).empty()) return std::nullopt;
  return x;
}

UrdfXml::UrdfXml(std::string_view text, std::string file) : file_(std::move(file)) {
  if (document_.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    const char* reason = document_.ErrorStr();
    throw InputError(file_, document_.ErrorLineNum(), "well-formed XML",
                     reason != nullptr ? reason : "a syntax error");
  }
  const tinyxml2::XMLElement* robot = document_.RootElement();
  if (robot == nullptr || std::string_view(robot->Name()) != "robot") {
    throw InputError(file_, line(robot), "a <robot> root element",
                     robot == nullptr ? "none" : "<" + std::string(robot->Name()) + ">");
  }
  first_joint_ = robot->FirstChildElement("joint");
  int order = 0;
  for (const auto* e = robot->FirstChildElement("joint"); e; e = e->NextSiblingElement("joint")) {
    if (const char* name = e->Attribute("name")) {
      joints_.emplace(name, e);
      joint_order_.emplace(name, order);
    }
    ++order;
  }
  for (const auto* e = robot->FirstChildElement("link"); e; e = e->NextSiblingElement("link")) {
    if (const char* name = e->Attribute("name")) links_.emplace(name, e);
  }
}

const tinyxml2::XMLElement* UrdfXml::joint(const std::string& name) const {
  const auto it = joints_.find(name);
  return it == joints_.end() ? nullptr : it->second;
}

const tinyxml2::XMLElement* UrdfXml::link(const std::string& name) const {
  const auto it = links_.find(name);
  return it == links_.end() ? nullptr : it->second;
}

int UrdfXml::joint_order(const std::string& name) const {
  const auto it = joint_order_.find(name);
  return it == joint_order_.end() ? -1 : it->second;
}

const tinyxml2::XMLElement* UrdfXml::collision(const std::string& link_name, int index) const {
  const tinyxml2::XMLElement* element = link(link_name);
  if (element == nullptr) return nullptr;
  const tinyxml2::XMLElement* collision = element->FirstChildElement("collision");
  for (int k = 0; k < index && collision != nullptr; ++k) {
    collision = collision->NextSiblingElement("collision");
  }
  return collision;
}

int UrdfXml::line(const tinyxml2::XMLElement* element) {
  return element == nullptr ? 0 : element->GetLineNum();
}

Eigen::Vector3d UrdfXml::origin_rpy(const tinyxml2::XMLElement& element,
                                    const std::string& owner) const {
  const tinyxml2::XMLElement* origin = element.FirstChildElement("origin");
  if (origin == nullptr) return Eigen::Vector3d::Zero();
  const char* rpy = origin->Attribute("rpy");
  if (rpy == nullptr) return Eigen::Vector3d::Zero();
  const std::optional<Eigen::Vector3d> v = parse_three_numbers(rpy);
  if (!v) {
    throw InputError(file_, line(origin),
                     "<origin rpy> of " + owner + " as three numbers, each 0 or of magnitude "
                     "within [1e-300, 1e9]",
                     quoted_attribute(rpy));
  }
  return *v;
}

double UrdfXml::number_attribute(const tinyxml2::XMLElement& element, const char* attribute,
                                 double default_value, const std::string& owner) const {
  const char* text = element.Attribute(attribute);
  if (text == nullptr) return default_value;
  const std::optional<double> x = parse_one_number(text);
  if (!x) {
    throw InputError(file_, line(&element),
                     std::string(attribute) + " of " + owner + " as a number, 0 or of magnitude "
                     "within [1e-300, 1e9]",
                     quoted_attribute(text));
  }
  return *x;
}

}  // namespace grpvss::io

#include "support/json_structure_check.hpp"

#include <regex>
#include <stdexcept>

namespace grpvss::test {

namespace {

using nlohmann::json;

bool has_type(const json& value, const std::string& type) {
  if (type == "object") return value.is_object();
  if (type == "array") return value.is_array();
  if (type == "string") return value.is_string();
  if (type == "boolean") return value.is_boolean();
  if (type == "null") return value.is_null();
  if (type == "integer") return value.is_number_integer();
  if (type == "number") return value.is_number();
  throw std::invalid_argument("schema type " + type + " not supported");
}

class Checker {
 public:
  explicit Checker(const json& root) : root_(root) {}

  void check(const json& value, const json& schema, const std::string& where) {
    if (schema.contains("$ref")) {
      const std::string ref = schema["$ref"];
      const std::string prefix = "#/$defs/";
      if (ref.rfind(prefix, 0) != 0) throw std::invalid_argument("unsupported $ref " + ref);
      check(value, root_.at("$defs").at(ref.substr(prefix.size())), where);
      return;
    }
    if (schema.contains("oneOf")) {
      int matches = 0;
      for (const json& option : schema["oneOf"]) {
        Checker inner(root_);
        inner.check(value, option, where);
        if (inner.errors.empty()) ++matches;
      }
      if (matches != 1) fail(where, "matches " + std::to_string(matches) + " oneOf options");
    }
    if (schema.contains("type") && !type_matches(value, schema["type"])) {
      fail(where, "type is not " + schema["type"].dump());
      return;
    }
    if (schema.contains("const") && value != schema["const"]) {
      fail(where, "is not " + schema["const"].dump());
    }
    if (schema.contains("enum")) {
      bool found = false;
      for (const json& option : schema["enum"]) found = found || value == option;
      if (!found) fail(where, value.dump() + " not in enum");
    }
    if (schema.contains("pattern") && value.is_string() &&
        !std::regex_search(value.get<std::string>(), std::regex(schema["pattern"].get<std::string>()))) {
      fail(where, "does not match " + schema["pattern"].get<std::string>());
    }
    if (value.is_object()) check_object(value, schema, where);
    if (value.is_array()) check_array(value, schema, where);
  }

  std::vector<std::string> errors;

 private:
  static bool type_matches(const json& value, const json& type) {
    if (type.is_string()) return has_type(value, type);
    for (const json& option : type) {
      if (has_type(value, option)) return true;
    }
    return false;
  }

  void check_object(const json& value, const json& schema, const std::string& where) {
    if (schema.contains("required")) {
      for (const json& name : schema["required"]) {
        if (!value.contains(name.get<std::string>())) fail(where, "missing " + name.dump());
      }
    }
    const json properties = schema.value("properties", json::object());
    for (const auto& [name, member] : value.items()) {
      if (properties.contains(name)) {
        check(member, properties[name], where + "/" + name);
      } else if (schema.contains("additionalProperties") && schema["additionalProperties"] == false) {
        fail(where, "undocumented field \"" + name + "\"");
      }
    }
  }

  void check_array(const json& value, const json& schema, const std::string& where) {
    if (schema.contains("minItems") && value.size() < schema["minItems"].get<std::size_t>()) {
      fail(where, "fewer than " + schema["minItems"].dump() + " items");
    }
    if (schema.contains("maxItems") && value.size() > schema["maxItems"].get<std::size_t>()) {
      fail(where, "more than " + schema["maxItems"].dump() + " items");
    }
    if (!schema.contains("items")) return;
    for (std::size_t i = 0; i < value.size(); ++i) {
      check(value[i], schema["items"], where + "/" + std::to_string(i));
    }
  }

  void fail(const std::string& where, const std::string& what) {
    errors.push_back((where.empty() ? "/" : where) + ": " + what);
  }

  const json& root_;
};

}  // namespace

std::vector<std::string> check_json_structure(const json& instance, const json& schema) {
  Checker checker(schema);
  checker.check(instance, schema, "");
  return checker.errors;
}

}  // namespace grpvss::test

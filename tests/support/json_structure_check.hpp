#pragma once
// A small structural checker for the subset of JSON Schema that docs/report.schema.json
// uses: type, required, properties, additionalProperties: false, items, enum, const, $ref to
// "#/$defs/...", oneOf, minItems/maxItems, pattern. Not a general validator.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace grpvss::test {

/// Every violation of `schema` by `instance`, as "<json pointer>: <what>"; empty if none.
std::vector<std::string> check_json_structure(const nlohmann::json& instance,
                                              const nlohmann::json& schema);

}  // namespace grpvss::test

#pragma once
/// \file
/// \brief The sections of a cell file (docs/cell-format.md), each read from its YAML node
/// by one function: the robot, the obstacles, the allowed contacts and the checks of the
/// lengths against the declared unit.

#include <cstddef>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "cell_yaml.hpp"
#include "grpvss/model/cell_description.hpp"

namespace grpvss::io {

/// Most joints a cell's `home` and `acceleration` may list, and most `package_paths`.
inline constexpr std::size_t kMaxCellJoints = 64;

/// `units:` — m, mm or in.
LengthUnit read_length_unit(const CellYaml& yaml, const YAML::Node& node, const char* what);

/// `robot:` — its file, frames, home and accelerations.
CellRobot read_cell_robot(const CellYaml& yaml, const YAML::Node& node);

/// `obstacles:` — named shapes with poses; names unique. Lengths stay in `units`; mesh
/// `units` become a scale into them.
std::vector<CellObstacle> read_cell_obstacles(CellYaml& yaml, const YAML::Node& node,
                                              LengthUnit units);

/// `allowed_contacts:` — pairs `[a, b]` (link or obstacle names) or `{link: L, obstacle: O}`
/// (O must be one of `obstacles`).
std::vector<AllowedContact> read_allowed_contacts(CellYaml& yaml, const YAML::Node& node,
                                                  const std::vector<CellObstacle>& obstacles);

/// Warnings for lengths that look like the wrong unit (docs/cell-format.md#unit-warnings).
void warn_about_unit_sizes(CellYaml& yaml, const CellDescription& cell);

/// The key node of `key` in `map` (for errors located at the key), or an undefined node.
YAML::Node key_node(const YAML::Node& map, const char* key);

}  // namespace grpvss::io

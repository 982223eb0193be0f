#include <map>
#include <string>

#include <fmt/core.h>

#include "cell_sections.hpp"
#include "grpvss/io/cell_file.hpp"
#include "grpvss/io/length_unit.hpp"

namespace grpvss::io {
namespace {

struct ShapeKey {
  const char* key;
  CellObstacle::Shape shape;
};
constexpr ShapeKey kShapeKeys[] = {{"box", CellObstacle::Shape::kBox},
                                   {"cylinder", CellObstacle::Shape::kCylinder},
                                   {"sphere", CellObstacle::Shape::kSphere},
                                   {"mesh", CellObstacle::Shape::kMesh},
                                   {"thesis_environment", CellObstacle::Shape::kThesisEnvironment}};
constexpr const char* kMeshOnlyKeys[] = {"scale", "units", "decompose"};

// The one shape key of an obstacle entry.
CellObstacle::Shape shape_of(const CellYaml& yaml, const YAML::Node& entry, const std::string& what) {
  const ShapeKey* found = nullptr;
  for (const ShapeKey& candidate : kShapeKeys) {
    if (!entry[candidate.key]) continue;
    if (found != nullptr) {
      yaml.fail(key_node(entry, candidate.key), what,
                fmt::format("one shape (it already is a {})", found->key));
    }
    found = &candidate;
  }
  if (found == nullptr) {
    yaml.fail_at(yaml_line(entry),
                 what + ": one shape key among box, cylinder, sphere, mesh, thesis_environment",
                 "none");
  }
  return found->shape;
}

void read_mesh_scale(const CellYaml& yaml, const YAML::Node& entry, const std::string& what,
                     LengthUnit cell_units, CellObstacle& obstacle) {
  const YAML::Node scale = entry["scale"];
  const YAML::Node units = entry["units"];
  if (scale && units) yaml.fail(key_node(entry, "units"), what, "either scale or units, not both");
  if (units) {
    const LengthUnit mesh_units = read_length_unit(yaml, units, "units");
    obstacle.mesh_units = mesh_units;
    obstacle.scale.setConstant(length_unit_factor(mesh_units, cell_units));
    obstacle.scale_is_exact = length_unit_factor_is_exact(mesh_units, cell_units);
    return;
  }
  if (!scale) return;
  const std::string name = what + ".scale";
  if (scale.IsScalar()) {
    obstacle.scale.setConstant(yaml.positive(scale, name));
    obstacle.scale_is_exact = CellYaml::is_exact_decimal_literal(scale);
    return;
  }
  if (!scale.IsSequence() || scale.size() != 3) yaml.fail(scale, name, "a number > 0 or a list of 3");
  obstacle.scale_is_exact = true;
  for (int k = 0; k < 3; ++k) {
    obstacle.scale[k] = yaml.positive(scale[k], fmt::format("{}[{}]", name, k));
    obstacle.scale_is_exact = obstacle.scale_is_exact && CellYaml::is_exact_decimal_literal(scale[k]);
  }
}

MeshDecomposition read_decomposition(const CellYaml& yaml, const YAML::Node& node, const std::string& what) {
  const std::string text = yaml.name(node, what);
  if (text == "hull") return MeshDecomposition::kHull;
  if (text == "parts") return MeshDecomposition::kParts;
  if (text == "exact") return MeshDecomposition::kExact;
  yaml.fail(node, what, "one of hull, parts, exact");
}

void read_mesh(const CellYaml& yaml, const YAML::Node& entry, const std::string& what,
               LengthUnit cell_units, CellObstacle& obstacle) {
  obstacle.file = yaml.file(entry["mesh"], what + ".mesh");
  read_mesh_scale(yaml, entry, what, cell_units, obstacle);
  if (const YAML::Node decompose = entry["decompose"]) {
    obstacle.decompose = read_decomposition(yaml, decompose, what + ".decompose");
  }
}

void read_shape(const CellYaml& yaml, const YAML::Node& entry, const std::string& what,
                LengthUnit cell_units, CellObstacle& obstacle) {
  switch (obstacle.shape) {
    case CellObstacle::Shape::kBox: {
      const YAML::Node box = entry["box"];
      if (!box.IsSequence() || box.size() != 3) yaml.fail(box, what + ".box", "a list of 3 sizes [x, y, z]");
      for (int k = 0; k < 3; ++k) obstacle.box_size[k] = yaml.positive(box[k], fmt::format("{}.box[{}]", what, k));
      return;
    }
    case CellObstacle::Shape::kCylinder: {
      const YAML::Node cylinder = entry["cylinder"];
      const std::string name = what + ".cylinder";
      yaml.require_keys(cylinder, name, {"radius", "length"});
      obstacle.radius = yaml.positive(yaml.required(cylinder, "radius", name), name + ".radius");
      obstacle.length = yaml.positive(yaml.required(cylinder, "length", name), name + ".length");
      return;
    }
    case CellObstacle::Shape::kSphere: {
      const YAML::Node sphere = entry["sphere"];
      const std::string name = what + ".sphere";
      yaml.require_keys(sphere, name, {"radius"});
      obstacle.radius = yaml.positive(yaml.required(sphere, "radius", name), name + ".radius");
      return;
    }
    case CellObstacle::Shape::kMesh: read_mesh(yaml, entry, what, cell_units, obstacle); return;
    case CellObstacle::Shape::kThesisEnvironment:
      obstacle.file = yaml.file(entry["thesis_environment"], what + ".thesis_environment");
      return;
  }
}

// Keys that only some shapes take.
void check_shape_keys(const CellYaml& yaml, const YAML::Node& entry, const std::string& what,
                      CellObstacle::Shape shape) {
  if (shape != CellObstacle::Shape::kMesh) {
    for (const char* key : kMeshOnlyKeys) {
      if (entry[key]) yaml.fail(key_node(entry, key), what, fmt::format("'{}' only with a mesh", key));
    }
  }
  if (shape == CellObstacle::Shape::kThesisEnvironment && entry["pose"]) {
    yaml.fail(key_node(entry, "pose"), what,
              "no pose with thesis_environment (its hulls are in world coordinates)");
  }
}

CellObstacle read_obstacle(const CellYaml& yaml, const YAML::Node& entry, std::size_t index,
                           LengthUnit cell_units) {
  const std::string position = fmt::format("obstacles[{}]", index);
  yaml.require_keys(entry, position,
                    {"name", "box", "cylinder", "sphere", "mesh", "thesis_environment", "pose",
                     "scale", "units", "decompose"});
  CellObstacle obstacle;
  obstacle.line = yaml_line(entry);
  obstacle.name = yaml.name(yaml.required(entry, "name", position), position + ".name");
  const std::string what = fmt::format("obstacle '{}'", obstacle.name);
  obstacle.shape = shape_of(yaml, entry, what);
  check_shape_keys(yaml, entry, what, obstacle.shape);
  read_shape(yaml, entry, what, cell_units, obstacle);
  if (const YAML::Node pose = entry["pose"]) obstacle.pose = yaml.pose(pose, what + ".pose");
  return obstacle;
}

}  // namespace

std::vector<CellObstacle> read_cell_obstacles(CellYaml& yaml, const YAML::Node& node, LengthUnit units) {
  if (!node.IsSequence() || node.size() > kMaxCellEntries) {
    yaml.fail(node, "obstacles", fmt::format("a list of at most {} obstacles", kMaxCellEntries));
  }
  std::vector<CellObstacle> obstacles;
  std::map<std::string, int> line_of_name;
  for (std::size_t i = 0; i < node.size(); ++i) {
    obstacles.push_back(read_obstacle(yaml, node[i], i, units));
    const CellObstacle& obstacle = obstacles.back();
    const auto [first, inserted] = line_of_name.emplace(obstacle.name, obstacle.line);
    if (!inserted) {
      yaml.fail(node[i]["name"], "obstacle names",
                fmt::format("each name once ('{}' is also the obstacle on line {})", obstacle.name,
                            first->second));
    }
  }
  return obstacles;
}

}  // namespace grpvss::io

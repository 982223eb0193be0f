#include "grpvss/io/cell_file.hpp"

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cell_sections.hpp"
#include "cell_yaml.hpp"
#include "did_you_mean.hpp"
#include "yaml_document.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/length_unit.hpp"
#include "grpvss/io/text_file.hpp"

namespace grpvss::io {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Spellings users write for the three units.
std::string unit_suggestion(const std::string& text) {
  for (const char* metre : {"metre", "meter", "metres", "meters", "M"}) {
    if (text == metre) return " (did you mean 'm'?)";
  }
  for (const char* millimetre : {"millimetre", "millimeter", "millimetres", "millimeters", "MM"}) {
    if (text == millimetre) return " (did you mean 'mm'?)";
  }
  for (const char* inch : {"inch", "inches", "IN", "\""}) {
    if (text == inch) return " (did you mean 'in'?)";
  }
  return did_you_mean(text, {"m", "mm", "in"});
}

ThesisConstants read_thesis_constants(const CellYaml& yaml, const YAML::Node& node) {
  const char* what = "thesis_constants";
  yaml.require_keys(node, what, {"smallest_angle", "smallest_thickness"});
  ThesisConstants constants;
  constants.line = yaml_line(node);
  const YAML::Node angle = yaml.required(node, "smallest_angle", what);
  constants.smallest_angle = yaml.positive(angle, "thesis_constants.smallest_angle");
  if (!(constants.smallest_angle < kPi)) {
    yaml.fail(angle, "thesis_constants.smallest_angle", "an angle in radians, 0 < angle < pi");
  }
  constants.smallest_thickness =
      yaml.positive(yaml.required(node, "smallest_thickness", what), "thesis_constants.smallest_thickness");
  return constants;
}

CellMotion read_motion(const CellYaml& yaml, const YAML::Node& node) {
  yaml.require_keys(node, "motion", {"cp_speed", "cp_spacing"});
  CellMotion motion;
  if (const YAML::Node speed = node["cp_speed"]) motion.cp_speed = yaml.positive(speed, "motion.cp_speed");
  if (const YAML::Node spacing = node["cp_spacing"]) {
    motion.cp_spacing = yaml.positive(spacing, "motion.cp_spacing");
  }
  return motion;
}

void read_cell_units(const CellYaml& yaml, const YAML::Node& root, CellDescription& cell) {
  const YAML::Node units = yaml.required(root, "units", "the cell");
  cell.units = read_length_unit(yaml, units, "units");
  cell.units_line = yaml_line(units);
  cell.metres_per_unit = length_unit_factor(cell.units, LengthUnit::kMetre);
  cell.metres_per_unit_is_exact = length_unit_factor_is_exact(cell.units, LengthUnit::kMetre);
}

CellDescription read_cell(CellYaml& yaml, const YAML::Node& root) {
  yaml.require_keys(root, "the cell",
                    {"units", "robot", "obstacles", "allowed_contacts", "tolerance", "motion",
                     "thesis_constants", "self_collision"});
  CellDescription cell;
  cell.source = yaml.file_name();
  read_cell_units(yaml, root, cell);
  cell.robot = read_cell_robot(yaml, yaml.required(root, "robot", "the cell"));
  if (const YAML::Node obstacles = root["obstacles"]) {
    cell.obstacles = read_cell_obstacles(yaml, obstacles, cell.units);
  }
  if (const YAML::Node contacts = root["allowed_contacts"]) {
    cell.allowed_contacts = read_allowed_contacts(yaml, contacts, cell.obstacles);
  }
  if (const YAML::Node tolerance = root["tolerance"]) {
    cell.tolerance = yaml.positive(tolerance, "tolerance");
    cell.tolerance_line = yaml_line(tolerance);
  }
  if (const YAML::Node self_collision = root["self_collision"]) {
    const std::string text = self_collision.IsScalar() ? self_collision.Scalar() : "";
    if (text != "true" && text != "false") yaml.fail(self_collision, "self_collision", "true or false");
    cell.self_collision = text == "true";
  }
  if (const YAML::Node motion = root["motion"]) cell.motion = read_motion(yaml, motion);
  if (const YAML::Node constants = root["thesis_constants"]) {
    cell.thesis_constants = read_thesis_constants(yaml, constants);
  }
  warn_about_unit_sizes(yaml, cell);
  return cell;
}

// The one YAML document of the text (the caller turns yaml-cpp's exceptions into InputErrors).
YAML::Node load_document(std::string_view text, const std::string& file_name) {
  if (text.size() > kMaxCellFileBytes) {
    throw InputError(file_name, 0, fmt::format("a cell file of at most {} bytes", kMaxCellFileBytes),
                     fmt::format("{} bytes", text.size()));
  }
  return load_single_yaml_document(text, file_name, "the cell");
}

std::string folder_of(const std::string& file_name) {
  return std::filesystem::path(file_name).parent_path().string();
}

}  // namespace

LengthUnit read_length_unit(const CellYaml& yaml, const YAML::Node& node, const char* what) {
  const std::string text = yaml.name(node, what);
  if (const auto unit = length_unit_from_name(text)) return *unit;
  yaml.fail(node, what, "one of m, mm, in" + unit_suggestion(text));
}

CellReadResult parse_cell(std::string_view text, const std::string& file_name, bool check_files) {
  CellYaml yaml(file_name, folder_of(file_name), check_files);
  try {
    const YAML::Node root = load_document(text, file_name);
    CellReadResult result;
    result.cell = read_cell(yaml, root);
    result.warnings = yaml.warnings();
    return result;
  } catch (const YAML::Exception& error) {
    const int line = error.mark.is_null() ? 0 : error.mark.line + 1;
    throw InputError(file_name, line, "well-formed YAML", error.msg);
  }
}

CellReadResult read_cell_file(const std::string& path) {
  return parse_cell(read_text_file(path), path, true);
}

}  // namespace grpvss::io

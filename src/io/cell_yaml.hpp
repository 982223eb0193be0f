#pragma once
/// \file
/// \brief The typed reading of cell-file YAML nodes (src/io/cell_*.cpp): keys, numbers,
/// vectors, names, files and poses, each failing with an InputError that names the cell file,
/// the node's line and what was expected (docs/cell-format.md#errors).

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include "grpvss/io/input_warning.hpp"
#include "grpvss/model/cell_description.hpp"

namespace grpvss::io {

/// 1-based line of a node in its file (0 when yaml-cpp has no mark for it).
int yaml_line(const YAML::Node& node);

/// What a node is, for messages: `'text'`, `a mapping`, `a list of 2 entries`, `nothing`.
std::string describe_node(const YAML::Node& node);

/// \brief Reads the nodes of one cell file.
class CellYaml {
 public:
  CellYaml(std::string file_name, std::string directory, bool check_files);

  const std::string& file_name() const { return file_name_; }

  /// Throws InputError(file, line of `at`, what + ": " + expected, describe(at)).
  [[noreturn]] void fail(const YAML::Node& at, std::string_view what, std::string_view expected) const;
  /// Throws InputError(file, line, expected, found).
  [[noreturn]] void fail_at(int line, std::string expected, std::string found = {}) const;

  /// Requires a mapping whose keys are plain scalars, each once, each in `allowed`.
  void require_keys(const YAML::Node& map, std::string_view what,
                    std::initializer_list<std::string_view> allowed) const;
  /// Requires that `map` holds `key` (map must be a mapping).
  const YAML::Node required(const YAML::Node& map, const char* key, std::string_view what) const;

  /// A finite number x with x = 0 or 1e-300 <= |x| <= 1e9, from a plain decimal scalar.
  double number(const YAML::Node& node, std::string_view what) const;
  /// number() > 0.
  double positive(const YAML::Node& node, std::string_view what) const;
  /// A list of exactly three numbers.
  Eigen::Vector3d vector3(const YAML::Node& node, std::string_view what) const;
  /// A list of 1..max_count numbers.
  std::vector<double> numbers(const YAML::Node& node, std::string_view what,
                              std::size_t max_count) const;
  /// A non-empty scalar of printable characters (at most 256), e.g. a name.
  std::string name(const YAML::Node& node, std::string_view what) const;
  /// A scalar written as a plain decimal (optional sign, digits, optional point and digits;
  /// at most 15 digits) whose value is a double exactly: 0.5, 0.25, 2, 1000, but not 0.001.
  /// False for anything else (an exponent, more digits), which may be exact but is not
  /// claimed to be.
  static bool is_exact_decimal_literal(const YAML::Node& node);

  /// Records a warning at the line of `at` (returned with the description).
  void warn(const YAML::Node& at, std::string text);
  void warn_at(int line, std::string text);
  const std::vector<InputWarning>& warnings() const { return warnings_; }

  /// A file reference (path relative to the cell's folder, `file://`, or `package://` through
  /// `packages`), resolved; must exist unless the reader does not check files.
  std::string file(const YAML::Node& node, std::string_view what,
                   const std::vector<std::string>& packages = {}) const;
  /// A directory relative to the cell's folder (or absolute), which must exist when checked.
  std::string directory(const YAML::Node& node, std::string_view what) const;

  /// `{xyz: [..], rpy: [..]}` or `{xyz: [..], quaternion: {w, x, y, z}}` (each key optional;
  /// rpy and quaternion exclusive).
  CellPose pose(const YAML::Node& node, std::string_view what) const;

 private:
  std::string file_name_;
  std::string directory_;
  bool check_files_;
  std::vector<InputWarning> warnings_;
};

}  // namespace grpvss::io

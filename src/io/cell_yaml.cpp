#include "cell_yaml.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <set>
#include <system_error>
#include <utility>

#include <fmt/core.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/resource_path.hpp"
#include "did_you_mean.hpp"

namespace grpvss::io {
namespace {

constexpr double kMaxMagnitude = 1e9;
// Below it a number is subnormal-adjacent: Lemma D (proofs/urdf-frames.md#decimal-inputs)
// needs 0 or a magnitude in [1e-300, 1e9].
constexpr double kMinMagnitude = 1e-300;
constexpr std::size_t kMaxNameLength = 256;

std::string quote_text(std::string_view text) {
  constexpr std::size_t kShown = 60;
  if (text.size() <= kShown) return fmt::format("'{}'", text);
  return fmt::format("'{}...'", text.substr(0, kShown));
}

std::string joined(std::initializer_list<std::string_view> words) {
  std::string text;
  for (const std::string_view word : words) {
    if (!text.empty()) text += ", ";
    text += word;
  }
  return text;
}

bool printable(std::string_view text) {
  for (const char c : text) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return false;
  }
  return true;
}

}  // namespace

int yaml_line(const YAML::Node& node) {
  if (!node.IsDefined()) return 0;
  const YAML::Mark mark = node.Mark();
  return mark.line < 0 ? 0 : mark.line + 1;
}

std::string describe_node(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsScalar()) return quote_text(node.Scalar());
  if (node.IsMap()) return "a mapping";
  const std::size_t size = node.size();
  return size == 1 ? "a list of 1 entry" : fmt::format("a list of {} entries", size);
}

CellYaml::CellYaml(std::string file_name, std::string directory, bool check_files)
    : file_name_(std::move(file_name)), directory_(std::move(directory)), check_files_(check_files) {}

void CellYaml::fail(const YAML::Node& at, std::string_view what, std::string_view expected) const {
  throw InputError(file_name_, yaml_line(at), fmt::format("{}: {}", what, expected), describe_node(at));
}

void CellYaml::fail_at(int line, std::string expected, std::string found) const {
  throw InputError(file_name_, line, std::move(expected), std::move(found));
}

void CellYaml::require_keys(const YAML::Node& map, std::string_view what,
                            std::initializer_list<std::string_view> allowed) const {
  if (!map.IsMap()) fail(map, what, "a mapping with keys " + joined(allowed));
  std::set<std::string> seen;
  for (auto entry = map.begin(); entry != map.end(); ++entry) {
    const YAML::Node key = entry->first;
    if (!key.IsScalar()) fail(key, what, "a key among " + joined(allowed));
    const std::string& text = key.Scalar();
    const std::vector<std::string_view> names(allowed);
    if (std::find(names.begin(), names.end(), text) == names.end()) {
      fail(key, what, "a key among " + joined(allowed) + did_you_mean(text, names));
    }
    if (!seen.insert(text).second) fail(key, what, "each key once (a second '" + text + "')");
  }
}

const YAML::Node CellYaml::required(const YAML::Node& map, const char* key,
                                    std::string_view what) const {
  const YAML::Node value = map[key];
  if (!value.IsDefined()) {
    fail_at(yaml_line(map), fmt::format("{}: the key '{}'", what, key), "a mapping without it");
  }
  return value;
}

double CellYaml::number(const YAML::Node& node, std::string_view what) const {
  const std::string_view expected = "a finite number, 0 or 1e-300 <= |x| <= 1e9";
  if (!node.IsScalar()) fail(node, what, expected);
  std::string_view text(node.Scalar());
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value,
                                            std::chars_format::general);
  const bool whole = error == std::errc() && end == text.data() + text.size() && !text.empty();
  const double magnitude = std::fabs(value);
  if (!whole || !std::isfinite(value) || magnitude > kMaxMagnitude ||
      (magnitude != 0.0 && magnitude < kMinMagnitude)) {
    fail(node, what, expected);
  }
  return value;
}

double CellYaml::positive(const YAML::Node& node, std::string_view what) const {
  const double value = number(node, what);
  if (!(value > 0.0)) fail(node, what, "a number > 0");
  return value;
}

std::vector<double> CellYaml::numbers(const YAML::Node& node, std::string_view what,
                                      std::size_t max_count) const {
  if (!node.IsSequence() || node.size() == 0 || node.size() > max_count) {
    fail(node, what, fmt::format("a list of 1 to {} numbers", max_count));
  }
  std::vector<double> values;
  values.reserve(node.size());
  for (std::size_t i = 0; i < node.size(); ++i) {
    values.push_back(number(node[i], fmt::format("{}[{}]", what, i)));
  }
  return values;
}

Eigen::Vector3d CellYaml::vector3(const YAML::Node& node, std::string_view what) const {
  if (!node.IsSequence() || node.size() != 3) fail(node, what, "a list of 3 numbers [x, y, z]");
  return {number(node[0], fmt::format("{}[0]", what)), number(node[1], fmt::format("{}[1]", what)),
          number(node[2], fmt::format("{}[2]", what))};
}

std::string CellYaml::name(const YAML::Node& node, std::string_view what) const {
  const std::string expected =
      fmt::format("a non-empty name of at most {} printable characters", kMaxNameLength);
  if (!node.IsScalar()) fail(node, what, expected);
  const std::string& text = node.Scalar();
  if (text.empty() || text.size() > kMaxNameLength || !printable(text)) fail(node, what, expected);
  return text;
}

bool CellYaml::is_exact_decimal_literal(const YAML::Node& node) {
  if (!node.IsScalar()) return false;
  std::string_view text(node.Scalar());
  if (!text.empty() && (text.front() == '+' || text.front() == '-')) text.remove_prefix(1);
  const std::size_t point = text.find('.');
  std::string digits(text.substr(0, point));
  std::size_t fraction_digits = 0;
  if (point != std::string_view::npos) {
    fraction_digits = text.size() - point - 1;
    digits += text.substr(point + 1);
  }
  // N < 10^15 < 2^53 digits in all: N / 10^k is a double exactly when 5^k divides N (the
  // quotient is then an integer < 2^53 over a power of two).
  if (digits.empty() || digits.size() > 15) return false;
  std::uint64_t numerator = 0;
  for (const char c : digits) {
    if (c < '0' || c > '9') return false;
    numerator = numerator * 10 + static_cast<std::uint64_t>(c - '0');
  }
  std::uint64_t five_power = 1;
  for (std::size_t k = 0; k < fraction_digits; ++k) five_power *= 5;
  return numerator % five_power == 0;
}

void CellYaml::warn(const YAML::Node& at, std::string text) {
  warnings_.push_back({file_name_, yaml_line(at), std::move(text)});
}

void CellYaml::warn_at(int line, std::string text) {
  warnings_.push_back({file_name_, line, std::move(text)});
}

std::string CellYaml::file(const YAML::Node& node, std::string_view what,
                           const std::vector<std::string>& packages) const {
  const std::string reference = name(node, what);
  const ResolvedResource resolved = resolve_resource(reference, directory_, packages);
  if (!resolved.path.empty()) return resolved.path;
  if (!check_files_ && !resolved.tried.empty()) return resolved.tried.front();
  std::string tried;
  for (const std::string& candidate : resolved.tried) tried += (tried.empty() ? "" : ", ") + candidate;
  throw InputError(file_name_, yaml_line(node),
                   fmt::format("{}: an existing file (a path relative to the cell file's folder, "
                               "file:// or package://)", what),
                   fmt::format("{} (tried: {})", quote_text(reference), tried.empty() ? "nothing" : tried));
}

std::string CellYaml::directory(const YAML::Node& node, std::string_view what) const {
  const std::string reference = name(node, what);
  namespace fs = std::filesystem;
  const fs::path path(reference);
  const std::string resolved = (path.is_absolute() || directory_.empty())
                                   ? path.lexically_normal().string()
                                   : (fs::path(directory_) / path).lexically_normal().string();
  std::error_code error;
  if (check_files_ && !fs::is_directory(resolved, error)) {
    fail(node, what, fmt::format("an existing directory (looked at {})", resolved));
  }
  return resolved;
}

CellPose CellYaml::pose(const YAML::Node& node, std::string_view what) const {
  require_keys(node, what, {"xyz", "rpy", "quaternion"});
  CellPose pose;
  pose.line = yaml_line(node);
  if (node["xyz"]) pose.xyz = vector3(node["xyz"], fmt::format("{}.xyz", what));
  if (node["rpy"] && node["quaternion"]) {
    fail(node["quaternion"], what, "either rpy or quaternion, not both");
  }
  if (node["rpy"]) pose.rpy = vector3(node["rpy"], fmt::format("{}.rpy", what));
  if (const YAML::Node q = node["quaternion"]) {
    const std::string name = fmt::format("{}.quaternion", what);
    require_keys(q, name, {"w", "x", "y", "z"});
    Eigen::Vector4d wxyz;
    const char* keys[] = {"w", "x", "y", "z"};
    for (int k = 0; k < 4; ++k) wxyz[k] = number(required(q, keys[k], name), name + "." + keys[k]);
    if (wxyz.isZero(0.0)) fail(q, name, "a nonzero quaternion {w, x, y, z}");
    pose.quaternion = wxyz;
  }
  return pose;
}

}  // namespace grpvss::io

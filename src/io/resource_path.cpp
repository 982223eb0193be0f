#include "grpvss/io/resource_path.hpp"

#include <cstdlib>
#include <filesystem>
#include <string_view>
#include <system_error>

namespace grpvss::io {
namespace {

namespace fs = std::filesystem;

bool is_existing_file(const fs::path& path) {
  std::error_code error;
  return fs::is_regular_file(path, error) && !error;
}

std::string against(const std::string& base_directory, const std::string& path) {
  const fs::path p(path);
  if (p.is_absolute() || base_directory.empty()) return p.lexically_normal().string();
  return (fs::path(base_directory) / p).lexically_normal().string();
}

// The last component of D, ignoring a trailing separator ("/a/pkg/" -> "pkg").
std::string last_component(const std::string& directory) {
  fs::path p(directory);
  if (!p.has_filename()) p = p.parent_path();
  return p.filename().string();
}

ResolvedResource resolve_package(std::string_view rest, const std::vector<std::string>& directories) {
  ResolvedResource result;
  const std::size_t slash = rest.find('/');
  if (slash == std::string_view::npos || slash == 0 || slash + 1 == rest.size()) return result;
  const std::string name(rest.substr(0, slash));
  const std::string inside(rest.substr(slash + 1));
  for (const std::string& directory : directories) {
    std::vector<fs::path> candidates{fs::path(directory) / name / inside};
    if (last_component(directory) == name) candidates.push_back(fs::path(directory) / inside);
    for (const fs::path& candidate : candidates) {
      result.tried.push_back(candidate.lexically_normal().string());
      if (is_existing_file(candidate)) {
        result.path = result.tried.back();
        return result;
      }
    }
  }
  return result;
}

ResolvedResource resolve_path(const std::string& path, const std::string& base_directory) {
  ResolvedResource result;
  result.tried.push_back(against(base_directory, path));
  if (is_existing_file(result.tried.back())) result.path = result.tried.back();
  return result;
}

}  // namespace

ResolvedResource resolve_resource(const std::string& reference, const std::string& base_directory,
                                  const std::vector<std::string>& package_directories) {
  constexpr std::string_view kPackage = "package://";
  constexpr std::string_view kFile = "file://";
  const std::string_view text(reference);
  if (text.substr(0, kPackage.size()) == kPackage) {
    return resolve_package(text.substr(kPackage.size()), package_directories);
  }
  if (text.substr(0, kFile.size()) == kFile) {
    const std::string path(text.substr(kFile.size()));
    return path.empty() ? ResolvedResource{} : resolve_path(path, base_directory);
  }
  if (text.empty() || text.find("://") != std::string_view::npos) return {};
  return resolve_path(reference, base_directory);
}

std::vector<std::string> ros_package_path_directories() {
  std::vector<std::string> directories;
  const char* value = std::getenv("ROS_PACKAGE_PATH");
  if (value == nullptr) return directories;
  std::string_view rest(value);
  while (!rest.empty()) {
    const std::size_t colon = rest.find(':');
    const std::string_view entry = rest.substr(0, colon);
    if (!entry.empty()) directories.emplace_back(entry);
    if (colon == std::string_view::npos) break;
    rest.remove_prefix(colon + 1);
  }
  return directories;
}

}  // namespace grpvss::io

#include "setup_cache_options.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include <fmt/core.h>

#include "grpvss/report/program_version.hpp"

namespace grpvss::app {
namespace {

std::string executable_identity() {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) return "unknown executable";
  const auto size = fs::file_size(self, error);
  if (error) return "unknown executable";
  const auto modified = fs::last_write_time(self, error);
  if (error) return "unknown executable";
  return fmt::format("{} bytes, modified {}", size,
                     static_cast<long long>(modified.time_since_epoch().count()));
}

}  // namespace

std::optional<certify::SetupCacheOptions> setup_cache_options(const std::string& cache_dir,
                                                              bool no_cache,
                                                              std::vector<std::string>& notes) {
  if (no_cache) return std::nullopt;
  certify::SetupCacheOptions options;
  if (!cache_dir.empty()) {
    options.directory = cache_dir;
  } else if (const auto directory = certify::default_setup_cache_directory(
                 std::getenv("XDG_CACHE_HOME"), std::getenv("HOME"))) {
    options.directory = *directory;
  } else {
    notes.push_back("set-up cache: neither XDG_CACHE_HOME nor HOME is set; no cache");
    return std::nullopt;
  }
  options.build_identity =
      fmt::format("grpvss {} ({})", report::program_version(), executable_identity());
  return options;
}

}  // namespace grpvss::app

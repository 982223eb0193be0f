#pragma once
// `verify --cache-dir DIR` / `--no-cache` turned into the set-up cache's options (docs/cache.md).
#include <optional>
#include <string>
#include <vector>

#include "grpvss/certify/setup_cache.hpp"

namespace grpvss::app {

/// The cache to use, or nullopt (--no-cache, or no directory: then a note says why).
/// The build identity is the program version plus this executable's size and modification
/// time, so that a rebuilt grpvss never reads the offsets of an older build.
std::optional<certify::SetupCacheOptions> setup_cache_options(const std::string& cache_dir,
                                                              bool no_cache,
                                                              std::vector<std::string>& notes);

}  // namespace grpvss::app

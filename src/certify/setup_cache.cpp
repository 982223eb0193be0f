#include "grpvss/certify/setup_cache.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include <fmt/core.h>

#include "grpvss/common/sha256.hpp"

namespace grpvss::certify {
namespace {

namespace fs = std::filesystem;

constexpr const char* kMagic = "grpvss-setup-cache 1";

// Hexadecimal floating point: exact, and read back bit for bit by strtod.
void append_point(std::string& out, const Eigen::Vector3d& p) {
  out += fmt::format("{:a} {:a} {:a}\n", p.x(), p.y(), p.z());
}

// Everything minkowski_offset's result depends on, plus the build that computed it.
std::string key_of(const LinkOffsetInputs& inputs, const std::string& build_identity) {
  std::string material = fmt::format("{} key\nbuild {}\nshape {}\ntolerance {:a}\nradius {:a}\n",
                                     kMagic, build_identity, to_string(inputs.offset_shape),
                                     inputs.tolerance, inputs.expansion_radius);
  material += fmt::format("hulls {}\n", inputs.hulls.size());
  for (const LinkHull& hull : inputs.hulls) {
    material += fmt::format("hull {} {} {}\n", hull.link, hull.hull, hull.raw_L.size());
    for (const Eigen::Vector3d& p : hull.raw_L) append_point(material, p);
  }
  return sha256_hex(material);
}

std::string entry_text(const std::string& key,
                       const std::vector<std::vector<Eigen::Vector3d>>& expanded_L) {
  std::string body = fmt::format("{}\nkey {}\nhulls {}\n", kMagic, key, expanded_L.size());
  for (const auto& offset : expanded_L) {
    body += fmt::format("offset {}\n", offset.size());
    for (const Eigen::Vector3d& p : offset) append_point(body, p);
  }
  return body + fmt::format("checksum {}\n", sha256_hex(body));
}

enum class EntryState { kMissing, kCorrupt, kStale, kCurrent };

struct ParsedEntry {
  EntryState state = EntryState::kMissing;
  std::string problem;
  std::vector<std::vector<Eigen::Vector3d>> offsets;
};

ParsedEntry corrupt(std::string problem) {
  ParsedEntry entry;
  entry.state = EntryState::kCorrupt;
  entry.problem = std::move(problem);
  return entry;
}

bool read_count(std::istringstream& in, const char* word, std::size_t& count) {
  std::string found;
  long long value = -1;
  if (!(in >> found >> value) || found != word || value < 0 || value > 1'000'000) return false;
  count = static_cast<std::size_t>(value);
  return true;
}

bool read_point(std::istringstream& in, Eigen::Vector3d& p) {
  for (int axis = 0; axis < 3; ++axis) {
    std::string token;
    if (!(in >> token)) return false;
    char* end = nullptr;
    p[axis] = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size()) return false;
  }
  return true;
}

// The body after the checksum line was verified: magic, key, counts, points.
ParsedEntry parse_body(const std::string& body, const std::string& key) {
  ParsedEntry entry;
  std::istringstream in(body);
  std::string magic_line, key_word, stored_key;
  std::getline(in, magic_line);
  if (magic_line != kMagic) return corrupt("wrong format");
  if (!(in >> key_word >> stored_key) || key_word != "key") return corrupt("no key");
  if (stored_key != key) {
    entry.state = EntryState::kStale;
    return entry;
  }
  std::size_t hulls = 0;
  if (!read_count(in, "hulls", hulls)) return corrupt("bad hull count");
  for (std::size_t h = 0; h < hulls; ++h) {
    std::size_t points = 0;
    if (!read_count(in, "offset", points)) return corrupt("bad offset header");
    std::vector<Eigen::Vector3d> offset(points);
    for (Eigen::Vector3d& p : offset) {
      if (!read_point(in, p)) return corrupt("bad coordinate");
    }
    entry.offsets.push_back(std::move(offset));
  }
  std::string rest;
  if (in >> rest) return corrupt("trailing data");
  entry.state = EntryState::kCurrent;
  return entry;
}

ParsedEntry read_entry(const std::string& path, const std::string& key) {
  ParsedEntry entry;
  std::ifstream file(path, std::ios::binary);
  if (!file) return entry;  // missing
  std::ostringstream content;
  content << file.rdbuf();
  const std::string text = content.str();
  const std::string marker = "checksum ";
  const std::size_t at = text.rfind(marker);
  if (text.empty() || text.back() != '\n' || at == std::string::npos ||
      (at != 0 && text[at - 1] != '\n')) {
    return corrupt("truncated");
  }
  const std::string body = text.substr(0, at);
  if (text.substr(at + marker.size()) != sha256_hex(body) + "\n") return corrupt("bad checksum");
  return parse_body(body, key);
}

// Whole or nothing: a temporary file in the same directory, renamed over the entry.
std::optional<std::string> publish(const std::string& path, const std::string& text) {
  static std::atomic<unsigned> counter{0};
  const std::string temporary =
      fmt::format("{}.{}.{}.tmp", path, static_cast<long>(::getpid()), counter++);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      return std::string("cannot write a temporary file");
    }
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    return error.message();
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> default_setup_cache_directory(const char* xdg_cache_home,
                                                         const char* home) {
  // XDG Base Directory: a relative XDG_CACHE_HOME is invalid and ignored.
  if (xdg_cache_home != nullptr && xdg_cache_home[0] == '/') {
    return (fs::path(xdg_cache_home) / "grpvss").string();
  }
  if (home != nullptr && home[0] != '\0') return (fs::path(home) / ".cache" / "grpvss").string();
  return std::nullopt;
}

SetupCache::SetupCache(SetupCacheOptions options) : options_(std::move(options)) {}

void SetupCache::note(const std::string& text) { notes_.push_back("set-up cache: " + text); }

bool SetupCache::usable() {
  if (directory_ready_) return *directory_ready_;
  std::error_code error;
  fs::create_directories(options_.directory, error);
  const bool ready = !error && fs::is_directory(options_.directory, error) && !error;
  if (!ready) {
    note(fmt::format("cannot use the directory {} ({}); the set-up is built without a cache",
                     options_.directory, error ? error.message() : "not a directory"));
  }
  directory_ready_ = ready;
  return ready;
}

std::string SetupCache::entry_path(const LinkOffsetInputs& inputs) const {
  return (fs::path(options_.directory) / (key_of(inputs, options_.build_identity) + ".offsets"))
      .string();
}

std::optional<std::vector<std::vector<Eigen::Vector3d>>> SetupCache::propose(
    const LinkOffsetInputs& inputs) {
  loaded_ = false;
  if (!usable()) return std::nullopt;
  const std::string path = entry_path(inputs);
  ParsedEntry entry = read_entry(path, key_of(inputs, options_.build_identity));
  switch (entry.state) {
    case EntryState::kMissing:
      return std::nullopt;
    case EntryState::kCorrupt:
      note(fmt::format("entry {} is corrupt ({}); rebuilt", path, entry.problem));
      return std::nullopt;
    case EntryState::kStale:
      note(fmt::format("entry {} is stale (other inputs or another build); rebuilt", path));
      return std::nullopt;
    case EntryState::kCurrent:
      break;
  }
  loaded_ = true;
  return std::move(entry.offsets);
}

void SetupCache::adopted(const LinkOffsetInputs& inputs,
                         const std::vector<std::vector<Eigen::Vector3d>>& expanded_L,
                         std::size_t rejected) {
  if (!usable()) return;
  const std::string path = entry_path(inputs);
  if (loaded_ && rejected == 0) return;  // a current entry, every offset re-checked
  if (loaded_) {
    note(fmt::format("entry {} failed the exact re-check ({} of {} offsets); rebuilt", path,
                     rejected, expanded_L.size()));
  }
  const std::string key = key_of(inputs, options_.build_identity);
  if (const auto problem = publish(path, entry_text(key, expanded_L))) {
    note(fmt::format("cannot write {} ({})", path, *problem));
  }
}

}  // namespace grpvss::certify

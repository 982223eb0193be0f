#include "support/text_files.hpp"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <system_error>
#include <vector>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>

namespace grpvss::test {

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ADD_FAILURE() << "cannot read " << path;
    return {};
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {
      lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

namespace {

/// The directories make_temporary_directory() made in this process, removed when it exits
/// (each test is its own process under ctest), so test runs leave nothing in /tmp.
class TemporaryDirectories {
 public:
  void add(const std::filesystem::path& directory) {
    const std::lock_guard<std::mutex> lock(mutex_);
    directories_.push_back(directory);
  }
  ~TemporaryDirectories() {
    if (::getpid() != owner_) return;  // a forked child leaving by exit() keeps its parent's
    for (const auto& directory : directories_) {
      std::error_code ignored;  // a directory a test removed itself is fine
      std::filesystem::remove_all(directory, ignored);
    }
  }

 private:
  const pid_t owner_ = ::getpid();
  std::mutex mutex_;
  std::vector<std::filesystem::path> directories_;
};

TemporaryDirectories& temporary_directories() {
  static TemporaryDirectories directories;
  return directories;
}

}  // namespace

std::string make_temporary_directory(const std::string& tag) {
  static std::atomic<int> counter{0};
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() /
      ("grpvss-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  temporary_directories().add(directory);
  return directory.string();
}

std::vector<std::string> directory_entries(const std::string& directory) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace grpvss::test

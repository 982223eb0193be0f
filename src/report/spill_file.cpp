#include "grpvss/report/spill_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <fmt/core.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/report/atomic_output.hpp"

namespace grpvss::report {
namespace {

constexpr std::size_t kBufferBytes = std::size_t{1} << 20;

[[noreturn]] void throw_spill_error(const std::string& path, const char* what, int error_number) {
  throw InputError(path, 0, "a writable output location",
                   fmt::format("{} a scratch file failed: {}", what, std::strerror(error_number)));
}

int open_anonymous(const std::string& output_path) {
  std::filesystem::path directory = std::filesystem::path(output_path).parent_path();
  if (directory.empty()) directory = ".";
  // Standard output has no folder: its scratch goes where its temporary file goes.
  if (output_path == kStandardOutput) directory = std::filesystem::temp_directory_path();
  const int fd = ::open(directory.c_str(), O_RDWR | O_TMPFILE | O_CLOEXEC, 0600);
  if (fd >= 0) return fd;
  if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL) {
    throw_spill_error(output_path, "creating", errno);
  }
  // No O_TMPFILE on this file system: a fresh name, unlinked at once.
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string name =
        (directory / fmt::format(".grpvss-spill.{}.{}", ::getpid(), counter.fetch_add(1))).string();
    const int named = ::open(name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (named >= 0) {
      ::unlink(name.c_str());
      return named;
    }
    if (errno != EEXIST) throw_spill_error(output_path, "creating", errno);
  }
  throw_spill_error(output_path, "creating", EEXIST);
}

}  // namespace

SpillFile::SpillFile(const std::string& output_path)
    : output_path_(output_path), fd_(open_anonymous(output_path)) {}

SpillFile::~SpillFile() {
  if (fd_ >= 0) ::close(fd_);
}

void SpillFile::flush() {
  std::string_view rest = buffer_;
  while (!rest.empty()) {
    const ssize_t done = ::pwrite(fd_, rest.data(), rest.size(), static_cast<off_t>(written_));
    if (done < 0) {
      if (errno == EINTR) continue;
      throw_spill_error(output_path_, "writing", errno);
    }
    rest.remove_prefix(static_cast<std::size_t>(done));
    written_ += static_cast<std::uint64_t>(done);
  }
  buffer_.clear();
}

void SpillFile::append(std::string_view bytes) {
  buffer_.append(bytes);
  if (buffer_.size() >= kBufferBytes) flush();
}

void SpillFile::copy_to(AtomicOutputFile& output, std::uint64_t begin, std::uint64_t end) {
  if (begin > end || end > size()) throw std::logic_error("SpillFile: range outside the spill");
  flush();
  std::vector<char> chunk(kBufferBytes);
  while (begin < end) {
    const std::size_t wanted =
        static_cast<std::size_t>(std::min<std::uint64_t>(end - begin, chunk.size()));
    const ssize_t got = ::pread(fd_, chunk.data(), wanted, static_cast<off_t>(begin));
    if (got < 0) {
      if (errno == EINTR) continue;
      throw_spill_error(output_path_, "reading", errno);
    }
    if (got == 0) throw std::logic_error("SpillFile: shorter than written");
    output.write(std::string_view(chunk.data(), static_cast<std::size_t>(got)));
    begin += static_cast<std::uint64_t>(got);
  }
}

}  // namespace grpvss::report

#include "grpvss/report/atomic_output.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include <fmt/core.h>

namespace grpvss::report {

OutputExistsError::OutputExistsError(const std::string& path)
    : InputError(path, 0, "a path that does not exist yet (use --force to overwrite)",
                 "an existing file") {}

namespace {

[[noreturn]] void throw_system(const std::string& path, const char* what, int error_number) {
  throw InputError(path, 0, "a writable output location",
                   fmt::format("{} failed: {}", what, std::strerror(error_number)));
}

/// Publishes `from` as `to` only if `to` does not exist; returns errno (0 on success).
int publish_without_clobbering(const std::string& from, const std::string& to) {
  if (::link(from.c_str(), to.c_str()) == 0) return 0;
  const int link_error = errno;
  // Some file systems (FAT, some FUSE) have no hard links; RENAME_NOREPLACE is equally atomic.
  if (link_error != EPERM && link_error != EOPNOTSUPP && link_error != ENOSYS) return link_error;
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return 0;
  return errno == EINVAL || errno == ENOSYS ? link_error : errno;
}

void sync_directory(const std::filesystem::path& directory) {
  // Best effort: the content is already durable; this makes the new name durable too.
  const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

/// Owns the temporary file: closes and unlinks it unless the content was published.
class AtomicOutputFile::Temporary {
 public:
  Temporary(const std::string& final_path, const std::filesystem::path& directory) {
    static std::atomic<unsigned> counter{0};
    const std::string base = std::filesystem::path(final_path).filename().string();
    for (int attempt = 0; attempt < 100; ++attempt) {
      name_ = (directory / fmt::format(".{}.{}.{}.grpvss-tmp", base, ::getpid(),
                                       counter.fetch_add(1)))
                  .string();
      // O_EXCL: never reuse (or follow a symlink planted at) an existing name.
      fd_ = ::open(name_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd_ >= 0) return;
      if (errno != EEXIST) throw_system(final_path, "creating a temporary file", errno);
    }
    throw_system(final_path, "creating a temporary file", EEXIST);
  }
  Temporary(const Temporary&) = delete;
  Temporary& operator=(const Temporary&) = delete;
  ~Temporary() {
    if (fd_ >= 0) ::close(fd_);
    if (!name_.empty()) ::unlink(name_.c_str());
  }

  void write_all(const std::string& final_path, std::string_view content) {
    while (!content.empty()) {
      const ssize_t written = ::write(fd_, content.data(), content.size());
      if (written < 0) {
        if (errno == EINTR) continue;
        throw_system(final_path, "writing", errno);
      }
      content.remove_prefix(static_cast<std::size_t>(written));
    }
  }

  void sync_and_close(const std::string& final_path) {
    // Durable before it becomes visible: a crash must not publish an empty/partial file.
    if (::fsync(fd_) != 0) throw_system(final_path, "fsync", errno);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) throw_system(final_path, "closing", errno);
  }

  // Standard output receives the whole content at once, after it was completely written.
  void copy_to_standard_output(const std::string& final_path) {
    if (::lseek(fd_, 0, SEEK_SET) != 0) throw_system(final_path, "rewinding", errno);
    std::string chunk(std::size_t{1} << 16, '\0');
    for (;;) {
      const ssize_t got = ::read(fd_, chunk.data(), chunk.size());
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) throw_system(final_path, "reading back", errno);
      if (got == 0) break;
      std::string_view piece(chunk.data(), static_cast<std::size_t>(got));
      while (!piece.empty()) {
        const ssize_t written = ::write(STDOUT_FILENO, piece.data(), piece.size());
        if (written < 0 && errno == EINTR) continue;
        if (written < 0) throw_system(final_path, "writing standard output", errno);
        piece.remove_prefix(static_cast<std::size_t>(written));
      }
    }
  }

  const std::string& name() const { return name_; }
  void forget() { name_.clear(); }

 private:
  std::string name_;
  int fd_ = -1;
};

namespace {

std::filesystem::path directory_of(const std::string& path) {
  if (path == kStandardOutput) return std::filesystem::temp_directory_path();
  std::filesystem::path directory = std::filesystem::path(path).parent_path();
  if (directory.empty()) directory = ".";
  return directory;
}

// Small pieces are gathered to about this size before a write(2).
constexpr std::size_t kWriteBufferBytes = std::size_t{1} << 20;

}  // namespace

AtomicOutputFile::AtomicOutputFile(std::string path, bool force)
    : path_(std::move(path)), force_(force) {
  if (path_.empty()) throw InputError(path_, 0, "a non-empty output path");
  temporary_ = std::make_unique<Temporary>(path_, directory_of(path_));
}

AtomicOutputFile::~AtomicOutputFile() = default;

void AtomicOutputFile::flush() {
  temporary_->write_all(path_, buffer_);
  buffer_.clear();
}

void AtomicOutputFile::write(std::string_view bytes) {
  if (!temporary_) throw std::logic_error("AtomicOutputFile: write after commit");
  if (buffer_.size() + bytes.size() <= kWriteBufferBytes) {
    buffer_.append(bytes);
    return;
  }
  flush();
  if (bytes.size() >= kWriteBufferBytes) {
    temporary_->write_all(path_, bytes);
  } else {
    buffer_.append(bytes);
  }
}

void AtomicOutputFile::commit() {
  if (!temporary_) throw std::logic_error("AtomicOutputFile: committed twice");
  flush();
  std::string().swap(buffer_);
  if (path_ == kStandardOutput) {
    std::fflush(stdout);  // what the program printed before stays before the content
    temporary_->copy_to_standard_output(path_);
    temporary_.reset();
    return;
  }
  temporary_->sync_and_close(path_);
  if (force_) {
    if (std::rename(temporary_->name().c_str(), path_.c_str()) != 0) {
      throw_system(path_, "renaming the temporary file over the output", errno);
    }
    temporary_->forget();  // the name now belongs to the output
  } else {
    const int error = publish_without_clobbering(temporary_->name(), path_);
    if (error == EEXIST) throw OutputExistsError(path_);
    if (error != 0) throw_system(path_, "publishing the output", error);
    // After link(2) the temporary is a second name of the output: ~Temporary drops it
    // (after renameat2 it is already gone and unlink fails harmlessly).
  }
  temporary_.reset();
  sync_directory(directory_of(path_));
}

void write_file_atomically(const std::string& path, std::string_view content, bool force) {
  AtomicOutputFile output(path, force);
  output.write(content);
  output.commit();
}

}  // namespace grpvss::report

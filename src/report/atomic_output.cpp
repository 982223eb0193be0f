#include "grpvss/report/atomic_output.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

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

/// Owns the temporary file: closes and unlinks it unless the content was published.
class TemporaryFile {
 public:
  TemporaryFile(const std::string& final_path, const std::filesystem::path& directory) {
    static std::atomic<unsigned> counter{0};
    const std::string base = std::filesystem::path(final_path).filename().string();
    for (int attempt = 0; attempt < 100; ++attempt) {
      name_ = (directory / fmt::format(".{}.{}.{}.grpvss-tmp", base, ::getpid(),
                                       counter.fetch_add(1)))
                  .string();
      // O_EXCL: never reuse (or follow a symlink planted at) an existing name.
      fd_ = ::open(name_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd_ >= 0) return;
      if (errno != EEXIST) throw_system(final_path, "creating a temporary file", errno);
    }
    throw_system(final_path, "creating a temporary file", EEXIST);
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
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
    // Durable before it becomes visible: a crash must not publish an empty/partial file.
    if (::fsync(fd_) != 0) throw_system(final_path, "fsync", errno);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) throw_system(final_path, "closing", errno);
  }

  const std::string& name() const { return name_; }
  void forget() { name_.clear(); }

 private:
  std::string name_;
  int fd_ = -1;
};

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

void write_file_atomically(const std::string& path, std::string_view content, bool force) {
  if (path.empty()) throw InputError(path, 0, "a non-empty output path");
  std::filesystem::path directory = std::filesystem::path(path).parent_path();
  if (directory.empty()) directory = ".";

  {
    TemporaryFile temporary(path, directory);
    temporary.write_all(path, content);
    if (force) {
      if (std::rename(temporary.name().c_str(), path.c_str()) != 0) {
        throw_system(path, "renaming the temporary file over the output", errno);
      }
      temporary.forget();  // the name now belongs to the output
    } else {
      const int error = publish_without_clobbering(temporary.name(), path);
      if (error == EEXIST) throw OutputExistsError(path);
      if (error != 0) throw_system(path, "publishing the output", error);
      // After link(2) the temporary is a second name of the output: ~TemporaryFile drops it
      // (after renameat2 it is already gone and unlink fails harmlessly).
    }
  }
  sync_directory(directory);
}

}  // namespace grpvss::report

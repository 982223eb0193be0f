#pragma once
/// \file
/// \brief Publishing an output file atomically and, unless forced, without clobbering.
///
/// A reader (or a crash) never sees a partial output: the content goes to a temporary file in
/// the same directory, is fsync'ed, and only then appears under its final name in one step.

#include <memory>
#include <string>
#include <string_view>

#include "grpvss/common/input_error.hpp"

namespace grpvss::report {

/// The output path that means standard output (`--json -`): the content is gathered in a
/// temporary file and copied to standard output only when complete (commit()), so a run that
/// fails part-way prints nothing; `force` does not apply.
inline constexpr const char* kStandardOutput = "-";

/// \brief The output path already exists and --force was not given. Like the thesis program
/// (A.2.2: "If one file with this name already exists in the disk, the execution of GRPVSS
/// will be terminated."), GRPVSS refuses to overwrite an existing output name.
class OutputExistsError : public InputError {
 public:
  explicit OutputExistsError(const std::string& path);
};

/// \brief Writes `content` to `path` atomically.
///
/// Writes `<dir>/.<name>.<pid>.<n>.grpvss-tmp` (created with O_EXCL, mode 0666 & ~umask),
/// fsyncs it, then publishes it:
/// - `force == false`: link(2) of the temporary to `path`, which fails with EEXIST if the path
///   exists (also if it appeared meanwhile: no check-then-act race), so an existing file is
///   never touched; where hard links are unsupported, renameat2(RENAME_NOREPLACE) is used;
/// - `force == true`: rename(2) over `path` (atomic replacement).
/// The directory is then fsync'ed (best effort). The temporary file is removed on every path,
/// successful or not. `path` kStandardOutput: the temporary file is made in the system's
/// temporary folder and copied to standard output.
///
/// \throws OutputExistsError when `path` exists and `force` is false.
/// \throws InputError (file = `path`, line 0) when the directory is missing or not writable,
///         the disk is full, or `path` names a directory.
void write_file_atomically(const std::string& path, std::string_view content, bool force);

/// \brief The same guarantees for an output written piece by piece (streaming writers,
/// docs/reliability.md#resource-bounds): the pieces go to the temporary file (buffered), and
/// commit() fsyncs and publishes it exactly as write_file_atomically() does. Destroyed without
/// a successful commit() (an exception on the way), it removes the temporary file: no partial
/// output is ever visible under `path`.
class AtomicOutputFile {
 public:
  /// Creates the temporary file next to `path`.
  /// \throws InputError (file = `path`) when the directory is missing or not writable.
  AtomicOutputFile(std::string path, bool force);
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;
  ~AtomicOutputFile();

  /// Appends `bytes`. \throws InputError (disk full, ...).
  void write(std::string_view bytes);

  /// Publishes the content under `path` (at most once).
  /// \throws OutputExistsError when `path` exists and `force` is false; InputError otherwise.
  void commit();

  const std::string& path() const { return path_; }

 private:
  class Temporary;
  void flush();

  std::string path_;
  bool force_ = false;
  std::unique_ptr<Temporary> temporary_;
  std::string buffer_;
};

}  // namespace grpvss::report

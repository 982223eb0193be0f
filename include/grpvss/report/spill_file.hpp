#pragma once
/// \file
/// \brief A scratch file for the parts of an output that are produced before the output's
/// head can be written (docs/reliability.md#resource-bounds): the steps are rendered as the
/// verification runs, the summary that precedes them in the file only at its end.
///
/// The file has no name: it is created with O_TMPFILE in the output's directory (so it uses
/// that file system's space, not memory, even where /tmp is a tmpfs) or, where O_TMPFILE is
/// unsupported, created and unlinked at once. It disappears when closed, also on a crash.

#include <cstdint>
#include <string>
#include <string_view>

namespace grpvss::report {

class AtomicOutputFile;

class SpillFile {
 public:
  /// `output_path`: the output this spill belongs to; the spill lives in its directory and
  /// errors name it. \throws InputError when no file can be created there.
  explicit SpillFile(const std::string& output_path);
  SpillFile(const SpillFile&) = delete;
  SpillFile& operator=(const SpillFile&) = delete;
  ~SpillFile();

  /// Appends `bytes` (buffered). \throws InputError (disk full, ...).
  void append(std::string_view bytes);

  /// Bytes appended so far.
  std::uint64_t size() const { return written_ + buffer_.size(); }

  /// Appends bytes [begin, end) of this spill to `output`.
  /// \throws std::logic_error when the range is not within [0, size()].
  void copy_to(AtomicOutputFile& output, std::uint64_t begin, std::uint64_t end);

  /// Appends everything to `output`.
  void copy_to(AtomicOutputFile& output) { copy_to(output, 0, size()); }

 private:
  void flush();

  std::string output_path_;
  int fd_ = -1;
  std::uint64_t written_ = 0;  ///< bytes in the file (the buffer holds the rest)
  std::string buffer_;
};

}  // namespace grpvss::report

#pragma once
/// \file
/// \brief Loading an input file whole, so the readers see one string_view and report lines.

#include <cstddef>
#include <string>

namespace grpvss::io {

/// Largest accepted input file (bytes): 10^6 points of ~40 characters fit many times over.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{256} * 1024 * 1024;

/// \brief Returns the bytes of the file at `path`.
/// \throws InputError(path, 0, "a readable file", reason) if it cannot be opened or read, and
/// InputError(path, 0, "a file of at most 268435456 bytes", size) if it is larger.
std::string read_text_file(const std::string& path);

}  // namespace grpvss::io

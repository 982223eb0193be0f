#pragma once
// Small file helpers shared by the report tests.

#include <string>
#include <vector>

namespace grpvss::test {

/// The whole file; fails the calling test (ADD_FAILURE) and returns "" if it cannot be read.
std::string read_text_file(const std::string& path);

/// `text` split at '\n' (a final newline does not add an empty line).
std::vector<std::string> split_lines(const std::string& text);

/// A fresh empty directory under the system temp dir, unique per call; removed with its
/// contents when the test process exits.
std::string make_temporary_directory(const std::string& tag);

/// Names of the entries of `directory`, sorted.
std::vector<std::string> directory_entries(const std::string& directory);

}  // namespace grpvss::test

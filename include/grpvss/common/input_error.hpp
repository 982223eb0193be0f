#pragma once
/// \file
/// \brief The one exception type for bad user input: it names the file, the line and what
/// was expected. The application turns it into exit code 2; the library never exits.

#include <stdexcept>
#include <string>

namespace grpvss {

/// \brief Bad user input, located in a file.
///
/// what() reads `FILE:LINE: expected EXPECTED, found FOUND` (the `, found ...` part only when
/// something was found). Line 0 means "the file as a whole" (e.g. it cannot be opened).
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string expected, std::string found = {});

  const std::string& file() const noexcept { return file_; }
  int line() const noexcept { return line_; }
  const std::string& expected() const noexcept { return expected_; }
  const std::string& found() const noexcept { return found_; }

 private:
  std::string file_;
  int line_;
  std::string expected_;
  std::string found_;
};

}  // namespace grpvss

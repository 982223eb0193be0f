#pragma once
// A one-line progress bar on stderr for long verifications: drawn only when stderr is a
// terminal (never into a pipe or a log file), redrawn only when the shown percentage changes.
#include <functional>
#include <string>

namespace grpvss::app {

class ProgressBar {
 public:
  /// `enabled` false: every call does nothing (--quiet, or stderr is not a terminal).
  ProgressBar(std::string label, bool enabled);
  ~ProgressBar();  ///< erases the bar line
  /// The callback for certify::RunHooks::progress (empty when disabled).
  std::function<void(double)> callback();
  void update(double fraction);

 private:
  std::string label_;
  bool enabled_;
  int shown_percent_ = -1;
};

/// isatty(STDERR_FILENO).
bool stderr_is_terminal();

}  // namespace grpvss::app

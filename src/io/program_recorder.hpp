#pragma once
// Shared by the robot-program readers: collects motions and warnings, and bounds the work a
// program can cause (calls are inlined, so a small file could otherwise expand without end).

#include <cstddef>
#include <set>
#include <string>
#include <tuple>

#include "grpvss/model/robot_program.hpp"

namespace grpvss::io {

class ProgramRecorder {
 public:
  /// Calls nested deeper than this are rejected (recursion is not evaluated).
  static constexpr int kMaxCallDepth = 32;
  /// Executed statements allowed beyond twice the program's own statement count.
  static constexpr std::size_t kExtraStatementBudget = 200000;

  ProgramRecorder(ProgramLanguage language, std::size_t statement_count);

  /// Sets the budget from the program's statement count (when known only after the recorder
  /// was made).
  void set_statement_count(std::size_t statement_count) {
    budget_ = kExtraStatementBudget + 2 * statement_count;
  }
  /// Records a warning once: a statement run again (a routine called twice) adds nothing.
  void warn(const std::string& file, int line, std::string text);
  void add_motion(ProgramMotion motion) { program_.motions.push_back(std::move(motion)); }
  /// Counts one executed statement; throws InputError once the budget is spent.
  void count_statement(const std::string& file, int line);
  /// Enters a call; throws InputError beyond kMaxCallDepth. Pair with leave_call().
  void enter_call(const std::string& file, int line, const std::string& routine);
  void leave_call() { --call_depth_; }

  RobotProgram& program() { return program_; }
  RobotProgram take() { return std::move(program_); }

 private:
  RobotProgram program_;
  std::set<std::tuple<std::string, int, std::string>> warned_;
  std::size_t budget_;
  std::size_t executed_ = 0;
  int call_depth_ = 0;
};

/// Leaves the call when it goes out of scope (also when an InputError passes through).
class CallScope {
 public:
  CallScope(ProgramRecorder& recorder, const std::string& file, int line,
            const std::string& routine)
      : recorder_(recorder) {
    recorder_.enter_call(file, line, routine);
  }
  ~CallScope() { recorder_.leave_call(); }
  CallScope(const CallScope&) = delete;
  CallScope& operator=(const CallScope&) = delete;

 private:
  ProgramRecorder& recorder_;
};

}  // namespace grpvss::io

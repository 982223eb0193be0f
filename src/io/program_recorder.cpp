#include "program_recorder.hpp"

#include "grpvss/common/input_error.hpp"

namespace grpvss::io {

ProgramRecorder::ProgramRecorder(ProgramLanguage language, std::size_t statement_count)
    : budget_(kExtraStatementBudget + 2 * statement_count) {
  program_.language = language;
}

void ProgramRecorder::warn(const std::string& file, int line, std::string text) {
  if (!warned_.emplace(file, line, text).second) return;
  program_.warnings.push_back({file, line, std::move(text)});
}

void ProgramRecorder::count_statement(const std::string& file, int line) {
  if (++executed_ > budget_) {
    throw InputError(file, line,
                     "a program whose calls expand to at most " + std::to_string(budget_) +
                         " executed statements",
                     "more");
  }
}

void ProgramRecorder::enter_call(const std::string& file, int line, const std::string& routine) {
  if (call_depth_ >= kMaxCallDepth) {
    throw InputError(file, line,
                     "calls nested at most " + std::to_string(kMaxCallDepth) +
                         " deep (recursion is not evaluated)",
                     "a call of " + routine + " nested deeper");
  }
  ++call_depth_;
}

}  // namespace grpvss::io

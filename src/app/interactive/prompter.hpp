#pragma once
/// \file
/// \brief The question-and-answer channel of the interactive session: prints a prompt, reads
/// one answer line, re-asks invalid answers with a reason, and ends the session cleanly at the
/// end of input or after too many invalid answers in a row (a script never loops forever).

#include <functional>
#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace grpvss::app::interactive {

/// Thrown when the input ends (EOF on a pipe, Ctrl-D at a terminal) while a question waits.
struct EndOfInput {};

/// Thrown when `max_invalid` answers in a row were invalid.
struct TooManyInvalidAnswers {
  int count = 0;
};

class Prompter {
 public:
  /// `echo`: repeat each answer after the prompt (for piped input, whose answers the terminal
  /// never shows, so that the transcript reads like the thesis's running sample).
  Prompter(std::istream& in, std::ostream& out, int max_invalid, bool echo);

  std::ostream& out() { return out_; }

  /// Prints `lines`, reads one answer line (trimmed). \throws EndOfInput.
  std::string ask(const std::vector<std::string>& lines);

  /// Asks until `parse` accepts the answer (returns a value); a rejected answer prints
  /// "INVALID ANSWER: <why>" and the question again.
  /// \throws EndOfInput, TooManyInvalidAnswers.
  template <class T>
  T ask_until(const std::vector<std::string>& lines,
              const std::function<std::optional<T>(const std::string& answer, std::string& why)>&
                  parse) {
    for (;;) {
      const std::string answer = ask(lines);
      std::string why;
      if (std::optional<T> value = parse(answer, why)) {
        accept();
        return *value;
      }
      reject(why);
    }
  }

  /// A numbered menu: `title`, then "1. ..." per option, then `footer`; answer 1..size.
  int ask_option(const std::string& title, const std::vector<std::string>& options,
                 const std::string& footer = "ENTER ONE OF THE OPTION NUMBERS");
  /// `lines` then "ENTER Y/N (DEFAULT = Y|N)"; the empty answer takes the default.
  bool ask_yes_no(const std::vector<std::string>& lines, bool default_yes);
  /// Exactly `count` numbers (comma list); `check` may reject them with a reason.
  std::vector<double> ask_numbers(
      const std::vector<std::string>& lines, std::size_t count,
      const std::function<bool(const std::vector<double>&, std::string& why)>& check = {});
  /// A non-empty answer (a file name).
  std::string ask_name(const std::vector<std::string>& lines);

  /// Counts an invalid answer and prints the reason. \throws TooManyInvalidAnswers at the bound.
  void reject(const std::string& why);
  /// A valid answer: the count of invalid answers in a row starts again.
  void accept() { invalid_in_a_row_ = 0; }

 private:
  std::istream& in_;
  std::ostream& out_;
  int max_invalid_;
  bool echo_;
  int invalid_in_a_row_ = 0;
};

}  // namespace grpvss::app::interactive

#include "interactive/prompter.hpp"

#include <fmt/core.h>

#include "interactive/answer_parsing.hpp"

namespace grpvss::app::interactive {

Prompter::Prompter(std::istream& in, std::ostream& out, int max_invalid, bool echo)
    : in_(in), out_(out), max_invalid_(max_invalid < 1 ? 1 : max_invalid), echo_(echo) {}

std::string Prompter::ask(const std::vector<std::string>& lines) {
  for (const std::string& line : lines) out_ << line << '\n';
  out_ << "> " << std::flush;
  std::string answer;
  if (!std::getline(in_, answer)) {
    out_ << '\n';
    throw EndOfInput{};
  }
  answer = trim_answer(answer);
  if (echo_) out_ << answer;
  out_ << '\n';
  return answer;
}

void Prompter::reject(const std::string& why) {
  ++invalid_in_a_row_;
  out_ << "INVALID ANSWER: " << why << '\n';
  if (invalid_in_a_row_ >= max_invalid_) throw TooManyInvalidAnswers{invalid_in_a_row_};
}

int Prompter::ask_option(const std::string& title, const std::vector<std::string>& options,
                         const std::string& footer) {
  std::vector<std::string> lines{title};
  for (std::size_t i = 0; i < options.size(); ++i) {
    lines.push_back(fmt::format("{}. {}", i + 1, options[i]));
  }
  lines.push_back(footer);
  const int count = static_cast<int>(options.size());
  return ask_until<int>(lines, [count](const std::string& answer, std::string& why) {
    std::optional<int> option = parse_option(answer, count);
    if (!option) why = fmt::format("enter one of the option numbers 1 to {}", count);
    return option;
  });
}

bool Prompter::ask_yes_no(const std::vector<std::string>& lines, bool default_yes) {
  std::vector<std::string> prompt = lines;
  prompt.push_back(default_yes ? "ENTER Y/N (DEFAULT = Y)" : "ENTER Y/N (DEFAULT = N)");
  return ask_until<bool>(prompt, [default_yes](const std::string& answer, std::string& why) {
    std::optional<bool> yes = parse_yes_no(answer, default_yes);
    if (!yes) why = "enter Y or N (or nothing for the default)";
    return yes;
  });
}

std::vector<double> Prompter::ask_numbers(
    const std::vector<std::string>& lines, std::size_t count,
    const std::function<bool(const std::vector<double>&, std::string& why)>& check) {
  return ask_until<std::vector<double>>(
      lines, [count, &check](const std::string& answer,
                             std::string& why) -> std::optional<std::vector<double>> {
        std::optional<std::vector<double>> numbers = parse_number_list(answer, why);
        if (!numbers) return std::nullopt;
        if (numbers->size() != count) {
          why = fmt::format("expected {} number{}, found {}", count, count == 1 ? "" : "s",
                            numbers->size());
          return std::nullopt;
        }
        if (check && !check(*numbers, why)) return std::nullopt;
        return numbers;
      });
}

std::string Prompter::ask_name(const std::vector<std::string>& lines) {
  return ask_until<std::string>(
      lines, [](const std::string& answer, std::string& why) -> std::optional<std::string> {
        if (answer.empty()) {
          why = "enter a file name";
          return std::nullopt;
        }
        return answer;
      });
}

}  // namespace grpvss::app::interactive

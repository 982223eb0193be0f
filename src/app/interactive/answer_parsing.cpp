#include "interactive/answer_parsing.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include <fmt/core.h>

namespace grpvss::app::interactive {

std::string trim_answer(const std::string& answer) {
  std::size_t begin = 0;
  std::size_t end = answer.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(answer[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(answer[end - 1]))) --end;
  return answer.substr(begin, end - begin);
}

std::optional<std::vector<double>> parse_number_list(const std::string& answer, std::string& why) {
  const std::string text = trim_answer(answer);
  std::vector<double> numbers;
  std::size_t i = 0;
  bool need_number = true;  // at the start and right after a comma
  while (i < text.size()) {
    const char c = text[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    if (c == ',') {
      if (need_number) {
        why = "an empty field between commas";
        return std::nullopt;
      }
      need_number = true;
      ++i;
      continue;
    }
    const char* start = text.c_str() + i;
    char* stop = nullptr;
    errno = 0;
    const double value = std::strtod(start, &stop);
    std::size_t used = static_cast<std::size_t>(stop - start);
    // strtod would also accept "nan", "inf" and hex floats: only decimal numbers are data here.
    const std::string token = text.substr(i, used);
    const bool decimal = used > 0 && token.find_first_not_of("0123456789+-.eE") == std::string::npos;
    if (!decimal || errno == ERANGE || !std::isfinite(value)) {
      std::size_t end = text.find_first_of(", \t", i);
      if (end == std::string::npos) end = text.size();
      why = fmt::format("'{}' is not a number", text.substr(i, std::max<std::size_t>(1, end - i)));
      return std::nullopt;
    }
    numbers.push_back(value);
    i += used;
    need_number = false;
    // The next character must separate numbers: "1.5x" is not two fields.
    if (i < text.size() && text[i] != ',' && !std::isspace(static_cast<unsigned char>(text[i]))) {
      std::size_t end = text.find_first_of(", \t", i);
      if (end == std::string::npos) end = text.size();
      why = fmt::format("'{}' is not a number", text.substr(i - used, end - (i - used)));
      return std::nullopt;
    }
  }
  if (numbers.empty()) {
    why = "no number";
    return std::nullopt;
  }
  return numbers;
}

std::optional<bool> parse_yes_no(const std::string& answer, bool default_yes) {
  std::string text = trim_answer(answer);
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (text.empty()) return default_yes;
  if (text == "Y" || text == "YES") return true;
  if (text == "N" || text == "NO") return false;
  return std::nullopt;
}

std::optional<int> parse_option(const std::string& answer, int count) {
  std::string text = trim_answer(answer);
  if (!text.empty() && (text.back() == ',' || text.back() == '.')) text.pop_back();
  if (text.empty() || text.size() > 3) return std::nullopt;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
  }
  const int value = std::stoi(text);
  if (value < 1 || value > count) return std::nullopt;
  return value;
}

}  // namespace grpvss::app::interactive

#include "number_reader.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

#include "grpvss/common/input_error.hpp"
#include "blank_char.hpp"

namespace grpvss::io {
namespace {

constexpr std::size_t kMaxQuotedField = 40;

/// The field as it appears in messages: quoted, cut to a readable length, control and
/// non-ASCII bytes written as \xNN so a message is always printable.
std::string quoted(std::string_view field) {
  const bool cut = field.size() > kMaxQuotedField;
  std::string text = "'";
  for (const char c : field.substr(0, kMaxQuotedField)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f) {
      static constexpr char kHex[] = "0123456789abcdef";
      text += "\\x";
      text += kHex[byte >> 4];
      text += kHex[byte & 0xf];
    } else {
      text += c;
    }
  }
  return text + (cut ? "...'" : "'");
}

/// from_chars rejects a leading '+'; users coming from FORTRAN write it.
std::string_view strip_plus(std::string_view field) {
  if (field.size() >= 2 && field[0] == '+' && field[1] != '-' && field[1] != '+') {
    return field.substr(1);
  }
  return field;
}

bool equal_ignoring_ascii_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto lower = [](char c) { return (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

std::string plural(std::size_t count, const char* noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

}  // namespace

double parse_number_field(std::string_view field, const std::string& file_name, int line,
                          std::string_view what) {
  const std::string_view digits = strip_plus(field);
  double value = 0.0;
  const auto [end, error] =
      std::from_chars(digits.data(), digits.data() + digits.size(), value);
  const bool consumed = end == digits.data() + digits.size();
  if (error == std::errc::result_out_of_range && consumed) {
    throw InputError(file_name, line,
                     "a number of magnitude at most 1e9 for " + std::string(what), quoted(field));
  }
  if (error != std::errc() || !consumed || digits.empty()) {
    throw InputError(file_name, line, "a number for " + std::string(what), quoted(field));
  }
  if (!std::isfinite(value)) {
    throw InputError(file_name, line, "a finite number for " + std::string(what),
                     quoted(field));
  }
  if (std::fabs(value) > NumberReader::kMaxMagnitude) {
    throw InputError(file_name, line,
                     "a number of magnitude at most 1e9 for " + std::string(what), quoted(field));
  }
  return value;
}

long long parse_integer_field(std::string_view field, const std::string& file_name, int line,
                              std::string_view what) {
  const std::string_view digits = strip_plus(field);
  long long value = 0;
  const auto [end, error] =
      std::from_chars(digits.data(), digits.data() + digits.size(), value, 10);
  if (error != std::errc() || end != digits.data() + digits.size()) {
    throw InputError(file_name, line, "an integer for " + std::string(what), quoted(field));
  }
  return value;
}

NumberReader::NumberReader(std::string_view text, std::string file_name)
    : text_(text), file_name_(std::move(file_name)) {
  // Editors on Windows may prepend a UTF-8 byte-order mark; it is not content.
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text_.substr(0, kByteOrderMark.size()) == kByteOrderMark) {
    text_.remove_prefix(kByteOrderMark.size());
  }
  int lines = 0;
  for (const char c : text_) lines += (c == '\n');
  if (!text_.empty() && text_.back() != '\n') ++lines;
  end_line_ = lines + 1;
}

void NumberReader::fail(int line, std::string expected, std::string found) const {
  throw InputError(file_name_, line, std::move(expected), std::move(found));
}

bool NumberReader::peek(RawLine& out, std::string_view what) {
  std::size_t start = position_;
  int number = position_line_;
  while (start < text_.size()) {
    const std::size_t newline = text_.find('\n', start);
    const std::size_t stop = newline == std::string_view::npos ? text_.size() : newline;
    std::string_view content = text_.substr(start, stop - start);
    if (!content.empty() && content.back() == '\r') content.remove_suffix(1);
    if (content.size() > kMaxLineLength) {
      fail(number, "a line of at most 4096 characters",
           std::to_string(content.size()) + " characters");
    }
    if (const std::size_t hash = content.find('#'); hash != std::string_view::npos) {
      content = content.substr(0, hash);
    }
    // Split on commas first (an empty field between commas is an error, a trailing comma
    // is allowed), then on blanks inside each comma-separated part.
    out.fields.clear();
    bool any_comma = false;
    std::size_t part_start = 0;
    while (part_start <= content.size()) {
      const std::size_t comma = content.find(',', part_start);
      const std::size_t part_stop = comma == std::string_view::npos ? content.size() : comma;
      const std::string_view part = content.substr(part_start, part_stop - part_start);
      const std::size_t before = out.fields.size();
      std::size_t i = 0;
      while (i < part.size()) {
        while (i < part.size() && is_blank(part[i])) ++i;
        std::size_t j = i;
        while (j < part.size() && !is_blank(part[j])) ++j;
        if (j > i) out.fields.push_back(part.substr(i, j - i));
        i = j;
      }
      const bool last_part = comma == std::string_view::npos;
      if (out.fields.size() == before && (any_comma || !last_part)) {
        const bool trailing = last_part && before > 0;
        if (!trailing) fail(number, "a number for " + std::string(what), "an empty field");
      }
      if (last_part) break;
      any_comma = true;
      part_start = comma + 1;
    }
    const std::size_t next = newline == std::string_view::npos ? text_.size() : newline + 1;
    if (!out.fields.empty()) {
      out.line = number;
      peek_end_ = next;
      peek_end_line_ = number + 1;
      return true;
    }
    start = next;
    ++number;
  }
  // Only blank lines remain: they count as consumed.
  position_ = text_.size();
  position_line_ = number;
  return false;
}

void NumberReader::consume() {
  position_ = peek_end_;
  position_line_ = peek_end_line_;
  line_ = peek_end_line_ - 1;
}

NumberReader::RawLine NumberReader::next_or_fail(const std::string& expected,
                                                std::string_view what) {
  RawLine raw;
  if (!peek(raw, what)) fail(end_line_, expected, "end of file");
  consume();
  return raw;
}

bool NumberReader::at_end() {
  RawLine raw;
  return !peek(raw, "end of file");
}

NumberLine NumberReader::read_numbers(std::string_view what) {
  const RawLine raw = next_or_fail("numbers for " + std::string(what), what);
  NumberLine result;
  result.line = raw.line;
  result.values.reserve(raw.fields.size());
  for (const std::string_view field : raw.fields) {
    result.values.push_back(parse_number_field(field, file_name_, raw.line, what));
  }
  return result;
}

NumberLine NumberReader::read_numbers(std::size_t count, std::string_view what) {
  const std::string expected = plural(count, "number") + " for " + std::string(what);
  const RawLine raw = next_or_fail(expected, what);
  if (raw.fields.size() != count) fail(raw.line, expected, plural(raw.fields.size(), "number"));
  NumberLine result;
  result.line = raw.line;
  result.values.reserve(count);
  for (const std::string_view field : raw.fields) {
    result.values.push_back(parse_number_field(field, file_name_, raw.line, what));
  }
  return result;
}

double NumberReader::read_number(std::string_view what) {
  return read_numbers(1, what).values.front();
}

long long NumberReader::read_integer(std::string_view what, long long minimum,
                                     long long maximum) {
  const std::string expected = "an integer for " + std::string(what);
  const RawLine raw = next_or_fail(expected, what);
  if (raw.fields.size() != 1) {
    fail(raw.line, "a single integer for " + std::string(what),
         plural(raw.fields.size(), "field"));
  }
  const long long value = parse_integer_field(raw.fields.front(), file_name_, raw.line, what);
  if (value < minimum || value > maximum) {
    fail(raw.line,
         std::string(what) + " between " + std::to_string(minimum) + " and " +
             std::to_string(maximum),
         std::to_string(value));
  }
  return value;
}

std::optional<long long> NumberReader::read_keyword_integer(std::string_view keyword,
                                                            std::string_view what,
                                                            long long minimum,
                                                            long long maximum) {
  RawLine raw;
  if (!peek(raw, what) || !equal_ignoring_ascii_case(raw.fields.front(), keyword)) {
    return std::nullopt;
  }
  consume();
  const std::string form = "'" + std::string(keyword) + " k' with one integer k for ";
  if (raw.fields.size() != 2) {
    fail(raw.line, form + std::string(what), plural(raw.fields.size(), "field"));
  }
  const long long value = parse_integer_field(raw.fields[1], file_name_, raw.line, what);
  if (value < minimum || value > maximum) {
    fail(raw.line,
         std::string(what) + " between " + std::to_string(minimum) + " and " +
             std::to_string(maximum),
         std::to_string(value));
  }
  return value;
}

void NumberReader::expect_end(std::string_view after) {
  RawLine raw;
  if (peek(raw, "end of file")) {
    fail(raw.line, "end of file after " + std::string(after), quoted(raw.fields.front()));
  }
}

}  // namespace grpvss::io

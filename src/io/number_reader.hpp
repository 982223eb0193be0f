#pragma once
/// \file
/// \brief The shared line-oriented number tokenizer of every GRPVSS text input (robot,
/// environment and path files of thesis Appendix A.1; motion-time tables; certificates).
///
/// Syntax of one line: numbers separated by commas and/or blanks (spaces, tabs), a trailing
/// comma allowed, empty fields (`1,,2`) rejected. `#` starts a comment that runs to the end of
/// the line. Lines that are blank after removing the comment are skipped. A leading UTF-8
/// byte-order mark is ignored. A number is what
/// `std::from_chars` reads in general format (`2.`, `.5`, `1e3`, with an optional leading `+`);
/// it must be finite and satisfy \f$|x| \le 10^9\f$. Lines are at most 4096 characters long.
/// Every failure throws grpvss::InputError naming the file, the 1-based line, what was
/// expected and what was found.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace grpvss::io {

/// \brief The numbers of one input line and the line's 1-based number.
struct NumberLine {
  int line = 0;
  std::vector<double> values;
};

/// \brief Reads a text line by line as numbers. The text must outlive the reader.
class NumberReader {
 public:
  static constexpr std::size_t kMaxLineLength = 4096;  ///< characters, without the newline
  static constexpr double kMaxMagnitude = 1e9;         ///< largest accepted |x|

  NumberReader(std::string_view text, std::string file_name);

  const std::string& file_name() const noexcept { return file_name_; }
  /// 1-based number of the last line consumed (0 before the first).
  int line() const noexcept { return line_; }
  /// The line number reported for "found end of file": one past the file's last line.
  int end_line() const noexcept { return end_line_; }

  /// True when nothing but blank and comment lines remains.
  bool at_end();

  /// Reads the next content line, which must hold at least one number.
  /// \param what names the expected content for messages (e.g. "the joint row of joint 1").
  NumberLine read_numbers(std::string_view what);
  /// Reads the next content line, which must hold exactly `count` numbers.
  NumberLine read_numbers(std::size_t count, std::string_view what);
  /// Reads the next content line, which must hold exactly one number.
  double read_number(std::string_view what);
  /// Reads the next content line, which must hold exactly one integer literal (optional sign
  /// and decimal digits only: `2.` and `2.5` are rejected) within [minimum, maximum].
  long long read_integer(std::string_view what, long long minimum, long long maximum);
  /// If the next content line's first field is `keyword` (ASCII case-insensitive), consumes
  /// the line, which must read `keyword k` with one integer k in [minimum, maximum], and
  /// returns k. Otherwise consumes nothing and returns std::nullopt.
  std::optional<long long> read_keyword_integer(std::string_view keyword, std::string_view what,
                                                long long minimum, long long maximum);
  /// Requires that nothing but blank and comment lines remains.
  /// \param after names the last item read (e.g. "the last hull of link 4").
  void expect_end(std::string_view after);

  /// Throws InputError(file_name(), line, expected, found).
  [[noreturn]] void fail(int line, std::string expected, std::string found = {}) const;

 private:
  struct RawLine {
    int line = 0;
    std::vector<std::string_view> fields;
  };
  /// Finds the next content line without consuming it; false at end of text.
  /// `what` names the expected content for the messages of malformed lines.
  bool peek(RawLine& out, std::string_view what);
  /// Consumes the line last returned by peek().
  void consume();
  /// peek() + consume(), failing with "found end of file" when the text is exhausted.
  RawLine next_or_fail(const std::string& expected, std::string_view what);

  std::string_view text_;
  std::string file_name_;
  std::size_t position_ = 0;      ///< offset of the first unconsumed line
  int position_line_ = 1;         ///< 1-based number of the line at position_
  std::size_t peek_end_ = 0;      ///< offset after the peeked line
  int peek_end_line_ = 1;         ///< number of the line after the peeked line
  int line_ = 0;
  int end_line_ = 1;
};

/// \brief Parses one field as a finite number with |x| <= NumberReader::kMaxMagnitude.
/// \throws InputError(file_name, line, "a number in " + what, "'field'") otherwise.
double parse_number_field(std::string_view field, const std::string& file_name, int line,
                          std::string_view what);

/// \brief Parses one field as an integer literal (optional sign, decimal digits).
/// \throws InputError(file_name, line, "an integer " + what, "'field'") otherwise.
long long parse_integer_field(std::string_view field, const std::string& file_name, int line,
                              std::string_view what);

}  // namespace grpvss::io

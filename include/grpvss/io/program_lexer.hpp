#pragma once
/// \file
/// \brief The tokenizer and token cursor shared by the robot-program readers (URScript,
/// KUKA KRL, ABB RAPID). Lexical rules per dialect: docs/robot-programs.md#lexical-rules.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace grpvss::io {

/// Which language's lexical rules apply.
enum class ProgramDialect { kUrScript, kKrl, kRapid };

enum class TokenKind {
  kName,       ///< identifier; KRL also `$SYSVAR` and `#ENUM`
  kNumber,     ///< numeric literal (KRL bit/hex literals 'B0101', 'H1F' too)
  kString,     ///< string literal; text is the contents without the quotes
  kSymbol,     ///< punctuation: one character, or `:=` `==` `<>` `<=` `>=` `!=`
  kEndOfLine,  ///< one or more line ends (consecutive ones are merged)
};

/// \brief One token. `text` views the source text, which must outlive the token.
struct ProgramToken {
  TokenKind kind = TokenKind::kSymbol;
  int line = 0;  ///< 1-based
  std::string_view text;
  double number = 0.0;  ///< kNumber only
};

/// \brief Splits `text` into tokens; comments, blanks and the dialect's header lines are
/// dropped (URScript `$ ...` step labels, KRL `&...` lines, RAPID `%%%` blocks).
/// \throws InputError(file_name, line, expected, found) on a character outside the language,
/// an unterminated string or a malformed number.
std::vector<ProgramToken> tokenize_program(std::string_view text, const std::string& file_name,
                                           ProgramDialect dialect);

/// The number of the line after the text's last line (where "found end of file" is reported).
int line_after_text(std::string_view text);

/// For messages: `'text'` cut at 40 characters, control and non-ASCII bytes as \xNN.
std::string quote_source(std::string_view text);

/// A number for messages: shortest form with 6 significant digits (`0.1`, `-2.5`, `1e+10`).
std::string number_text(double value);

/// ASCII case-insensitive comparison (KRL and RAPID names are case-insensitive).
bool same_name(std::string_view a, std::string_view b);

/// The name in ASCII upper case (the lookup key of case-insensitive names).
std::string upper_name(std::string_view name);

/// \brief A half-open range of tokens forming one statement, and its first line.
struct TokenRange {
  std::size_t begin = 0;
  std::size_t end = 0;
  int line = 0;
};

/// \brief Splits tokens into statements at line ends (URScript's tokenizer emits no line end
/// inside brackets, so its statements continue there).
/// \throws InputError on an unmatched closing bracket or a bracket left open at the
/// statement's end.
std::vector<TokenRange> split_line_statements(const std::vector<ProgramToken>& tokens,
                                              const std::string& file_name);

/// \brief Reads one statement's tokens front to back; every failure throws InputError naming
/// the file, the line of the token at hand and what was expected.
class TokenCursor {
 public:
  /// Nesting of brackets the parsers accept (deeper input is rejected, never overflows).
  static constexpr int kMaxNesting = 64;

  TokenCursor(const std::vector<ProgramToken>& tokens, TokenRange range, std::string file_name);

  bool at_end() const noexcept { return position_ >= range_.end; }
  /// The token `ahead` places on; a kEndOfLine token with empty text past the end.
  const ProgramToken& peek(std::size_t ahead = 0) const noexcept;
  /// Consumes and returns the current token (fails at the end).
  const ProgramToken& next(std::string_view expected);
  bool peek_symbol(std::string_view symbol, std::size_t ahead = 0) const noexcept;
  bool peek_name(std::string_view name, std::size_t ahead = 0) const noexcept;
  /// Consumes the symbol if it is next.
  bool accept_symbol(std::string_view symbol);
  /// Consumes the name (case-insensitive) if it is next.
  bool accept_name(std::string_view name);
  void expect_symbol(std::string_view symbol, std::string_view expected);
  const ProgramToken& expect_name(std::string_view expected);
  /// Fails unless the whole range was consumed.
  void expect_end(std::string_view after);

  /// The line of the current token (the statement's last line past the end).
  int line() const noexcept;
  const std::string& file_name() const noexcept { return file_name_; }
  TokenRange range() const noexcept { return range_; }
  std::size_t position() const noexcept { return position_; }
  void set_position(std::size_t position) noexcept { position_ = position; }
  /// The statement's source tokens joined by spaces (for warnings), cut at 80 characters.
  std::string statement_text() const;

  /// Increments the nesting depth for the lifetime of the guard; fails beyond kMaxNesting.
  class NestingGuard {
   public:
    explicit NestingGuard(TokenCursor& cursor);
    ~NestingGuard();
    NestingGuard(const NestingGuard&) = delete;
    NestingGuard& operator=(const NestingGuard&) = delete;

   private:
    TokenCursor& cursor_;
  };

  /// Throws InputError(file, line(), expected, what the current token is).
  [[noreturn]] void fail(std::string expected) const;
  /// Throws InputError(file, line, expected, found).
  [[noreturn]] void fail_at(int line, std::string expected, std::string found) const;

 private:
  const std::vector<ProgramToken>& tokens_;
  TokenRange range_;
  std::string file_name_;
  std::size_t position_;
  int depth_ = 0;
};

/// The source text of tokens [begin, end) joined as written (`movel(p[0, 1], a=1)`, `PTP XP1
/// C_DIS`), cut at 80 characters, non-printable bytes as '?': for warnings and names.
std::string join_tokens(const std::vector<ProgramToken>& tokens, std::size_t begin,
                        std::size_t end);

/// How a token reads in messages: the quoted text, "a string \"..\"", "end of statement".
std::string describe_token(const ProgramToken& token);

}  // namespace grpvss::io

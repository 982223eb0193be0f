#include "grpvss/io/program_lexer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <system_error>

#include "grpvss/common/input_error.hpp"
#include "blank_char.hpp"

namespace grpvss::io {
namespace {

constexpr std::size_t kMaxQuoted = 40;

bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_name_char(char c) { return is_letter(c) || is_digit(c); }
char upper(char c) { return (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c; }

char comment_character(ProgramDialect dialect) {
  switch (dialect) {
    case ProgramDialect::kUrScript: return '#';
    case ProgramDialect::kKrl: return ';';
    case ProgramDialect::kRapid: return '!';
  }
  return '#';
}

/// The tokenizer's state over one text.
class Lexer {
 public:
  Lexer(std::string_view text, const std::string& file_name, ProgramDialect dialect)
      : text_(text), file_name_(file_name), dialect_(dialect) {}

  std::vector<ProgramToken> run() {
    constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
    if (text_.substr(0, kByteOrderMark.size()) == kByteOrderMark) at_ = kByteOrderMark.size();
    while (at_ < text_.size()) step();
    return std::move(tokens_);
  }

 private:
  [[noreturn]] void fail(std::string expected, std::string found) const {
    throw InputError(file_name_, line_, std::move(expected), std::move(found));
  }

  char peek(std::size_t ahead = 0) const {
    return at_ + ahead < text_.size() ? text_[at_ + ahead] : '\0';
  }

  void push(TokenKind kind, std::size_t begin, std::size_t end, double number = 0.0) {
    tokens_.push_back({kind, line_, text_.substr(begin, end - begin), number});
  }

  void end_line() {
    // URScript statements continue over line ends inside brackets.
    const bool continued = dialect_ == ProgramDialect::kUrScript && depth_ > 0;
    if (!continued && !tokens_.empty() && tokens_.back().kind != TokenKind::kEndOfLine) {
      tokens_.push_back({TokenKind::kEndOfLine, line_, {}, 0.0});
    }
    ++line_;
    ++at_;
    line_start_ = true;
  }

  void skip_to_line_end() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
  }

  /// Header lines that are not program content: URScript `$ n "label"` step markers, KRL
  /// `&ACCESS` lines, RAPID `%%%` ... `%%%` blocks.
  bool skip_header_line() {
    const char c = peek();
    if ((dialect_ == ProgramDialect::kUrScript && c == '$') ||
        (dialect_ == ProgramDialect::kKrl && c == '&')) {
      skip_to_line_end();
      return true;
    }
    if (dialect_ == ProgramDialect::kRapid && text_.substr(at_, 3) == "%%%") {
      skip_rapid_header();
      return true;
    }
    return false;
  }

  void skip_rapid_header() {
    const int first_line = line_;
    skip_to_line_end();
    while (at_ < text_.size()) {
      ++at_;  // the newline
      ++line_;
      std::size_t start = at_;
      while (start < text_.size() && is_blank(text_[start])) ++start;
      const bool closing = text_.substr(start, 3) == "%%%";
      at_ = start;
      skip_to_line_end();
      if (closing) return;
    }
    line_ = first_line;
    fail("a closing %%% line for the header opened here", "end of file");
  }

  void step() {
    const char c = peek();
    if (c == '\n') return end_line();
    if (is_blank(c)) {
      ++at_;
      return;
    }
    if (line_start_ && skip_header_line()) return;
    line_start_ = false;
    if (c == comment_character(dialect_)) return skip_to_line_end();
    if (is_letter(c) || (dialect_ == ProgramDialect::kKrl && (c == '$' || c == '#'))) {
      return read_name();
    }
    if (is_digit(c) || (c == '.' && is_digit(peek(1)))) return read_number();
    if (c == '"' || (dialect_ == ProgramDialect::kUrScript && c == '\'')) return read_string();
    if (c == '\'' && dialect_ == ProgramDialect::kKrl) return read_krl_bits();
    read_symbol();
  }

  void read_name() {
    const std::size_t begin = at_++;
    while (at_ < text_.size() && is_name_char(text_[at_])) ++at_;
    if (at_ - begin == 1 && !is_name_char(text_[begin])) {
      fail("a name after '" + std::string(1, text_[begin]) + "'", quote_source(text_.substr(begin, 2)));
    }
    push(TokenKind::kName, begin, at_);
  }

  void read_digits() {
    while (at_ < text_.size() && is_digit(text_[at_])) ++at_;
  }

  void read_number() {
    const std::size_t begin = at_;
    read_digits();
    if (peek() == '.') {
      ++at_;
      read_digits();
    }
    const char e = peek();
    if ((e == 'e' || e == 'E') &&
        (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
      at_ += 2;
      read_digits();
    }
    if (is_name_char(peek()) || peek() == '.') {
      std::size_t end = at_;
      while (end < text_.size() && (is_name_char(text_[end]) || text_[end] == '.')) ++end;
      fail("a number", quote_source(text_.substr(begin, end - begin)));
    }
    const std::string_view spelling = text_.substr(begin, at_ - begin);
    double value = 0.0;
    const auto [end, error] = std::from_chars(spelling.data(), spelling.data() + spelling.size(),
                                              value, std::chars_format::general);
    if (error != std::errc() || end != spelling.data() + spelling.size() || !std::isfinite(value)) {
      fail("a finite number", quote_source(spelling));
    }
    push(TokenKind::kNumber, begin, at_, value);
  }

  void read_string() {
    const char quote = peek();
    const std::size_t begin = ++at_;
    while (true) {
      const char c = peek();
      if (at_ >= text_.size() || c == '\n') fail("the closing " + std::string(1, quote) + " of a string", "end of line");
      if (c == quote && dialect_ == ProgramDialect::kRapid && peek(1) == quote) {
        at_ += 2;  // RAPID writes a quote inside a string as ""
        continue;
      }
      if (c == '\\' && dialect_ != ProgramDialect::kKrl && at_ + 1 < text_.size() &&
          text_[at_ + 1] != '\n') {
        at_ += 2;
        continue;
      }
      if (c == quote) break;
      ++at_;
    }
    push(TokenKind::kString, begin, at_);
    ++at_;
  }

  /// KRL bit and hex literals: 'B0101', 'H1F'.
  void read_krl_bits() {
    const std::size_t begin = at_;
    const char base = upper(peek(1));
    const std::size_t digits_begin = std::min(at_ + 2, text_.size());  // a ' may end the text
    std::size_t end = digits_begin;
    while (end < text_.size() && is_name_char(text_[end])) ++end;
    const std::string_view digits = text_.substr(digits_begin, end - digits_begin);
    const bool closed = end < text_.size() && text_[end] == '\'';
    unsigned long long value = 0;
    const int radix = base == 'B' ? 2 : 16;
    const auto [stop, error] =
        std::from_chars(digits.data(), digits.data() + digits.size(), value, radix);
    if ((base != 'B' && base != 'H') || !closed || digits.empty() || error != std::errc() ||
        stop != digits.data() + digits.size() || value > (1ull << 31)) {
      fail("a bit ('B0101') or hex ('H1F') literal of at most 31 bits",
           quote_source(text_.substr(begin, std::min(end + 1, text_.size()) - begin)));
    }
    at_ = end + 1;
    push(TokenKind::kNumber, begin, at_, static_cast<double>(value));
  }

  void read_symbol() {
    const char c = peek();
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x21 || byte >= 0x7f) fail("a program character", quote_source(text_.substr(at_, 1)));
    static constexpr std::string_view kPairs[] = {":=", "==", "<>", "<=", ">=", "!="};
    for (const std::string_view pair : kPairs) {
      if (text_.substr(at_, 2) == pair) {
        push(TokenKind::kSymbol, at_, at_ + 2);
        at_ += 2;
        return;
      }
    }
    if (c == '(' || c == '[' || c == '{') ++depth_;
    if ((c == ')' || c == ']' || c == '}') && depth_ > 0) --depth_;
    push(TokenKind::kSymbol, at_, at_ + 1);
    ++at_;
  }

  std::string_view text_;
  const std::string& file_name_;
  ProgramDialect dialect_;
  std::size_t at_ = 0;
  int line_ = 1;
  bool line_start_ = true;
  int depth_ = 0;  ///< brackets open (URScript joins lines inside them)
  std::vector<ProgramToken> tokens_;
};

bool is_opening(std::string_view s) { return s == "(" || s == "[" || s == "{"; }
bool is_closing(std::string_view s) { return s == ")" || s == "]" || s == "}"; }
char closing_of(char opening) { return opening == '(' ? ')' : opening == '[' ? ']' : '}'; }

bool is_symbol(const ProgramToken& token, std::string_view set) {
  return token.kind == TokenKind::kSymbol && token.text.size() == 1 &&
         set.find(token.text[0]) != std::string_view::npos;
}

/// Statement text for warnings: `movel(p[0, -1], a=1)`, `PTP XP1 C_DIS`, `MoveL p, v\V:=5`.
bool needs_space(const std::vector<ProgramToken>& tokens, std::size_t begin, std::size_t i) {
  const ProgramToken& previous = tokens[i - 1];
  const ProgramToken& token = tokens[i];
  if (is_symbol(previous, "([{.\\") || is_symbol(token, ")]},.:;\\")) return false;
  if (is_symbol(token, "([{") && previous.kind == TokenKind::kName) return false;
  if (is_symbol(token, "=") || is_symbol(previous, "=")) return false;
  const bool option = i >= begin + 2 && is_symbol(tokens[i - 2], "\\");
  if (token.text == ":=" && option) return false;
  if (previous.text == ":=" && i >= begin + 3 && is_symbol(tokens[i - 3], "\\")) return false;
  // No space after a sign that follows an operator, an opening bracket or a comma.
  const bool sign = is_symbol(previous, "-+");
  const bool unary = i == begin + 1 || (tokens[i - 2].kind == TokenKind::kSymbol && tokens[i - 2].text != ")" &&
                                        tokens[i - 2].text != "]" && tokens[i - 2].text != "}");
  return !(sign && unary);
}

}  // namespace

std::vector<ProgramToken> tokenize_program(std::string_view text, const std::string& file_name,
                                           ProgramDialect dialect) {
  return Lexer(text, file_name, dialect).run();
}

int line_after_text(std::string_view text) {
  int lines = 0;
  for (const char c : text) lines += (c == '\n');
  if (!text.empty() && text.back() != '\n') ++lines;
  return lines + 1;
}

std::string quote_source(std::string_view text) {
  const bool cut = text.size() > kMaxQuoted;
  std::string result = "'";
  for (const char c : text.substr(0, kMaxQuoted)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f) {
      static constexpr char kHex[] = "0123456789abcdef";
      result += "\\x";
      result += kHex[byte >> 4];
      result += kHex[byte & 0xf];
    } else {
      result += c;
    }
  }
  return result + (cut ? "...'" : "'");
}

std::string number_text(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

bool same_name(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (upper(a[i]) != upper(b[i])) return false;
  }
  return true;
}

std::string upper_name(std::string_view name) {
  std::string result(name);
  for (char& c : result) c = upper(c);
  return result;
}

std::vector<TokenRange> split_line_statements(const std::vector<ProgramToken>& tokens,
                                              const std::string& file_name) {
  std::vector<TokenRange> statements;
  std::string open;  // the brackets open at this point
  std::size_t begin = 0;
  const auto close_statement = [&](std::size_t end) {
    if (!open.empty()) {
      throw InputError(file_name, tokens[end - 1].line,
                       std::string("a closing '") + closing_of(open.back()) + "'",
                       "end of statement");
    }
    if (end > begin) statements.push_back({begin, end, tokens[begin].line});
  };
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const ProgramToken& token = tokens[i];
    if (token.kind == TokenKind::kEndOfLine) {
      close_statement(i);
      begin = i + 1;
      continue;
    }
    if (token.kind != TokenKind::kSymbol) continue;
    if (is_opening(token.text)) open += token.text[0];
    if (is_closing(token.text)) {
      if (open.empty() || closing_of(open.back()) != token.text[0]) {
        const std::string expected = open.empty() ? std::string("no closing bracket here")
                                                  : std::string("'") + closing_of(open.back()) + "'";
        throw InputError(file_name, token.line, expected, quote_source(token.text));
      }
      open.pop_back();
    }
  }
  close_statement(tokens.size());
  return statements;
}

std::string join_tokens(const std::vector<ProgramToken>& tokens, std::size_t begin,
                        std::size_t end) {
  constexpr std::size_t kMaxText = 80;
  std::string text;
  for (std::size_t i = begin; i < end && i < tokens.size() && text.size() <= kMaxText; ++i) {
    const ProgramToken& token = tokens[i];
    if (i > begin && needs_space(tokens, begin, i)) text += ' ';
    if (token.kind == TokenKind::kString) {
      text += '"' + std::string(token.text) + '"';
    } else {
      text += token.text;
    }
  }
  if (text.size() > kMaxText) text = text.substr(0, kMaxText) + "...";
  // Strings may hold any byte; warnings must stay printable.
  for (char& c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f) c = '?';
  }
  return text;
}

std::string describe_token(const ProgramToken& token) {
  switch (token.kind) {
    case TokenKind::kEndOfLine: return "end of statement";
    case TokenKind::kString: return "a string " + quote_source(token.text);
    default: return quote_source(token.text);
  }
}

TokenCursor::TokenCursor(const std::vector<ProgramToken>& tokens, TokenRange range,
                         std::string file_name)
    : tokens_(tokens), range_(range), file_name_(std::move(file_name)), position_(range.begin) {}

const ProgramToken& TokenCursor::peek(std::size_t ahead) const noexcept {
  static const ProgramToken kEnd{TokenKind::kEndOfLine, 0, {}, 0.0};
  return position_ + ahead < range_.end ? tokens_[position_ + ahead] : kEnd;
}

const ProgramToken& TokenCursor::next(std::string_view expected) {
  if (at_end()) fail(std::string(expected));
  return tokens_[position_++];
}

bool TokenCursor::peek_symbol(std::string_view symbol, std::size_t ahead) const noexcept {
  const ProgramToken& token = peek(ahead);
  return token.kind == TokenKind::kSymbol && token.text == symbol;
}

bool TokenCursor::peek_name(std::string_view name, std::size_t ahead) const noexcept {
  const ProgramToken& token = peek(ahead);
  return token.kind == TokenKind::kName && same_name(token.text, name);
}

bool TokenCursor::accept_symbol(std::string_view symbol) {
  if (!peek_symbol(symbol)) return false;
  ++position_;
  return true;
}

bool TokenCursor::accept_name(std::string_view name) {
  if (!peek_name(name)) return false;
  ++position_;
  return true;
}

void TokenCursor::expect_symbol(std::string_view symbol, std::string_view expected) {
  if (!accept_symbol(symbol)) fail(std::string(expected));
}

const ProgramToken& TokenCursor::expect_name(std::string_view expected) {
  if (peek().kind != TokenKind::kName) fail(std::string(expected));
  return tokens_[position_++];
}

void TokenCursor::expect_end(std::string_view after) {
  if (!at_end()) fail("end of statement after " + std::string(after));
}

int TokenCursor::line() const noexcept {
  if (position_ < range_.end) return tokens_[position_].line;
  return range_.end > range_.begin ? tokens_[range_.end - 1].line : range_.line;
}

std::string TokenCursor::statement_text() const {
  return join_tokens(tokens_, range_.begin, range_.end);
}

TokenCursor::NestingGuard::NestingGuard(TokenCursor& cursor) : cursor_(cursor) {
  if (++cursor_.depth_ > kMaxNesting) {
    --cursor_.depth_;
    cursor_.fail("an expression nested at most 64 deep");
  }
}

TokenCursor::NestingGuard::~NestingGuard() { --cursor_.depth_; }

void TokenCursor::fail(std::string expected) const {
  throw InputError(file_name_, line(), std::move(expected), describe_token(peek()));
}

void TokenCursor::fail_at(int line, std::string expected, std::string found) const {
  throw InputError(file_name_, line, std::move(expected), std::move(found));
}

}  // namespace grpvss::io

#include "urscript_blocks.hpp"

#include "grpvss/common/input_error.hpp"

namespace grpvss::io::urscript {
namespace {

LineKind classify(const ProgramToken& first) {
  if (first.kind != TokenKind::kName) return LineKind::kOther;
  static const std::map<std::string_view, LineKind> kKeywords = {
      {"def", LineKind::kDef},     {"thread", LineKind::kThread}, {"if", LineKind::kIf},
      {"elif", LineKind::kElif},   {"else", LineKind::kElse},     {"while", LineKind::kWhile},
      {"for", LineKind::kFor},     {"end", LineKind::kEnd}};
  const auto found = kKeywords.find(first.text);
  return found == kKeywords.end() ? LineKind::kOther : found->second;
}

bool opens_block(LineKind kind) {
  return kind == LineKind::kDef || kind == LineKind::kThread || kind == LineKind::kIf ||
         kind == LineKind::kWhile || kind == LineKind::kFor;
}

std::string keyword_of(LineKind kind) {
  switch (kind) {
    case LineKind::kDef: return "def";
    case LineKind::kThread: return "thread";
    case LineKind::kIf: return "if";
    case LineKind::kWhile: return "while";
    default: return "for";
  }
}

/// Skips a default value's tokens up to the ',' or ')' that ends it.
std::pair<std::size_t, std::size_t> default_value(TokenCursor& cursor) {
  const std::size_t begin = cursor.position();
  int depth = 0;
  while (!(depth == 0 && (cursor.peek_symbol(",") || cursor.peek_symbol(")")))) {
    const ProgramToken& token = cursor.next("')' closing the parameters");
    if (token.text == "(" || token.text == "[") ++depth;
    if (token.text == ")" || token.text == "]") --depth;
  }
  if (cursor.position() == begin) cursor.fail("a default value after '='");
  return {begin, cursor.position()};
}

/// `def name(a, b=1):` or `thread name():`
Function read_header(const std::vector<ProgramToken>& tokens, TokenRange range,
                     const std::string& file_name, LineKind kind) {
  TokenCursor cursor(tokens, range, file_name);
  const std::string keyword = keyword_of(kind);
  cursor.next(keyword);
  Function function;
  function.name = std::string(cursor.expect_name("a name after '" + keyword + "'").text);
  cursor.expect_symbol("(", "'(' after the " + keyword + " name");
  if (!cursor.accept_symbol(")")) {
    do {
      function.parameters.emplace_back(cursor.expect_name("a parameter name").text);
      function.defaults.push_back(
          cursor.accept_symbol("=") ? default_value(cursor) : std::pair<std::size_t, std::size_t>{});
    } while (cursor.accept_symbol(","));
    cursor.expect_symbol(")", "',' or ')' after a parameter");
  }
  cursor.expect_symbol(":", "':' at the end of the " + keyword + " line");
  cursor.expect_end(keyword + " " + function.name + "(...):");
  return function;
}

}  // namespace

Blocks analyse_blocks(const std::vector<ProgramToken>& tokens,
                      const std::vector<TokenRange>& statements, const std::string& file_name,
                      int end_line) {
  Blocks blocks;
  blocks.kinds.resize(statements.size());
  blocks.block_end.assign(statements.size(), 0);
  blocks.depth.assign(statements.size(), 0);
  std::vector<std::size_t> open;
  for (std::size_t i = 0; i < statements.size(); ++i) {
    const ProgramToken& first = tokens[statements[i].begin];
    const LineKind kind = classify(first);
    blocks.kinds[i] = kind;
    blocks.depth[i] = static_cast<int>(open.size());
    if (kind == LineKind::kElif || kind == LineKind::kElse) {
      if (open.empty() || blocks.kinds[open.back()] != LineKind::kIf) {
        throw InputError(file_name, first.line, "'" + std::string(first.text) + "' inside an if block",
                         "'" + std::string(first.text) + "' outside one");
      }
    }
    if (kind == LineKind::kEnd) {
      if (open.empty()) {
        throw InputError(file_name, first.line, "a statement ('end' closes no open block here)",
                         "'end'");
      }
      blocks.block_end[open.back()] = i;
      if (blocks.kinds[open.back()] == LineKind::kDef) {
        blocks.functions.at(std::string(tokens[statements[open.back()].begin + 1].text)).end = i;
      }
      open.pop_back();
      blocks.depth[i] = static_cast<int>(open.size());
    }
    if (kind == LineKind::kDef) {
      Function function = read_header(tokens, statements[i], file_name, kind);
      function.header = i;
      const auto [place, added] = blocks.functions.emplace(function.name, function);
      if (!added) {
        throw InputError(file_name, first.line,
                         "a function name not defined before (line " +
                             std::to_string(statements[place->second.header].line) + ")",
                         quote_source(function.name));
      }
    }
    if (kind == LineKind::kThread) read_header(tokens, statements[i], file_name, kind);
    if (opens_block(kind)) open.push_back(i);
  }
  if (!open.empty()) {
    const TokenRange& opener = statements[open.back()];
    throw InputError(file_name, end_line,
                     "an 'end' closing the '" + std::string(tokens[opener.begin].text) +
                         "' of line " + std::to_string(opener.line),
                     "end of file");
  }
  return blocks;
}

}  // namespace grpvss::io::urscript

#include "rapid_structure.hpp"

#include <algorithm>

#include "grpvss/common/input_error.hpp"

namespace grpvss::io::rapid {
namespace {

bool is_word(const ProgramToken& token, std::initializer_list<std::string_view> words) {
  return token.kind == TokenKind::kName &&
         std::any_of(words.begin(), words.end(), [&](std::string_view w) { return same_name(token.text, w); });
}

bool is_symbol(const ProgramToken& token, std::string_view symbol) {
  return token.kind == TokenKind::kSymbol && token.text == symbol;
}

/// The keyword that decides how a statement ends (after a LOCAL/TASK prefix).
const ProgramToken& leading_keyword(const std::vector<ProgramToken>& tokens, std::size_t start) {
  if (is_word(tokens[start], {"LOCAL", "TASK"}) && start + 1 < tokens.size()) return tokens[start + 1];
  return tokens[start];
}

/// Index one past the statement that starts at `start`, and whether a ';' ends it.
std::size_t statement_end(const std::vector<ProgramToken>& tokens, std::size_t start, bool& semicolon) {
  const ProgramToken& first = leading_keyword(tokens, start);
  semicolon = false;
  const auto until = [&](auto stop) {
    std::size_t i = start;
    while (i < tokens.size() && !stop(tokens[i])) ++i;
    return i;
  };
  if (is_word(first, {"MODULE", "ENDMODULE", "PROC", "ENDPROC", "FUNC", "ENDFUNC", "TRAP", "ENDTRAP", "RECORD",
                      "ENDRECORD", "ENDIF", "ENDWHILE", "ENDFOR", "ENDTEST", "ELSE", "TEST", "ERROR", "UNDO",
                      "BACKWARD"})) {
    return until([&](const ProgramToken& token) { return token.line != tokens[start].line; });
  }
  if (is_word(first, {"IF", "ELSEIF", "WHILE", "FOR"})) {
    const std::size_t i = until([](const ProgramToken& token) {
      return is_word(token, {"THEN", "DO"}) || is_symbol(token, ";");
    });
    if (i < tokens.size() && !is_symbol(tokens[i], ";")) return i + 1;
    semicolon = true;
    return i;
  }
  if (is_word(first, {"CASE", "DEFAULT"}) ||
      (first.kind == TokenKind::kName && start + 1 < tokens.size() && is_symbol(tokens[start + 1], ":"))) {
    const std::size_t i = until([](const ProgramToken& token) { return is_symbol(token, ":"); });
    return i < tokens.size() ? i + 1 : i;
  }
  semicolon = true;
  return until([](const ProgramToken& token) { return is_symbol(token, ";"); });
}

/// `[LOCAL] PROC name(params)`, `[LOCAL] FUNC type name(params)`, `[LOCAL] TRAP name`.
Routine read_header(TokenCursor& cursor) {
  Routine routine;
  cursor.accept_name("LOCAL");
  routine.kind = upper_name(cursor.next("PROC, FUNC or TRAP").text);
  if (routine.kind == "FUNC") cursor.expect_name("a return type after FUNC");
  routine.name = std::string(cursor.expect_name("a routine name").text);
  if (routine.kind == "TRAP") {
    cursor.expect_end("TRAP " + routine.name);
    return routine;
  }
  cursor.expect_symbol("(", "'(' after the routine name");
  if (!cursor.accept_symbol(")")) {
    bool alternative = false;
    do {
      Parameter parameter;
      parameter.optional = cursor.accept_symbol("\\") || alternative;
      if (!cursor.accept_name("VAR") && !cursor.accept_name("PERS")) cursor.accept_name("INOUT");
      parameter.type = upper_name(cursor.expect_name("a parameter type").text);
      parameter.name = upper_name(cursor.expect_name("a parameter name").text);
      if (cursor.accept_symbol("{")) {
        while (!cursor.accept_symbol("}")) cursor.next("'}' closing the array dimensions");
      }
      routine.parameters.push_back(parameter);
      alternative = cursor.accept_symbol("|");
    } while (alternative || cursor.accept_symbol(","));
    cursor.expect_symbol(")", "',' or ')' after a parameter");
  }
  cursor.expect_end("the routine header");
  return routine;
}

std::string end_keyword(const std::string& kind) { return "END" + kind; }

}  // namespace

std::vector<TokenRange> split_rapid_statements(const std::vector<ProgramToken>& tokens,
                                               const std::string& file_name, int end_line) {
  std::vector<TokenRange> statements;
  std::size_t start = 0;
  while (start < tokens.size()) {
    if (is_symbol(tokens[start], ";")) {  // an empty statement
      ++start;
      continue;
    }
    bool semicolon = false;
    const std::size_t end = statement_end(tokens, start, semicolon);
    if (semicolon && end >= tokens.size()) {
      throw InputError(file_name, end_line,
                       "';' ending the statement of line " + std::to_string(tokens[start].line),
                       "end of file");
    }
    statements.push_back({start, end, tokens[start].line});
    start = semicolon ? end + 1 : end;
  }
  return statements;
}

bool is_rapid_declaration(const TokenCursor& cursor) {
  const std::size_t at = (cursor.peek_name("LOCAL") || cursor.peek_name("TASK")) ? 1 : 0;
  return cursor.peek_name("VAR", at) || cursor.peek_name("PERS", at) || cursor.peek_name("CONST", at);
}

Structure analyse_structure(const std::vector<ProgramToken>& tokens,
                            const std::vector<TokenRange>& statements, const std::string& file_name,
                            int end_line, std::vector<ProgramWarning>& warnings) {
  enum class Place { kOutside, kModule, kRoutine, kRecord };
  Place place = Place::kOutside;
  Structure structure;
  int module_line = 0;
  for (std::size_t i = 0; i < statements.size(); ++i) {
    TokenCursor cursor(tokens, statements[i], file_name);
    const ProgramToken& keyword = leading_keyword(tokens, statements[i].begin);
    switch (place) {
      case Place::kOutside:
        if (!cursor.accept_name("MODULE")) cursor.fail("MODULE (RAPID code lives in modules)");
        cursor.expect_name("a module name");
        module_line = statements[i].line;
        place = Place::kModule;
        break;
      case Place::kModule:
        if (cursor.accept_name("ENDMODULE")) {
          cursor.expect_end("ENDMODULE");
          place = Place::kOutside;
        } else if (is_word(keyword, {"PROC", "FUNC", "TRAP"})) {
          Routine routine = read_header(cursor);
          routine.header = i;
          if (!structure.index.emplace(upper_name(routine.name), structure.routines.size()).second) {
            throw InputError(file_name, statements[i].line, "a routine name not used before", quote_source(routine.name));
          }
          structure.routines.push_back(std::move(routine));
          place = Place::kRoutine;
        } else if (is_word(keyword, {"RECORD"})) {
          warnings.push_back({file_name, statements[i].line, "not read: " + cursor.statement_text() + " (a user-defined data type)"});
          module_line = statements[i].line;
          place = Place::kRecord;
        } else if (is_word(keyword, {"ALIAS"})) {
          warnings.push_back({file_name, statements[i].line, "not read: " + cursor.statement_text()});
        } else if (is_rapid_declaration(cursor)) {
          structure.declarations.push_back(i);
        } else {
          cursor.fail("a data declaration, PROC, FUNC, TRAP or ENDMODULE in the module");
        }
        break;
      case Place::kRoutine: {
        Routine& routine = structure.routines.back();
        if (is_word(keyword, {"ENDPROC", "ENDFUNC", "ENDTRAP"})) {
          if (!same_name(keyword.text, end_keyword(routine.kind))) {
            cursor.fail(end_keyword(routine.kind) + " closing the " + routine.kind + " " + routine.name);
          }
          cursor.next("END");
          cursor.expect_end(end_keyword(routine.kind));
          routine.end = i;
          if (routine.body_end == 0) routine.body_end = i;
          place = Place::kModule;
        } else if (is_word(keyword, {"MODULE", "ENDMODULE", "PROC", "FUNC", "TRAP", "RECORD"})) {
          cursor.fail(end_keyword(routine.kind) + " closing the " + routine.kind + " " + routine.name +
                      " of line " + std::to_string(statements[routine.header].line));
        } else if (is_word(keyword, {"ERROR", "UNDO", "BACKWARD"}) && routine.body_end == 0) {
          routine.body_end = i;
        }
        break;
      }
      case Place::kRecord:
        if (cursor.accept_name("ENDRECORD")) place = Place::kModule;
        break;
    }
  }
  if (place == Place::kRoutine) {
    const Routine& routine = structure.routines.back();
    throw InputError(file_name, end_line,
                     end_keyword(routine.kind) + " closing the " + routine.kind + " " + routine.name +
                         " of line " + std::to_string(statements[routine.header].line),
                     "end of file");
  }
  if (place != Place::kOutside) {
    throw InputError(file_name, end_line,
                     std::string(place == Place::kRecord ? "ENDRECORD" : "ENDMODULE") +
                         " closing the block of line " + std::to_string(module_line),
                     "end of file");
  }
  return structure;
}

}  // namespace grpvss::io::rapid

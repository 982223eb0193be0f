#include "krl_routines.hpp"

#include "grpvss/common/input_error.hpp"

namespace grpvss::io::krl {
namespace {

/// `[GLOBAL] DEF name(p1:IN, p2:OUT)` or `[GLOBAL] DEFFCT type name(...)`.
Routine read_header(TokenCursor& cursor) {
  Routine routine;
  routine.function = cursor.accept_name("DEFFCT");
  if (!routine.function) cursor.next("DEF");
  if (routine.function) cursor.expect_name("a return type after DEFFCT");
  routine.name = std::string(cursor.expect_name("a routine name").text);
  cursor.expect_symbol("(", "'(' after the routine name");
  if (!cursor.accept_symbol(")")) {
    do {
      routine.parameters.push_back(upper_name(cursor.expect_name("a parameter name").text));
      if (cursor.accept_symbol(":")) {
        if (!cursor.accept_name("IN") && !cursor.accept_name("OUT")) cursor.fail("IN or OUT after ':'");
      }
    } while (cursor.accept_symbol(","));
    cursor.expect_symbol(")", "',' or ')' after a parameter");
  }
  cursor.expect_end("the routine header");
  return routine;
}

}  // namespace

Routines find_routines(const std::vector<ProgramToken>& tokens,
                       const std::vector<TokenRange>& statements, const std::string& file_name,
                       int end_line) {
  Routines routines;
  bool open = false;
  for (std::size_t i = 0; i < statements.size(); ++i) {
    TokenCursor cursor(tokens, statements[i], file_name);
    const std::size_t start = cursor.position();
    cursor.accept_name("GLOBAL");
    const bool header = cursor.peek_name("DEF") || cursor.peek_name("DEFFCT");
    const bool closer = cursor.position() == start && (cursor.peek_name("END") || cursor.peek_name("ENDFCT"));
    if (header) {
      if (open) {
        const Routine& current = routines.in_order.back();
        cursor.fail("END closing the DEF " + current.name + " of line " + std::to_string(statements[current.header].line));
      }
      Routine routine = read_header(cursor);
      routine.header = i;
      if (!routines.index.emplace(upper_name(routine.name), routines.in_order.size()).second) {
        throw InputError(file_name, statements[i].line, "a routine name not used before", quote_source(routine.name));
      }
      routines.in_order.push_back(std::move(routine));
      open = true;
    } else if (closer) {
      const bool fct = cursor.peek_name("ENDFCT");
      if (!open || routines.in_order.back().function != fct) {
        cursor.fail(open ? (fct ? "END closing the DEF" : "ENDFCT closing the DEFFCT")
                         : "DEF or DEFFCT (a .src holds routines only)");
      }
      cursor.next("END");
      cursor.expect_end("END");
      routines.in_order.back().end = i;
      open = false;
    } else if (!open) {
      cursor.set_position(start);
      cursor.fail("DEF or DEFFCT (a .src holds routines only)");
    }
  }
  if (open) {
    const Routine& current = routines.in_order.back();
    throw InputError(file_name, end_line,
                     std::string(current.function ? "ENDFCT" : "END") + " closing the " +
                         (current.function ? "DEFFCT " : "DEF ") + current.name + " of line " +
                         std::to_string(statements[current.header].line),
                     "end of file");
  }
  if (routines.in_order.empty()) {
    throw InputError(file_name, end_line, "a DEF ... END in the .src", "no DEF");
  }
  return routines;
}

}  // namespace grpvss::io::krl

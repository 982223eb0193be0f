#pragma once
// The block structure of a URScript text: which line opens or closes which block, and the
// functions (def) it defines (docs/robot-programs.md#urscript).

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "grpvss/io/program_lexer.hpp"

namespace grpvss::io::urscript {

enum class LineKind { kDef, kThread, kIf, kElif, kElse, kWhile, kFor, kEnd, kOther };

/// A `def name(p1, p2=default):` ... `end` block.
struct Function {
  std::string name;
  std::vector<std::string> parameters;
  /// Token ranges of default values (begin == end: no default).
  std::vector<std::pair<std::size_t, std::size_t>> defaults;
  std::size_t header = 0;  ///< statement index of the def line
  std::size_t end = 0;     ///< statement index of its end line
};

struct Blocks {
  std::vector<LineKind> kinds;         ///< per statement
  std::vector<std::size_t> block_end;  ///< per opening statement: index of its end
  std::vector<int> depth;              ///< blocks open before each statement
  std::map<std::string, Function> functions;
};

/// \brief Matches blocks and reads every def header.
/// \throws InputError on an unmatched end, elif/else outside an if, a block left open at the
/// end of the file (reported at `end_line`), a malformed def header or a repeated def name.
Blocks analyse_blocks(const std::vector<ProgramToken>& tokens,
                      const std::vector<TokenRange>& statements, const std::string& file_name,
                      int end_line);

}  // namespace grpvss::io::urscript

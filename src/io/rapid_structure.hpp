#pragma once
// The structure of a RAPID text: statements (ended by ';' or by their header line), modules,
// routines and module data (docs/robot-programs.md#abb-rapid).

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "grpvss/io/program_lexer.hpp"
#include "grpvss/model/robot_program.hpp"

namespace grpvss::io::rapid {

/// \brief Splits RAPID tokens (line ends already removed) into statements: most end at ';'
/// (excluded from the range); MODULE, PROC, FUNC, TRAP, RECORD headers and their END lines,
/// ELSE, TEST, ERROR, UNDO, BACKWARD end with their line; IF/ELSEIF at THEN (a compact IF at
/// ';'), WHILE/FOR at DO, CASE/DEFAULT and labels at ':'.
/// \throws InputError for a statement without its ';' (reported at `end_line`).
std::vector<TokenRange> split_rapid_statements(const std::vector<ProgramToken>& tokens,
                                               const std::string& file_name, int end_line);

struct Parameter {
  std::string name;  ///< upper case
  std::string type;  ///< upper case
  bool optional = false;
};

struct Routine {
  std::string name;  ///< as written
  std::string kind;  ///< PROC, FUNC or TRAP
  std::vector<Parameter> parameters;
  std::size_t header = 0;   ///< statement index of the header
  std::size_t body_end = 0; ///< the first statement not run: ERROR/UNDO/BACKWARD or the END
  std::size_t end = 0;      ///< statement index of ENDPROC/ENDFUNC/ENDTRAP
};

struct Structure {
  std::vector<Routine> routines;
  std::map<std::string, std::size_t> index;  ///< upper-case name -> routines index
  std::vector<std::size_t> declarations;     ///< module data statements, in order
};

/// \brief Finds modules, routines and module data. A statement outside a MODULE, a statement
/// in a module that is neither data nor a routine, a nested routine, a mismatched END or a
/// block left open at the end (reported at `end_line`) throws InputError. RECORD and ALIAS
/// definitions are warned about in `warnings` and skipped.
Structure analyse_structure(const std::vector<ProgramToken>& tokens,
                            const std::vector<TokenRange>& statements, const std::string& file_name,
                            int end_line, std::vector<ProgramWarning>& warnings);

/// True for a data declaration: [LOCAL | TASK] (VAR | PERS | CONST) ...
bool is_rapid_declaration(const TokenCursor& cursor);

}  // namespace grpvss::io::rapid

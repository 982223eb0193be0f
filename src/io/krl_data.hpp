#pragma once
// KUKA KRL data: declarations (DECL), assignments to variables, components and array
// elements, and the data files (.dat, $config.dat) that hold them
// (docs/robot-programs.md#kuka-krl).

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "grpvss/io/program_lexer.hpp"
#include "krl_value.hpp"
#include "program_recorder.hpp"

namespace grpvss::io::krl {

/// A declared or assigned variable (or array element).
struct Variable {
  std::string spelling;  ///< as written, for messages
  std::string type;      ///< upper-case declared type; "" when assigned without a DECL
  Value value;           ///< unknown (with the reason) until a value is given
  std::string file;
  int line = 0;
};

/// Variables by key: upper-case name, array elements as NAME[1] (krl::element_key).
using Scope = std::map<std::string, Variable>;

/// True if the statement at the cursor declares data: `DECL ...`, `GLOBAL DECL ...`, or a
/// built-in type followed by a name (`E6POS XP1={...}`: DECL is optional in KRL).
bool is_declaration(const TokenCursor& cursor);

/// \brief Reads a declaration `[GLOBAL] [DECL] [GLOBAL] [CONST] TYPE name[dims] [= value],
/// ...` into `scope`. Structure values without a type take the declared one.
void read_declaration(TokenCursor& cursor, Scope& scope, const Lookup& lookup);

/// The left side of an assignment: NAME [indices] (.COMPONENT)*.
struct Designator {
  std::string key;                      ///< upper-case name or element key
  std::string spelling;                 ///< as written
  std::vector<std::string> components;  ///< upper-case component path
  std::string unknown_index;            ///< why an index was not computed ("" if it was)
  int line = 0;
};

/// Reads a designator at the cursor.
Designator read_designator(TokenCursor& cursor, Evaluator& evaluator);

/// \brief Assigns `value` to the designated variable or component in `scope`. A structure
/// assigned to a structure keeps the components it does not give (KRL aggregate rule).
void assign(Scope& scope, const Designator& target, Value value, const std::string& file);

/// \brief Reads a data file (DEFDAT ... ENDDAT): declarations and assignments go into
/// `scope`; every other line is warned about.
void read_data_file(std::string_view text, const std::string& file_name, Scope& scope,
                    ProgramRecorder& recorder);

/// The lookup over a chain of scopes (innermost first) and the reader's fixed names.
Value lookup_variable(const std::vector<const Scope*>& scopes, const std::string& key,
                      const std::string& spelling);

}  // namespace grpvss::io::krl

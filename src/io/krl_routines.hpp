#pragma once
// The routines of a KRL .src: DEF ... END and DEFFCT ... ENDFCT blocks.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "grpvss/io/program_lexer.hpp"

namespace grpvss::io::krl {

struct Routine {
  std::string name;                     ///< as written
  std::vector<std::string> parameters;  ///< upper case
  std::size_t header = 0;               ///< statement index of the DEF line
  std::size_t end = 0;                  ///< statement index of its END line
  bool function = false;                ///< DEFFCT (not read)
};

struct Routines {
  std::vector<Routine> in_order;             ///< the first is the program
  std::map<std::string, std::size_t> index;  ///< upper-case name -> in_order index
};

/// \brief Finds every routine. A .src holds routines only: any statement outside them, a
/// nested DEF, an END without DEF, or a DEF left open at the end (reported at `end_line`)
/// throws InputError; so does a .src without any DEF.
Routines find_routines(const std::vector<ProgramToken>& tokens,
                       const std::vector<TokenRange>& statements, const std::string& file_name,
                       int end_line);

}  // namespace grpvss::io::krl

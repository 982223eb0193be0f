#pragma once
// KUKA KRL values and expressions as the reader evaluates them
// (docs/robot-programs.md#kuka-krl).

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grpvss/io/program_lexer.hpp"

namespace grpvss::io::krl {

/// \brief A KRL value: number (INT and REAL alike), boolean, string, enum (#NAME), structure
/// ({TYPE: NAME value, ...}) or unknown (a value the reader does not compute, and why).
struct Value {
  enum class Kind { kNumber, kBoolean, kString, kEnum, kStructure, kUnknown };
  Kind kind = Kind::kUnknown;
  double number = 0.0;
  bool boolean = false;
  /// kString: contents; kEnum: upper-case name without '#'; kStructure: upper-case type
  /// (empty when not known); kUnknown: the reason, used in messages.
  std::string text;
  std::vector<std::string> names;  ///< kStructure: upper-case component names, in order
  std::vector<Value> values;       ///< kStructure: component values

  static Value of_number(double number);
  static Value unknown(std::string reason);
  static Value structure(std::string type);

  bool is_unknown() const { return kind == Kind::kUnknown; }
  /// The component (case-insensitive), or nullptr.
  const Value* component(std::string_view name) const;
  /// Sets or appends the component.
  void set_component(const std::string& name, Value value);
};

/// "a number", "a structure E6POS", ... (the reason for an unknown value).
std::string describe(const Value& value);

/// Finds a name's value: `key` is upper case, array elements as `NAME[1]`, `NAME[1,2]`.
/// Returns an unknown value (with the reason) for names the program does not define.
using Lookup = std::function<Value(const std::string& key, const std::string& spelling, int line)>;

/// An array index as written: an integer, or empty (`TOOL_NAME[1,]`, `NAME[]`: a whole CHAR row).
using Index = std::optional<long long>;

/// \brief The key of an array element: `NAME[i]`, `NAME[i,j]`, `NAME[i,]`.
std::string element_key(const std::string& name, const std::vector<Index>& indices);

/// \brief Recursive-descent evaluation at the cursor (KRL precedence: OR/EXOR, AND, NOT,
/// comparisons, + -, * /, the geometric operator ':', unary -, postfix .component).
class Evaluator {
 public:
  Evaluator(TokenCursor& cursor, Lookup lookup) : cursor_(cursor), lookup_(std::move(lookup)) {}

  Value expression();
  /// `[i]`, `[i, j]`, `[i,]` at the cursor; `unknown` receives the reason when an index is
  /// not computed.
  std::vector<Index> indices(std::string& unknown);

 private:
  Value logical();
  Value conjunction();
  Value negation();
  Value comparison();
  Value sum();
  Value product();
  Value geometric();
  Value unary();
  Value postfix();
  Value primary();
  Value aggregate();
  Value name_value(const ProgramToken& name);
  Value function_call(const ProgramToken& name);
  Value arithmetic(const std::string& op, const Value& left, const Value& right, int line);
  Value compose(const Value& left, const Value& right, int line);

  TokenCursor& cursor_;
  Lookup lookup_;
};

/// The FRAME components X, Y, Z (mm), A, B, C (degrees) of a structure, absent ones 0.
struct FrameComponents {
  double x = 0, y = 0, z = 0, a = 0, b = 0, c = 0;
};
FrameComponents frame_components(const Value& structure);
/// A FRAME structure with these components.
Value frame_value(const FrameComponents& frame);

}  // namespace grpvss::io::krl

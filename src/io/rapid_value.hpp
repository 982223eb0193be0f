#pragma once
// ABB RAPID values and expressions as the reader evaluates them
// (docs/robot-programs.md#abb-rapid).

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "grpvss/io/program_lexer.hpp"

namespace grpvss::io::rapid {

/// \brief A RAPID value: num, bool, string, aggregate ([a, b, ...]: records and arrays) or
/// unknown (a value the reader does not compute; `text` says why).
struct Value {
  enum class Kind { kNumber, kBoolean, kString, kAggregate, kUnknown };
  Kind kind = Kind::kUnknown;
  double number = 0.0;
  bool boolean = false;
  std::string text;              ///< kString: contents; kUnknown: the reason
  std::vector<Value> elements;   ///< kAggregate
  std::string type;              ///< upper-case data type when known ("ROBTARGET"), else ""
  bool array = false;            ///< an array of `type` (elements are the items)

  static Value of_number(double number);
  static Value of_boolean(bool value);
  static Value unknown(std::string reason);
  static Value aggregate(std::vector<Value> elements, std::string type = {});
  bool is_unknown() const { return kind == Kind::kUnknown; }
};

/// "a num", "an aggregate of 4 items", ... (the reason for an unknown value).
std::string describe(const Value& value);

/// A record type's components: name (upper case) and type (upper case).
struct Component {
  std::string name;
  std::string type;
};
/// The components of a RAPID record type the reader knows (robtarget, pose, ...); nullptr
/// for num, bool, string and unknown types.
const std::vector<Component>* record_components(const std::string& type);

/// \brief Checks a value against a known type recursively (aggregate lengths, nums, bools)
/// and returns it tagged with the type. Returns "" on success, else what was expected.
std::string conform(Value& value, const std::string& type);

/// The first unknown part of a value (itself, or an item at any depth); nullptr if none.
const Value* first_unknown_part(const Value& value);

/// An argument of a call: positional expression or `\Name[:=expr]` (range begin == end for
/// a switch).
struct Argument {
  std::string name;  ///< upper case for optional arguments; "" for positional ones
  std::string spelling;
  std::size_t begin = 0;
  std::size_t end = 0;
};

/// Finds a variable (upper-case name); an unknown value with the reason when not declared.
using Lookup = std::function<Value(const std::string& key, const std::string& spelling)>;

/// \brief Recursive-descent evaluation at the cursor: OR/XOR, AND, NOT, comparisons,
/// + -, * / DIV MOD, unary -, postfix {index} and .component; Offs() and RelTool().
class Evaluator {
 public:
  Evaluator(TokenCursor& cursor, Lookup lookup) : cursor_(cursor), lookup_(std::move(lookup)) {}

  Value expression();
  /// Reads an argument list up to `closing` (")" for functions, ";"-less end for
  /// procedures: pass "") without evaluating it.
  std::vector<Argument> arguments(std::string_view closing);
  /// Evaluates the expression of an argument.
  Value evaluate(const Argument& argument);
  /// Component access on a value, following record_components().
  Value component(const Value& value, const std::string& name, int line);
  /// Array element (1-based).
  Value element(const Value& value, const Value& index, int line);

 private:
  Value disjunction();
  Value conjunction();
  Value negation();
  Value comparison();
  Value sum();
  Value product();
  Value unary();
  Value postfix();
  Value primary();
  Value aggregate();
  Value function_call(const ProgramToken& name);
  Value arithmetic(const std::string& op, const Value& left, const Value& right, int line);
  void skip_expression(std::string_view closing);

  TokenCursor& cursor_;
  Lookup lookup_;
};

}  // namespace grpvss::io::rapid

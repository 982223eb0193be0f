#pragma once
// URScript values and expressions as the reader evaluates them (docs/robot-programs.md#urscript).

#include <functional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <Eigen/Geometry>

#include "grpvss/io/program_lexer.hpp"

namespace grpvss::io::urscript {

/// A value the reader does not compute, and why (used in messages: "..., found <reason>").
struct Unknown {
  std::string reason;
};

using NumberList = std::vector<double>;

/// `get_inverse_kin(x, qnear)`: the joints of pose x (active TCP) nearest qnear (empty: none given).
struct InverseKinematics {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  NumberList qnear;
};

/// A URScript value: number, boolean, string, list of numbers, pose (X, SI), the joints of an
/// inverse-kinematics call, or unknown.
using Value = std::variant<double, bool, std::string, NumberList, Eigen::Isometry3d, InverseKinematics, Unknown>;

/// "a number", "a pose", ... for messages.
std::string describe(const Value& value);

/// Finds a variable's value; nullptr when the program has not assigned it.
using Lookup = std::function<const Value*(std::string_view name)>;

/// An argument of a call: `name=` when given by name, else empty.
struct CallArgument {
  std::string name;
  std::size_t begin = 0;  ///< token positions of the argument's expression
  std::size_t end = 0;
};

/// \brief Recursive-descent evaluation of one expression at the cursor (Python-like
/// precedence: or, and, not, comparisons, + -, * / %, unary -, postfix [i] and .member).
class Evaluator {
 public:
  Evaluator(TokenCursor& cursor, Lookup lookup) : cursor_(cursor), lookup_(std::move(lookup)) {}

  Value expression();

  /// Reads `( arg, name=arg, ... )` without evaluating the arguments (the cursor is at '(').
  std::vector<CallArgument> call_arguments();
  /// Evaluates the expression between two token positions (an argument).
  Value evaluate_range(std::size_t begin, std::size_t end);

 private:
  Value logical_or();
  Value logical_and();
  Value logical_not();
  Value comparison();
  Value sum();
  Value product();
  Value unary();
  Value postfix();
  Value primary();
  Value name_value(const ProgramToken& name);
  Value function_call(const ProgramToken& name);
  Value builtin(const std::string& name, const std::vector<Value>& arguments, int line);
  Value inverse_kinematics(const std::vector<CallArgument>& arguments, int line);
  Value pose_literal();
  Value list_literal();
  Value arithmetic(const std::string& op, const Value& left, const Value& right, int line);
  Value element(const Value& container, const Value& index, int line);

  TokenCursor& cursor_;
  Lookup lookup_;
};

}  // namespace grpvss::io::urscript

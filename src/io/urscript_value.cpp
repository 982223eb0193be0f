#include "urscript_value.hpp"

#include <cmath>
#include <algorithm>
#include <map>
#include <optional>

#include "grpvss/io/program_orientation.hpp"
#include "grpvss/io/units.hpp"

namespace grpvss::io::urscript {
namespace {

constexpr double kPi = 3.14159265358979323846;

const Unknown* unknown_of(const Value& value) { return std::get_if<Unknown>(&value); }

/// The first unknown operand, if any: an expression with an unknown part is unknown.
std::optional<Value> first_unknown(const std::vector<Value>& values) {
  for (const Value& value : values) {
    if (unknown_of(value)) return value;
  }
  return std::nullopt;
}

Value condition_value(const Value& left, const Value& right) {
  if (unknown_of(left)) return left;
  if (unknown_of(right)) return right;
  return Unknown{"a condition (conditions are not evaluated)"};
}

Value finite_or_unknown(double value, const std::string& what) {
  if (!std::isfinite(value)) return Unknown{what + " that is not a finite number"};
  return value;
}

}  // namespace

std::string describe(const Value& value) {
  struct Describer {
    std::string operator()(double) const { return "a number"; }
    std::string operator()(bool) const { return "a boolean"; }
    std::string operator()(const std::string&) const { return "a string"; }
    std::string operator()(const NumberList& list) const {
      return "a list of " + std::to_string(list.size()) + " numbers";
    }
    std::string operator()(const Eigen::Isometry3d&) const { return "a pose"; }
    std::string operator()(const InverseKinematics&) const { return "the joints of get_inverse_kin()"; }
    std::string operator()(const Unknown& unknown) const { return unknown.reason; }
  };
  return std::visit(Describer{}, value);
}

Value Evaluator::expression() { return logical_or(); }

Value Evaluator::logical_or() {
  Value left = logical_and();
  while (cursor_.accept_name("or") || cursor_.accept_name("xor")) {
    left = condition_value(left, logical_and());
  }
  return left;
}

Value Evaluator::logical_and() {
  Value left = logical_not();
  while (cursor_.accept_name("and")) left = condition_value(left, logical_not());
  return left;
}

Value Evaluator::logical_not() {
  if (!cursor_.accept_name("not")) return comparison();
  TokenCursor::NestingGuard guard(cursor_);
  const Value operand = logical_not();
  return condition_value(operand, operand);
}

Value Evaluator::comparison() {
  Value left = sum();
  static constexpr std::string_view kComparisons[] = {"==", "!=", "<", ">", "<=", ">="};
  while (true) {
    bool matched = false;
    for (const std::string_view op : kComparisons) matched = matched || cursor_.accept_symbol(op);
    if (!matched) return left;
    left = condition_value(left, sum());
  }
}

Value Evaluator::sum() {
  Value left = product();
  while (cursor_.peek_symbol("+") || cursor_.peek_symbol("-")) {
    const ProgramToken& op = cursor_.next("an operator");
    left = arithmetic(std::string(op.text), left, product(), op.line);
  }
  return left;
}

Value Evaluator::product() {
  Value left = unary();
  while (cursor_.peek_symbol("*") || cursor_.peek_symbol("/") || cursor_.peek_symbol("%")) {
    const ProgramToken& op = cursor_.next("an operator");
    left = arithmetic(std::string(op.text), left, unary(), op.line);
  }
  return left;
}

Value Evaluator::unary() {
  if (!cursor_.peek_symbol("-") && !cursor_.peek_symbol("+")) return postfix();
  const ProgramToken& op = cursor_.next("an operator");
  TokenCursor::NestingGuard guard(cursor_);
  const Value operand = unary();
  if (op.text == "+" || unknown_of(operand)) return operand;
  if (const double* number = std::get_if<double>(&operand)) return -*number;
  cursor_.fail_at(op.line, "a number after unary '-'", describe(operand));
}

Value Evaluator::postfix() {
  Value value = primary();
  while (cursor_.peek_symbol("[") || cursor_.peek_symbol(".")) {
    const int line = cursor_.line();
    if (cursor_.accept_symbol(".")) {
      const ProgramToken& member = cursor_.expect_name("a member name after '.'");
      value = Unknown{"a member access ." + std::string(member.text) + " (not evaluated)"};
      continue;
    }
    cursor_.expect_symbol("[", "'['");
    TokenCursor::NestingGuard guard(cursor_);
    const Value index = expression();
    cursor_.expect_symbol("]", "']' after the index");
    value = element(value, index, line);
  }
  return value;
}

Value Evaluator::element(const Value& container, const Value& index, int line) {
  if (unknown_of(container)) return container;
  if (unknown_of(index)) return index;
  const double* i = std::get_if<double>(&index);
  if (!i || *i != std::floor(*i)) cursor_.fail_at(line, "an integer index", describe(index));
  if (const NumberList* list = std::get_if<NumberList>(&container)) {
    if (*i < 0 || *i >= static_cast<double>(list->size())) {
      cursor_.fail_at(line, "an index below " + std::to_string(list->size()), number_text(*i));
    }
    return (*list)[static_cast<std::size_t>(*i)];
  }
  if (std::holds_alternative<InverseKinematics>(container)) {
    return Unknown{"an element of get_inverse_kin() (its joint values are not computed)"};
  }
  if (const auto* pose = std::get_if<Eigen::Isometry3d>(&container)) {
    if (*i < 0 || *i > 5) {
      cursor_.fail_at(line, "a pose index 0..5", number_text(*i));
    }
    return urscript_pose_vector(*pose)[static_cast<int>(*i)];
  }
  cursor_.fail_at(line, "a list or pose before '['", describe(container));
}

Value Evaluator::primary() {
  TokenCursor::NestingGuard guard(cursor_);
  const ProgramToken& token = cursor_.peek();
  if (token.kind == TokenKind::kNumber) return cursor_.next("a number").number;
  if (token.kind == TokenKind::kString) return std::string(cursor_.next("a string").text);
  if (token.kind == TokenKind::kName) {
    if (token.text == "p" && cursor_.peek_symbol("[", 1)) return pose_literal();
    const ProgramToken& name = cursor_.next("a name");
    if (name.text == "True") return true;
    if (name.text == "False") return false;
    if (cursor_.peek_symbol("(")) return function_call(name);
    return name_value(name);
  }
  if (cursor_.peek_symbol("[")) return list_literal();
  if (cursor_.accept_symbol("(")) {
    Value value = expression();
    cursor_.expect_symbol(")", "')'");
    return value;
  }
  cursor_.fail("an expression");
}

Value Evaluator::name_value(const ProgramToken& name) {
  if (const Value* value = lookup_(name.text)) return *value;
  if (name.text == "pi") return kPi;
  return Unknown{"'" + std::string(name.text) + "', which this program does not assign before line " +
                 std::to_string(name.line)};
}

std::vector<CallArgument> Evaluator::call_arguments() {
  cursor_.expect_symbol("(", "'('");
  std::vector<CallArgument> arguments;
  if (cursor_.accept_symbol(")")) return arguments;
  while (true) {
    CallArgument argument;
    if (cursor_.peek().kind == TokenKind::kName && cursor_.peek_symbol("=", 1)) {
      argument.name = std::string(cursor_.next("a name").text);
      cursor_.next("'='");
    }
    argument.begin = cursor_.position();
    int depth = 0;
    while (!(depth == 0 && (cursor_.peek_symbol(",") || cursor_.peek_symbol(")")))) {
      const ProgramToken& token = cursor_.next("')' closing the arguments");
      if (token.kind != TokenKind::kSymbol) continue;
      if (token.text == "(" || token.text == "[" || token.text == "{") ++depth;
      if (token.text == ")" || token.text == "]" || token.text == "}") --depth;
    }
    argument.end = cursor_.position();
    if (argument.end == argument.begin) cursor_.fail("an argument");
    arguments.push_back(std::move(argument));
    if (cursor_.accept_symbol(")")) return arguments;
    cursor_.expect_symbol(",", "',' or ')'");
  }
}

Value Evaluator::evaluate_range(std::size_t begin, std::size_t end) {
  const std::size_t resume = cursor_.position();
  cursor_.set_position(begin);
  Value value = expression();
  if (cursor_.position() != end) cursor_.fail("',' or ')' after the argument");
  cursor_.set_position(resume);
  return value;
}

Value Evaluator::function_call(const ProgramToken& name) {
  const std::vector<CallArgument> arguments = call_arguments();
  if (name.text == "get_inverse_kin") return inverse_kinematics(arguments, name.line);
  std::vector<Value> values;
  for (const CallArgument& argument : arguments) {
    values.push_back(evaluate_range(argument.begin, argument.end));
  }
  return builtin(std::string(name.text), values, name.line);
}

/// get_inverse_kin(x, qnear, maxPositionError, maxOrientationError, tcp): read as the pose x
/// with the configuration nearest qnear; a `tcp` other than the active one is not read.
Value Evaluator::inverse_kinematics(const std::vector<CallArgument>& arguments, int line) {
  static const std::vector<std::string> kParameters = {"x", "qnear", "maxPositionError", "maxOrientationError", "tcp"};
  std::map<std::string, Value> bound;
  std::size_t positional = 0;
  for (const CallArgument& argument : arguments) {
    const std::string parameter = argument.name.empty() && positional < kParameters.size() ? kParameters[positional++] : argument.name;
    if (std::find(kParameters.begin(), kParameters.end(), parameter) == kParameters.end()) {
      cursor_.fail_at(line, "an argument of get_inverse_kin (x, qnear, maxPositionError, maxOrientationError, tcp)",
                      parameter.empty() ? "a sixth argument" : quote_source(parameter));
    }
    if (!bound.emplace(parameter, evaluate_range(argument.begin, argument.end)).second) {
      cursor_.fail_at(line, "one value for " + parameter + " of get_inverse_kin", "a second one");
    }
  }
  if (!bound.count("x")) cursor_.fail_at(line, "a pose x for get_inverse_kin", "none");
  if (bound.count("tcp")) return Unknown{"get_inverse_kin() for a tcp= other than the active one (not read)"};
  for (const auto& [parameter, value] : bound) {
    if (unknown_of(value)) return value;
  }
  InverseKinematics result;
  const auto* pose = std::get_if<Eigen::Isometry3d>(&bound.at("x"));
  if (!pose) cursor_.fail_at(line, "a pose x for get_inverse_kin", describe(bound.at("x")));
  result.pose = *pose;
  if (bound.count("qnear")) {
    const auto* qnear = std::get_if<NumberList>(&bound.at("qnear"));
    if (!qnear || qnear->size() != 6) cursor_.fail_at(line, "6 joint values for qnear of get_inverse_kin", describe(bound.at("qnear")));
    result.qnear = *qnear;
  }
  return result;
}

Value Evaluator::builtin(const std::string& name, const std::vector<Value>& arguments, int line) {
  static const std::vector<std::pair<std::string, std::size_t>> kNumeric = {
      {"d2r", 1}, {"r2d", 1}, {"sqrt", 1}, {"sin", 1}, {"cos", 1}, {"tan", 1}, {"atan2", 2}};
  static const std::vector<std::pair<std::string, std::size_t>> kPoses = {
      {"pose_trans", 2}, {"pose_inv", 1}, {"pose_add", 2}};
  std::size_t count = 0;
  bool poses = false;
  for (const auto& [known, arity] : kNumeric) count = known == name ? arity : count;
  for (const auto& [known, arity] : kPoses) {
    if (known == name) {
      count = arity;
      poses = true;
    }
  }
  if (count == 0) return Unknown{name + "(), which the reader does not evaluate"};
  if (arguments.size() != count) {
    cursor_.fail_at(line, std::to_string(count) + " argument" + (count == 1 ? "" : "s") +
                              " for " + name, std::to_string(arguments.size()));
  }
  if (auto unknown = first_unknown(arguments)) return *unknown;
  for (const Value& argument : arguments) {
    const bool fits = poses ? std::holds_alternative<Eigen::Isometry3d>(argument)
                            : std::holds_alternative<double>(argument);
    if (!fits) cursor_.fail_at(line, std::string(poses ? "poses" : "numbers") + " for " + name, describe(argument));
  }
  if (poses) {
    const auto& a = std::get<Eigen::Isometry3d>(arguments[0]);
    if (name == "pose_inv") return Value(a.inverse());
    const auto& b = std::get<Eigen::Isometry3d>(arguments[1]);
    if (name == "pose_trans") return Value(Eigen::Isometry3d(a * b));
    Eigen::Isometry3d sum = Eigen::Isometry3d::Identity();  // pose_add
    sum.translation() = a.translation() + b.translation();
    sum.linear() = a.linear() * b.linear();
    return Value(sum);
  }
  const double x = std::get<double>(arguments[0]);
  if (name == "d2r") return degrees_to_radians(x);
  if (name == "r2d") return x / kRadiansPerDegree;
  if (name == "sqrt") return finite_or_unknown(std::sqrt(x), "sqrt of a negative number");
  if (name == "sin") return std::sin(x);
  if (name == "cos") return std::cos(x);
  if (name == "tan") return finite_or_unknown(std::tan(x), "tan");
  return std::atan2(x, std::get<double>(arguments[1]));
}

Value Evaluator::pose_literal() {
  const int line = cursor_.line();
  cursor_.next("p");
  const Value list = list_literal();
  if (unknown_of(list)) return list;
  const NumberList* numbers = std::get_if<NumberList>(&list);
  if (!numbers || numbers->size() != 6) {
    cursor_.fail_at(line, "6 numbers in p[x, y, z, rx, ry, rz]", describe(list));
  }
  Eigen::Matrix<double, 6, 1> p;
  for (int i = 0; i < 6; ++i) p[i] = (*numbers)[static_cast<std::size_t>(i)];
  return Value(urscript_pose(p));
}

Value Evaluator::list_literal() {
  cursor_.expect_symbol("[", "'['");
  NumberList numbers;
  std::optional<Value> unknown;
  bool non_numbers = false;
  if (cursor_.accept_symbol("]")) return numbers;
  do {
    const Value element = expression();
    if (unknown_of(element)) {
      if (!unknown) unknown = element;
    } else if (const double* number = std::get_if<double>(&element)) {
      numbers.push_back(*number);
    } else {
      non_numbers = true;
    }
  } while (cursor_.accept_symbol(","));
  cursor_.expect_symbol("]", "',' or ']' in the list");
  if (unknown) return *unknown;
  if (non_numbers) return Unknown{"a list of non-numbers (not read)"};
  return numbers;
}

Value Evaluator::arithmetic(const std::string& op, const Value& left, const Value& right,
                            int line) {
  if (unknown_of(left)) return left;
  if (unknown_of(right)) return right;
  const double* a = std::get_if<double>(&left);
  const double* b = std::get_if<double>(&right);
  if (!a || !b) {
    cursor_.fail_at(line, "numbers for '" + op + "'", describe(a ? right : left));
  }
  if (op == "+") return finite_or_unknown(*a + *b, "a sum");
  if (op == "-") return finite_or_unknown(*a - *b, "a difference");
  if (op == "*") return finite_or_unknown(*a * *b, "a product");
  if (*b == 0.0) return Unknown{"a division by zero"};
  if (op == "/") return finite_or_unknown(*a / *b, "a quotient");
  return finite_or_unknown(std::fmod(*a, *b), "a remainder");
}

}  // namespace grpvss::io::urscript

#include "rapid_value.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "grpvss/io/program_orientation.hpp"
#include "grpvss/io/units.hpp"

namespace grpvss::io::rapid {
namespace {

const std::map<std::string, std::vector<Component>>& record_table() {
  static const std::map<std::string, std::vector<Component>> kTable = {
      {"ROBTARGET", {{"TRANS", "POS"}, {"ROT", "ORIENT"}, {"ROBCONF", "CONFDATA"}, {"EXTAX", "EXTJOINT"}}},
      {"JOINTTARGET", {{"ROBAX", "ROBJOINT"}, {"EXTAX", "EXTJOINT"}}},
      {"POSE", {{"TRANS", "POS"}, {"ROT", "ORIENT"}}},
      {"POS", {{"X", "NUM"}, {"Y", "NUM"}, {"Z", "NUM"}}},
      {"ORIENT", {{"Q1", "NUM"}, {"Q2", "NUM"}, {"Q3", "NUM"}, {"Q4", "NUM"}}},
      {"CONFDATA", {{"CF1", "NUM"}, {"CF4", "NUM"}, {"CF6", "NUM"}, {"CFX", "NUM"}}},
      {"ROBJOINT", {{"RAX_1", "NUM"}, {"RAX_2", "NUM"}, {"RAX_3", "NUM"}, {"RAX_4", "NUM"}, {"RAX_5", "NUM"}, {"RAX_6", "NUM"}}},
      {"EXTJOINT", {{"EAX_A", "NUM"}, {"EAX_B", "NUM"}, {"EAX_C", "NUM"}, {"EAX_D", "NUM"}, {"EAX_E", "NUM"}, {"EAX_F", "NUM"}}},
      {"TOOLDATA", {{"ROBHOLD", "BOOL"}, {"TFRAME", "POSE"}, {"TLOAD", "LOADDATA"}}},
      {"WOBJDATA", {{"ROBHOLD", "BOOL"}, {"UFPROG", "BOOL"}, {"UFMEC", "STRING"}, {"UFRAME", "POSE"}, {"OFRAME", "POSE"}}},
      {"LOADDATA", {{"MASS", "NUM"}, {"COG", "POS"}, {"AOM", "ORIENT"}, {"IX", "NUM"}, {"IY", "NUM"}, {"IZ", "NUM"}}},
      {"SPEEDDATA", {{"V_TCP", "NUM"}, {"V_ORI", "NUM"}, {"V_LEAX", "NUM"}, {"V_REAX", "NUM"}}},
      {"ZONEDATA", {{"FINEP", "BOOL"}, {"PZONE_TCP", "NUM"}, {"PZONE_ORI", "NUM"}, {"PZONE_EAX", "NUM"},
                    {"ZONE_ORI", "NUM"}, {"ZONE_LEAX", "NUM"}, {"ZONE_REAX", "NUM"}}}};
  return kTable;
}

std::string lower(std::string text) {
  for (char& c : text) c = (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
  return text;
}

std::string shape(const std::string& type, const std::vector<Component>& components) {
  std::string text = "a " + lower(type) + " [";
  for (std::size_t i = 0; i < components.size(); ++i) text += (i ? ", " : "") + lower(components[i].name);
  return text + "]";
}

Value condition(const Value& left, const Value& right) {
  if (left.is_unknown()) return left;
  if (right.is_unknown()) return right;
  return Value::unknown("a condition (conditions are not evaluated)");
}

bool is_current_position_function(const std::string& name) {
  return name == "CROBT" || name == "CJOINTT" || name == "CPOS" || name == "CTOOL" ||
         name == "CWOBJ" || name == "CALCJOINTT" || name == "CALCROBT";
}

/// The robtarget's position (mm) and unit rotation; fails on a non-unit quaternion.
void robtarget_parts(const Value& target, Eigen::Vector3d& trans, Eigen::Quaterniond& rot,
                     const TokenCursor& cursor, int line) {
  const auto& t = target.elements[0].elements;
  const auto& r = target.elements[1].elements;
  trans = Eigen::Vector3d(t[0].number, t[1].number, t[2].number);
  const auto q = rapid_quaternion(r[0].number, r[1].number, r[2].number, r[3].number);
  if (!q) cursor.fail_at(line, "a unit quaternion [q1, q2, q3, q4] in the robtarget", "norm " + number_text(Eigen::Vector4d(r[0].number, r[1].number, r[2].number, r[3].number).norm()));
  rot = *q;
}

Value with_parts(Value target, const Eigen::Vector3d& trans, const Eigen::Quaterniond& rot) {
  auto& t = target.elements[0].elements;
  auto& r = target.elements[1].elements;
  for (int i = 0; i < 3; ++i) t[static_cast<std::size_t>(i)].number = trans[i];
  r[0].number = rot.w();
  r[1].number = rot.x();
  r[2].number = rot.y();
  r[3].number = rot.z();
  return target;
}

}  // namespace

Value Value::of_number(double number) {
  Value value;
  value.kind = Kind::kNumber;
  value.number = number;
  return value;
}

Value Value::of_boolean(bool boolean) {
  Value value;
  value.kind = Kind::kBoolean;
  value.boolean = boolean;
  return value;
}

Value Value::unknown(std::string reason) {
  Value value;
  value.text = std::move(reason);
  return value;
}

Value Value::aggregate(std::vector<Value> elements, std::string type) {
  Value value;
  value.kind = Kind::kAggregate;
  value.elements = std::move(elements);
  value.type = std::move(type);
  return value;
}

std::string describe(const Value& value) {
  switch (value.kind) {
    case Value::Kind::kNumber: return "a num";
    case Value::Kind::kBoolean: return "a bool";
    case Value::Kind::kString: return "a string";
    case Value::Kind::kAggregate:
      return "an aggregate of " + std::to_string(value.elements.size()) + " item" +
             (value.elements.size() == 1 ? "" : "s");
    case Value::Kind::kUnknown: return value.text;
  }
  return "a value";
}

const Value* first_unknown_part(const Value& value) {
  if (value.is_unknown()) return &value;
  for (const Value& element : value.elements) {
    if (const Value* unknown = first_unknown_part(element)) return unknown;
  }
  return nullptr;
}

const std::vector<Component>* record_components(const std::string& type) {
  const auto found = record_table().find(type);
  return found == record_table().end() ? nullptr : &found->second;
}

std::string conform(Value& value, const std::string& type) {
  if (value.is_unknown()) return {};
  if (type == "NUM" || type == "DNUM") return value.kind == Value::Kind::kNumber ? "" : "a num";
  if (type == "BOOL") return value.kind == Value::Kind::kBoolean ? "" : "a bool (TRUE or FALSE)";
  if (type == "STRING") return value.kind == Value::Kind::kString ? "" : "a string";
  const std::vector<Component>* components = record_components(type);
  if (!components) return {};  // a type the reader does not know: taken as written
  if (value.kind != Value::Kind::kAggregate || value.elements.size() != components->size()) {
    return shape(type, *components);
  }
  for (std::size_t i = 0; i < components->size(); ++i) {
    const std::string inner = conform(value.elements[i], (*components)[i].type);
    if (!inner.empty()) return inner + " (" + lower((*components)[i].name) + " of a " + lower(type) + ")";
  }
  value.type = type;
  return {};
}

Value Evaluator::expression() { return disjunction(); }

Value Evaluator::disjunction() {
  Value left = conjunction();
  while (cursor_.accept_name("OR") || cursor_.accept_name("XOR")) left = condition(left, conjunction());
  return left;
}

Value Evaluator::conjunction() {
  Value left = negation();
  while (cursor_.accept_name("AND")) left = condition(left, negation());
  return left;
}

Value Evaluator::negation() {
  if (!cursor_.accept_name("NOT")) return comparison();
  TokenCursor::NestingGuard guard(cursor_);
  const Value operand = negation();
  return condition(operand, operand);
}

Value Evaluator::comparison() {
  Value left = sum();
  static constexpr std::string_view kComparisons[] = {"=", "<>", "<", ">", "<=", ">="};
  while (true) {
    bool matched = false;
    for (const std::string_view op : kComparisons) matched = matched || cursor_.accept_symbol(op);
    if (!matched) return left;
    left = condition(left, sum());
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
  while (cursor_.peek_symbol("*") || cursor_.peek_symbol("/") || cursor_.peek_name("DIV") ||
         cursor_.peek_name("MOD")) {
    const ProgramToken& op = cursor_.next("an operator");
    left = arithmetic(upper_name(op.text), left, unary(), op.line);
  }
  return left;
}

Value Evaluator::unary() {
  if (!cursor_.peek_symbol("-") && !cursor_.peek_symbol("+")) return postfix();
  const ProgramToken& op = cursor_.next("an operator");
  TokenCursor::NestingGuard guard(cursor_);
  Value operand = unary();
  if (op.text == "+" || operand.is_unknown()) return operand;
  if (operand.kind != Value::Kind::kNumber) {
    return Value::unknown("'-' before " + describe(operand) + " (not evaluated)");
  }
  operand.number = -operand.number;
  return operand;
}

Value Evaluator::postfix() {
  Value value = primary();
  while (cursor_.peek_symbol(".") || cursor_.peek_symbol("{")) {
    const int line = cursor_.line();
    if (cursor_.accept_symbol(".")) {
      value = component(value, upper_name(cursor_.expect_name("a component name after '.'").text), line);
      continue;
    }
    cursor_.expect_symbol("{", "'{'");
    TokenCursor::NestingGuard guard(cursor_);
    const Value index = expression();
    cursor_.expect_symbol("}", "'}' after the index");
    value = element(value, index, line);
  }
  return value;
}

Value Evaluator::component(const Value& value, const std::string& name, int line) {
  if (value.is_unknown()) return value;
  const std::vector<Component>* components = record_components(value.type);
  const bool record = components && !value.array && value.kind == Value::Kind::kAggregate &&
                      value.elements.size() == components->size();
  if (!record) {
    return Value::unknown("a component ." + lower(name) + " of " + describe(value) + " of unknown type");
  }
  for (std::size_t i = 0; i < components->size(); ++i) {
    if ((*components)[i].name != name) continue;
    Value result = value.elements[i];
    result.type = (*components)[i].type;
    return result;
  }
  cursor_.fail_at(line, "a component of " + shape(value.type, *components), quote_source(lower(name)));
}

Value Evaluator::element(const Value& value, const Value& index, int line) {
  if (value.is_unknown()) return value;
  if (index.is_unknown()) return index;
  if (value.kind != Value::Kind::kAggregate) cursor_.fail_at(line, "an array before '{'", describe(value));
  const double i = index.kind == Value::Kind::kNumber ? index.number : 0.0;
  if (i < 1 || i > static_cast<double>(value.elements.size()) || i != std::floor(i)) {
    cursor_.fail_at(line, "an index from 1 to " + std::to_string(value.elements.size()),
                    index.kind == Value::Kind::kNumber ? number_text(index.number) : describe(index));
  }
  Value result = value.elements[static_cast<std::size_t>(i) - 1];
  if (value.array) result.type = value.type;
  return result;
}

Value Evaluator::primary() {
  TokenCursor::NestingGuard guard(cursor_);
  const ProgramToken& token = cursor_.peek();
  if (token.kind == TokenKind::kNumber) return Value::of_number(cursor_.next("a number").number);
  if (token.kind == TokenKind::kString) {
    Value value;
    value.kind = Value::Kind::kString;
    value.text = std::string(cursor_.next("a string").text);
    return value;
  }
  if (cursor_.peek_symbol("[")) return aggregate();
  if (cursor_.accept_symbol("(")) {
    Value value = expression();
    cursor_.expect_symbol(")", "')'");
    return value;
  }
  if (token.kind != TokenKind::kName) cursor_.fail("an expression");
  const ProgramToken& name = cursor_.next("a name");
  if (same_name(name.text, "TRUE") || same_name(name.text, "FALSE")) {
    return Value::of_boolean(same_name(name.text, "TRUE"));
  }
  if (cursor_.peek_symbol("(")) return function_call(name);
  return lookup_(upper_name(name.text), std::string(name.text));
}

Value Evaluator::aggregate() {
  cursor_.expect_symbol("[", "'['");
  std::vector<Value> elements;
  if (!cursor_.accept_symbol("]")) {
    do {
      elements.push_back(expression());
    } while (cursor_.accept_symbol(","));
    cursor_.expect_symbol("]", "',' or ']' in the aggregate");
  }
  return Value::aggregate(std::move(elements));
}

std::vector<Argument> Evaluator::arguments(std::string_view closing) {
  std::vector<Argument> result;
  const auto at_stop = [&] {
    return cursor_.at_end() || (!closing.empty() && cursor_.peek_symbol(closing)) || cursor_.peek_symbol(",");
  };
  const auto optional = [&] {
    while (cursor_.accept_symbol("\\")) {
      const ProgramToken& name = cursor_.expect_name("an optional argument name after '\\'");
      Argument argument{upper_name(name.text), std::string(name.text), 0, 0};
      if (cursor_.accept_symbol(":=")) {
        argument.begin = cursor_.position();
        skip_expression(closing);
        argument.end = cursor_.position();
        if (argument.end == argument.begin) cursor_.fail("a value after ':='");
      }
      result.push_back(argument);
    }
  };
  if (!closing.empty() && cursor_.accept_symbol(closing)) return result;
  if (closing.empty() && cursor_.at_end()) return result;
  do {
    optional();
    if (!at_stop() && !cursor_.peek_symbol("\\")) {
      Argument argument;
      argument.begin = cursor_.position();
      skip_expression(closing);
      argument.end = cursor_.position();
      result.push_back(argument);
    }
    optional();
    if (!at_stop()) cursor_.fail(closing.empty() ? "',' or ';' after an argument" : "',' or ')' after an argument");
  } while (cursor_.accept_symbol(","));
  if (!closing.empty()) cursor_.expect_symbol(closing, "')' closing the arguments");
  return result;
}

/// Moves past one argument's tokens without evaluating them (each argument is evaluated once,
/// by evaluate(): evaluating here too would double the work at every level of nested calls).
void Evaluator::skip_expression(std::string_view closing) {
  int depth = 0;
  while (!cursor_.at_end()) {
    const bool stop = cursor_.peek_symbol(",") || cursor_.peek_symbol("\\") ||
                      (!closing.empty() && cursor_.peek_symbol(closing));
    if (depth == 0 && stop) return;
    const ProgramToken& token = cursor_.next("an argument");
    if (token.kind != TokenKind::kSymbol) continue;
    if (token.text == "(" || token.text == "[" || token.text == "{") ++depth;
    if (token.text == ")" || token.text == "]" || token.text == "}") --depth;
  }
}

Value Evaluator::evaluate(const Argument& argument) {
  if (argument.begin == argument.end) return Value::of_boolean(true);  // a switch
  const std::size_t resume = cursor_.position();
  cursor_.set_position(argument.begin);
  Value value = expression();
  if (cursor_.position() != argument.end) cursor_.fail("',' after the argument");
  cursor_.set_position(resume);
  return value;
}

Value Evaluator::function_call(const ProgramToken& name) {
  const std::string function = upper_name(name.text);
  const int line = name.line;
  cursor_.expect_symbol("(", "'('");
  const std::vector<Argument> arguments = this->arguments(")");
  std::vector<Value> positional;
  std::map<std::string, Value> optional;
  for (const Argument& argument : arguments) {
    (argument.name.empty() ? positional.emplace_back() : optional[argument.name]) = evaluate(argument);
  }
  if (is_current_position_function(function)) {
    return Value::unknown(std::string(name.text) + "(), the current position, which is not known before the run");
  }
  if (function != "OFFS" && function != "RELTOOL") {
    return Value::unknown(std::string(name.text) + "(), which the reader does not evaluate");
  }
  if (positional.size() != 4) {
    cursor_.fail_at(line, "4 arguments (point, x, y, z) for " + std::string(name.text), std::to_string(positional.size()));
  }
  for (const Value& argument : positional) {
    if (argument.is_unknown()) return argument;
  }
  Value target = positional[0];
  if (const std::string problem = conform(target, "ROBTARGET"); !problem.empty()) {
    cursor_.fail_at(line, problem + " as the point of " + std::string(name.text), describe(positional[0]));
  }
  if (const Value* unknown = first_unknown_part(target)) return *unknown;
  Eigen::Vector3d offset;
  for (int i = 0; i < 3; ++i) {
    const Value& number = positional[static_cast<std::size_t>(i) + 1];
    if (number.kind != Value::Kind::kNumber) cursor_.fail_at(line, "a num offset for " + std::string(name.text), describe(number));
    offset[i] = number.number;
  }
  Eigen::Vector3d trans;
  Eigen::Quaterniond rot;
  robtarget_parts(target, trans, rot, cursor_, line);
  if (function == "OFFS") return with_parts(target, trans + offset, rot);
  // RelTool: displacement in the tool frame; rotations about the tool's x, then the new y,
  // then the new z axis.
  Eigen::Quaterniond turned = rot;
  for (const auto& [axis_name, axis] : {std::pair{"RX", Eigen::Vector3d::UnitX()}, std::pair{"RY", Eigen::Vector3d::UnitY()},
                                        std::pair{"RZ", Eigen::Vector3d::UnitZ()}}) {
    const auto found = optional.find(axis_name);
    if (found == optional.end()) continue;
    if (found->second.is_unknown()) return found->second;
    if (found->second.kind != Value::Kind::kNumber) cursor_.fail_at(line, std::string("a num for \\") + axis_name, describe(found->second));
    turned = turned * Eigen::Quaterniond(Eigen::AngleAxisd(degrees_to_radians(found->second.number), axis));
  }
  return with_parts(target, trans + rot * offset, turned.normalized());
}

Value Evaluator::arithmetic(const std::string& op, const Value& left, const Value& right, int) {
  if (left.is_unknown()) return left;
  if (right.is_unknown()) return right;
  if (left.kind != Value::Kind::kNumber || right.kind != Value::Kind::kNumber) {
    return Value::unknown("'" + op + "' of " + describe(left) + " and " + describe(right) + " (not evaluated)");
  }
  const double a = left.number;
  const double b = right.number;
  double result = 0.0;
  if (op == "+") result = a + b;
  if (op == "-") result = a - b;
  if (op == "*") result = a * b;
  if (op == "/" || op == "DIV" || op == "MOD") {
    if (b == 0.0) return Value::unknown("a division by zero");
    result = op == "/" ? a / b : op == "DIV" ? std::trunc(a / b) : std::fmod(a, b);
  }
  if (!std::isfinite(result)) return Value::unknown("a result that is not a finite number");
  return Value::of_number(result);
}

}  // namespace grpvss::io::rapid

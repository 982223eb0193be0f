#include "krl_value.hpp"

#include <cmath>

#include "grpvss/io/program_orientation.hpp"
#include "grpvss/io/units.hpp"

namespace grpvss::io::krl {
namespace {

Value unknown_operand(const Value& left, const Value& right) {
  return left.is_unknown() ? left : right;
}

Value condition(const Value& left, const Value& right) {
  if (left.is_unknown() || right.is_unknown()) return unknown_operand(left, right);
  return Value::unknown("a condition (conditions are not evaluated)");
}

}  // namespace

Value Value::of_number(double number) {
  Value value;
  value.kind = Kind::kNumber;
  value.number = number;
  return value;
}

Value Value::unknown(std::string reason) {
  Value value;
  value.text = std::move(reason);
  return value;
}

Value Value::structure(std::string type) {
  Value value;
  value.kind = Kind::kStructure;
  value.text = std::move(type);
  return value;
}

const Value* Value::component(std::string_view name) const {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (same_name(names[i], name)) return &values[i];
  }
  return nullptr;
}

void Value::set_component(const std::string& name, Value value) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) {
      values[i] = std::move(value);
      return;
    }
  }
  names.push_back(name);
  values.push_back(std::move(value));
}

std::string describe(const Value& value) {
  switch (value.kind) {
    case Value::Kind::kNumber: return "a number";
    case Value::Kind::kBoolean: return "a boolean";
    case Value::Kind::kString: return "a string";
    case Value::Kind::kEnum: return "#" + value.text;
    case Value::Kind::kStructure:
      return value.text.empty() ? "a structure" : "a structure " + value.text;
    case Value::Kind::kUnknown: return value.text;
  }
  return "a value";
}

std::string element_key(const std::string& name, const std::vector<Index>& indices) {
  std::string key = name + "[";
  for (std::size_t i = 0; i < indices.size(); ++i) {
    key += (i ? "," : "") + (indices[i] ? std::to_string(*indices[i]) : std::string());
  }
  return key + "]";
}

FrameComponents frame_components(const Value& structure) {
  FrameComponents frame;
  const auto get = [&](const char* name, double& out) {
    const Value* component = structure.component(name);
    if (component && component->kind == Value::Kind::kNumber) out = component->number;
  };
  get("X", frame.x);
  get("Y", frame.y);
  get("Z", frame.z);
  get("A", frame.a);
  get("B", frame.b);
  get("C", frame.c);
  return frame;
}

Value frame_value(const FrameComponents& frame) {
  Value value = Value::structure("FRAME");
  value.set_component("X", Value::of_number(frame.x));
  value.set_component("Y", Value::of_number(frame.y));
  value.set_component("Z", Value::of_number(frame.z));
  value.set_component("A", Value::of_number(frame.a));
  value.set_component("B", Value::of_number(frame.b));
  value.set_component("C", Value::of_number(frame.c));
  return value;
}

Value Evaluator::expression() { return logical(); }

Value Evaluator::logical() {
  Value left = conjunction();
  while (cursor_.accept_name("OR") || cursor_.accept_name("EXOR") || cursor_.accept_name("B_OR") ||
         cursor_.accept_name("B_EXOR")) {
    left = condition(left, conjunction());
  }
  return left;
}

Value Evaluator::conjunction() {
  Value left = negation();
  while (cursor_.accept_name("AND") || cursor_.accept_name("B_AND")) {
    left = condition(left, negation());
  }
  return left;
}

Value Evaluator::negation() {
  if (!cursor_.accept_name("NOT") && !cursor_.accept_name("B_NOT")) return comparison();
  TokenCursor::NestingGuard guard(cursor_);
  const Value operand = negation();
  return condition(operand, operand);
}

Value Evaluator::comparison() {
  Value left = sum();
  static constexpr std::string_view kComparisons[] = {"==", "<>", "<", ">", "<=", ">="};
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
  Value left = geometric();
  while (cursor_.peek_symbol("*") || cursor_.peek_symbol("/")) {
    const ProgramToken& op = cursor_.next("an operator");
    left = arithmetic(std::string(op.text), left, geometric(), op.line);
  }
  return left;
}

Value Evaluator::geometric() {
  Value left = unary();
  while (cursor_.peek_symbol(":")) {
    const int line = cursor_.next("':'").line;
    left = compose(left, unary(), line);
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
    cursor_.fail_at(op.line, "a number after unary '-'", describe(operand));
  }
  operand.number = -operand.number;
  return operand;
}

Value Evaluator::postfix() {
  Value value = primary();
  while (cursor_.peek_symbol(".")) {
    const int line = cursor_.next("'.'").line;
    const ProgramToken& name = cursor_.expect_name("a component name after '.'");
    if (value.is_unknown()) continue;
    const Value* component = value.component(name.text);
    if (value.kind != Value::Kind::kStructure || !component) {
      cursor_.fail_at(line, "a structure with a component " + upper_name(name.text),
                      describe(value));
    }
    value = Value(*component);
  }
  return value;
}

std::vector<Index> Evaluator::indices(std::string& unknown) {
  cursor_.expect_symbol("[", "'['");
  std::vector<Index> result;
  if (cursor_.accept_symbol("]")) return result;
  do {
    if (cursor_.peek_symbol(",") || cursor_.peek_symbol("]")) {
      result.emplace_back();  // an empty index: a whole CHAR row
      continue;
    }
    const int line = cursor_.line();
    const Value index = expression();
    if (index.is_unknown()) {
      if (unknown.empty()) unknown = index.text;
      result.emplace_back();
      continue;
    }
    if (index.kind != Value::Kind::kNumber || index.number != std::floor(index.number) ||
        std::fabs(index.number) > 1e6) {
      cursor_.fail_at(line, "an integer index", describe(index));
    }
    result.push_back(static_cast<long long>(index.number));
  } while (cursor_.accept_symbol(","));
  cursor_.expect_symbol("]", "',' or ']' after the index");
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
  if (cursor_.peek_symbol("{")) return aggregate();
  if (cursor_.accept_symbol("(")) {
    Value value = expression();
    cursor_.expect_symbol(")", "')'");
    return value;
  }
  if (token.kind != TokenKind::kName) cursor_.fail("an expression");
  const ProgramToken& name = cursor_.next("a name");
  if (name.text[0] == '#') {
    Value value;
    value.kind = Value::Kind::kEnum;
    value.text = upper_name(name.text.substr(1));
    return value;
  }
  if (same_name(name.text, "TRUE") || same_name(name.text, "FALSE")) {
    Value value;
    value.kind = Value::Kind::kBoolean;
    value.boolean = same_name(name.text, "TRUE");
    return value;
  }
  if (cursor_.peek_symbol("(")) return function_call(name);
  return name_value(name);
}

Value Evaluator::name_value(const ProgramToken& name) {
  std::string key = upper_name(name.text);
  std::string spelling(name.text);
  if (cursor_.peek_symbol("[")) {
    std::string unknown;
    const std::vector<Index> index = indices(unknown);
    if (!unknown.empty()) return Value::unknown("an index that is not computed (" + unknown + ")");
    key = element_key(key, index);
    spelling = element_key(spelling, index);
  }
  return lookup_(key, spelling, name.line);
}

Value Evaluator::function_call(const ProgramToken& name) {
  cursor_.expect_symbol("(", "'('");
  if (!cursor_.accept_symbol(")")) {
    do {
      expression();  // evaluated for its syntax; KRL functions are not evaluated
    } while (cursor_.accept_symbol(","));
    cursor_.expect_symbol(")", "',' or ')' after an argument");
  }
  return Value::unknown(upper_name(name.text) + "(), which the reader does not evaluate");
}

Value Evaluator::aggregate() {
  cursor_.expect_symbol("{", "'{'");
  Value value = Value::structure("");
  if (cursor_.peek().kind == TokenKind::kName && cursor_.peek_symbol(":", 1)) {
    value.text = upper_name(cursor_.next("a type").text);
    cursor_.next("':'");
  }
  if (cursor_.accept_symbol("}")) return value;
  do {
    const ProgramToken& name = cursor_.expect_name("a component name");
    if (cursor_.accept_symbol("[")) cursor_.expect_symbol("]", "']' (a CHAR array component)");
    const std::string key = upper_name(name.text);
    if (value.component(key)) cursor_.fail_at(name.line, "each component once", quote_source(name.text));
    value.set_component(key, expression());
  } while (cursor_.accept_symbol(","));
  cursor_.expect_symbol("}", "',' or '}' in the aggregate");
  return value;
}

Value Evaluator::arithmetic(const std::string& op, const Value& left, const Value& right,
                            int line) {
  if (left.is_unknown() || right.is_unknown()) return unknown_operand(left, right);
  if (left.kind != Value::Kind::kNumber || right.kind != Value::Kind::kNumber) {
    cursor_.fail_at(line, "numbers for '" + op + "'",
                    describe(left.kind != Value::Kind::kNumber ? left : right));
  }
  double result = 0.0;
  if (op == "+") result = left.number + right.number;
  if (op == "-") result = left.number - right.number;
  if (op == "*") result = left.number * right.number;
  if (op == "/") {
    if (right.number == 0.0) return Value::unknown("a division by zero");
    result = left.number / right.number;
  }
  if (!std::isfinite(result)) return Value::unknown("a result that is not a finite number");
  return Value::of_number(result);
}

/// KRL's geometric operator: `A : B` is the frame B expressed through A (X_0B = X_0A X_AB);
/// the result keeps B's other components (S, T, E1..).
Value Evaluator::compose(const Value& left, const Value& right, int line) {
  if (left.is_unknown() || right.is_unknown()) return unknown_operand(left, right);
  for (const Value* operand : {&left, &right}) {
    if (operand->kind != Value::Kind::kStructure) {
      cursor_.fail_at(line, "FRAME or POS operands for ':'", describe(*operand));
    }
  }
  const FrameComponents a = frame_components(left);
  const FrameComponents b = frame_components(right);
  const Eigen::Isometry3d pose =
      krl_frame_pose(a.x, a.y, a.z, a.a, a.b, a.c) * krl_frame_pose(b.x, b.y, b.z, b.a, b.b, b.c);
  const Eigen::Matrix3d R = pose.linear();
  FrameComponents result;
  result.x = pose.translation().x() * 1000.0;
  result.y = pose.translation().y() * 1000.0;
  result.z = pose.translation().z() * 1000.0;
  result.a = std::atan2(R(1, 0), R(0, 0)) / kRadiansPerDegree;
  result.b = std::atan2(-R(2, 0), std::hypot(R(0, 0), R(1, 0))) / kRadiansPerDegree;
  result.c = std::atan2(R(2, 1), R(2, 2)) / kRadiansPerDegree;
  Value composed = right;
  const Value frame = frame_value(result);
  for (std::size_t i = 0; i < frame.names.size(); ++i) {
    composed.set_component(frame.names[i], frame.values[i]);
  }
  if (composed.text.empty()) composed.text = "FRAME";
  return composed;
}

}  // namespace grpvss::io::krl

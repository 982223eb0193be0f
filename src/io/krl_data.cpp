#include "krl_data.hpp"

#include <algorithm>

namespace grpvss::io::krl {
namespace {

bool is_builtin_type(std::string_view name) {
  static constexpr std::string_view kTypes[] = {"INT",    "REAL",   "BOOL", "CHAR", "FRAME",
                                                "POS",    "E6POS",  "AXIS", "E6AXIS",
                                                "FDAT",   "PDAT",   "LDAT", "LOAD"};
  return std::any_of(std::begin(kTypes), std::end(kTypes),
                     [&](std::string_view type) { return same_name(type, name); });
}

/// Skips array dimensions `[16]` or `[4,24]` of a declaration.
void skip_dimensions(TokenCursor& cursor) {
  if (!cursor.accept_symbol("[")) return;
  while (!cursor.accept_symbol("]")) cursor.next("']' closing the dimensions");
}

Value with_type(Value value, const std::string& type) {
  if (value.kind == Value::Kind::kStructure && value.text.empty()) value.text = type;
  return value;
}

/// Merges `value` into `old` when both are structures (components not given stay).
Value merged(const Value& old, Value value) {
  if (old.kind != Value::Kind::kStructure || value.kind != Value::Kind::kStructure) return value;
  Value result = old;
  for (std::size_t i = 0; i < value.names.size(); ++i) {
    result.set_component(value.names[i], std::move(value.values[i]));
  }
  if (!value.text.empty()) result.text = value.text;
  return result;
}

/// Sets the component path of `holder` to `value`.
void set_path(Value& holder, const std::vector<std::string>& path, std::size_t at, Value value) {
  if (holder.is_unknown()) return;  // a component of an unknown value stays unknown
  if (holder.kind != Value::Kind::kStructure) holder = Value::structure("");
  if (at + 1 == path.size()) {
    const Value* old = holder.component(path[at]);
    holder.set_component(path[at], old ? merged(*old, std::move(value)) : std::move(value));
    return;
  }
  Value inner = holder.component(path[at]) ? *holder.component(path[at]) : Value::structure("");
  set_path(inner, path, at + 1, std::move(value));
  holder.set_component(path[at], std::move(inner));
}

}  // namespace

bool is_declaration(const TokenCursor& cursor) {
  std::size_t at = 0;
  if (cursor.peek_name("GLOBAL")) ++at;
  if (cursor.peek_name("DECL", at)) return true;
  const ProgramToken& type = cursor.peek(at);
  return type.kind == TokenKind::kName && is_builtin_type(type.text) &&
         cursor.peek(at + 1).kind == TokenKind::kName;
}

void read_declaration(TokenCursor& cursor, Scope& scope, const Lookup& lookup) {
  cursor.accept_name("GLOBAL");
  cursor.accept_name("DECL");
  cursor.accept_name("GLOBAL");
  cursor.accept_name("CONST");
  const std::string type = upper_name(cursor.expect_name("a data type after DECL").text);
  Evaluator evaluator(cursor, lookup);
  do {
    const ProgramToken& name = cursor.expect_name("a variable name in the declaration");
    skip_dimensions(cursor);
    Variable variable;
    variable.spelling = std::string(name.text);
    variable.type = type;
    variable.file = cursor.file_name();
    variable.line = name.line;
    const std::string key = upper_name(name.text);
    if (cursor.accept_symbol("=")) {
      variable.value = with_type(evaluator.expression(), type);
    } else if (const auto existing = scope.find(key); existing != scope.end()) {
      variable.value = with_type(existing->second.value, type);  // DECL typing a parameter
    } else {
      variable.value = Value::unknown(variable.spelling + ", declared without a value at " +
                                      cursor.file_name() + ":" + std::to_string(name.line));
    }
    scope[key] = std::move(variable);
  } while (cursor.accept_symbol(","));
  cursor.expect_end("the declaration");
}

Designator read_designator(TokenCursor& cursor, Evaluator& evaluator) {
  Designator target;
  const ProgramToken& name = cursor.expect_name("a variable name");
  target.line = name.line;
  target.key = upper_name(name.text);
  target.spelling = std::string(name.text);
  if (cursor.peek_symbol("[")) {
    const std::vector<Index> indices = evaluator.indices(target.unknown_index);
    target.key = element_key(target.key, indices);
    target.spelling = element_key(target.spelling, indices);
  }
  while (cursor.accept_symbol(".")) {
    target.components.push_back(upper_name(cursor.expect_name("a component name after '.'").text));
  }
  return target;
}

void assign(Scope& scope, const Designator& target, Value value, const std::string& file) {
  auto found = scope.find(target.key);
  if (found == scope.end()) {
    Variable variable;
    variable.spelling = target.spelling;
    variable.value = Value::unknown(target.spelling + ", which has no value before line " +
                                    std::to_string(target.line));
    variable.file = file;
    variable.line = target.line;
    found = scope.emplace(target.key, std::move(variable)).first;
    if (!target.components.empty()) found->second.value = Value::structure("");
  }
  Variable& variable = found->second;
  if (target.components.empty()) {
    variable.value = with_type(merged(variable.value, std::move(value)), variable.type);
    return;
  }
  set_path(variable.value, target.components, 0, std::move(value));
}

void read_data_file(std::string_view text, const std::string& file_name, Scope& scope,
                    ProgramRecorder& recorder) {
  const std::vector<ProgramToken> tokens = tokenize_program(text, file_name, ProgramDialect::kKrl);
  const Lookup lookup = [&scope](const std::string& key, const std::string& spelling, int) {
    return lookup_variable({&scope}, key, spelling);
  };
  for (const TokenRange& range : split_line_statements(tokens, file_name)) {
    TokenCursor cursor(tokens, range, file_name);
    if (cursor.peek_name("DEFDAT") || cursor.peek_name("ENDDAT")) continue;
    if (is_declaration(cursor)) {
      read_declaration(cursor, scope, lookup);
      continue;
    }
    const bool assignment = cursor.peek().kind == TokenKind::kName &&
                            (cursor.peek_symbol("=", 1) || cursor.peek_symbol("[", 1) ||
                             cursor.peek_symbol(".", 1));
    if (!assignment) {
      recorder.warn(file_name, range.line, "not read: " + cursor.statement_text());
      continue;
    }
    Evaluator evaluator(cursor, lookup);
    const Designator target = read_designator(cursor, evaluator);
    cursor.expect_symbol("=", "'=' after " + target.spelling);
    Value value = evaluator.expression();
    cursor.expect_end("the assigned value");
    if (!target.unknown_index.empty()) {
      recorder.warn(file_name, range.line, "not read: " + cursor.statement_text() + " (the index is not computed)");
      continue;
    }
    assign(scope, target, std::move(value), file_name);
  }
}

Value lookup_variable(const std::vector<const Scope*>& scopes, const std::string& key,
                      const std::string& spelling) {
  for (const Scope* scope : scopes) {
    if (auto found = scope->find(key); found != scope->end()) return found->second.value;
  }
  if (key == "$NULLFRAME") return frame_value({});
  if (!key.empty() && key[0] == '$') {
    return Value::unknown("the system variable " + spelling + ", which the reader does not know");
  }
  return Value::unknown(spelling + ", which is declared nowhere (neither in the program nor in its data files)");
}

}  // namespace grpvss::io::krl

#include "grpvss/io/rapid_file.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/program_lexer.hpp"
#include "grpvss/io/text_file.hpp"
#include "program_recorder.hpp"
#include "rapid_data.hpp"
#include "rapid_structure.hpp"
#include "rapid_value.hpp"

namespace grpvss::io {
namespace {
// Named: the program readers' interpreters share their names, and a unity batch would
// otherwise bring two of them into one anonymous namespace.
namespace rapid_reader {

using rapid::Argument;
using rapid::Evaluator;
using rapid::Value;

struct Variable {
  std::string spelling;
  std::string type;  ///< upper case
  Value value;
};
using Scope = std::map<std::string, Variable>;

bool is_one_of(std::string_view word, std::initializer_list<std::string_view> words) {
  return std::any_of(words.begin(), words.end(), [&](std::string_view w) { return same_name(w, word); });
}

/// Motion instructions the reader does not read: a program with one is rejected.
bool is_unread_motion(std::string_view name) {
  static constexpr std::string_view kPrefixes[] = {"Move", "Search", "Trigg", "Arc", "Spot", "Cap", "Paint", "Disp"};
  return std::any_of(std::begin(kPrefixes), std::end(kPrefixes), [&](std::string_view prefix) {
    return name.size() > prefix.size() && same_name(name.substr(0, prefix.size()), prefix);
  });
}

/// The first ':=' of the statement is an assignment's (not an optional argument's `\V:=`).
bool is_assignment(const std::vector<ProgramToken>& tokens, TokenRange range) {
  for (std::size_t i = range.begin; i < range.end; ++i) {
    if (tokens[i].kind != TokenKind::kSymbol || tokens[i].text != ":=") continue;
    return !(i >= range.begin + 2 && tokens[i - 2].kind == TokenKind::kSymbol && tokens[i - 2].text == "\\");
  }
  return false;
}

/// A path step of an assignment target: a component or a 1-based index.
struct Step {
  std::string component;
  Value index;
};

struct MotionSpec {
  MotionKind kind;
  std::size_t positional;  ///< ToPoint (CirPoint), Speed, Zone, Tool
  bool joint_target;
};

std::optional<MotionSpec> motion_spec(std::string_view name) {
  if (same_name(name, "MoveJ")) return MotionSpec{MotionKind::kJoint, 4, false};
  if (same_name(name, "MoveAbsJ")) return MotionSpec{MotionKind::kJoint, 4, true};
  if (same_name(name, "MoveL")) return MotionSpec{MotionKind::kLinear, 4, false};
  if (same_name(name, "MoveC")) return MotionSpec{MotionKind::kCircular, 5, false};
  return std::nullopt;
}

class MotionArguments;

class Interpreter {
 public:
  Interpreter(std::vector<ProgramToken> tokens, std::string file, int end_line, ProgramRecorder& recorder)
      : tokens_(std::move(tokens)),
        statements_(rapid::split_rapid_statements(tokens_, file, end_line)),
        file_(std::move(file)),
        end_line_(end_line),
        recorder_(recorder),
        structure_(rapid::analyse_structure(tokens_, statements_, file_, end_line, recorder.program().warnings)) {
    recorder_.set_statement_count(statements_.size());
  }

  void run();

 private:
  TokenCursor cursor(std::size_t statement) const { return TokenCursor(tokens_, statements_[statement], file_); }
  rapid::Lookup lookup() {
    return [this](const std::string& key, const std::string& spelling) { return find(key, spelling); };
  }
  Value find(const std::string& key, const std::string& spelling) const;
  void warn(int line, const std::string& text) { recorder_.warn(file_, line, text); }

  void declare(TokenCursor& statement, Scope& scope);
  void run_routine(const rapid::Routine& routine, Scope frame, int line);
  void run_statement(std::size_t index);
  void dispatch(TokenCursor& statement);
  void assignment(TokenCursor& statement);
  void assign_path(Value& holder, const std::vector<Step>& steps, std::size_t at, Value value, const TokenCursor& statement);
  void call(TokenCursor& statement);
  void motion(TokenCursor& statement, const MotionSpec& spec);
  void motion_targets(const MotionArguments& arguments, const MotionSpec& spec, ProgramMotion& motion);

  std::vector<ProgramToken> tokens_;
  std::vector<TokenRange> statements_;
  std::string file_;
  int end_line_;
  ProgramRecorder& recorder_;
  rapid::Structure structure_;
  Scope globals_;
  std::vector<Scope> frames_;
};

Value Interpreter::find(const std::string& key, const std::string& spelling) const {
  if (!frames_.empty()) {
    if (auto found = frames_.back().find(key); found != frames_.back().end()) return found->second.value;
  }
  if (auto found = globals_.find(key); found != globals_.end()) return found->second.value;
  const auto& predefined = rapid::predefined_data();
  if (auto found = predefined.find(key); found != predefined.end()) return found->second;
  return Value::unknown(spelling + ", which is declared nowhere in the program");
}

void Interpreter::run() {
  for (const std::size_t index : structure_.declarations) {
    TokenCursor statement = cursor(index);
    declare(statement, globals_);
  }
  std::optional<std::size_t> main;
  if (auto found = structure_.index.find("MAIN"); found != structure_.index.end() &&
                                                  structure_.routines[found->second].kind == "PROC") {
    main = found->second;
  }
  for (std::size_t i = 0; !main && i < structure_.routines.size(); ++i) {
    if (structure_.routines[i].kind != "PROC") continue;
    main = i;
    warn(statements_[structure_.routines[i].header].line,
         "no PROC main: the first PROC " + structure_.routines[i].name + " is read as the program");
  }
  if (!main) throw InputError(file_, end_line_, "a PROC (the program) in the module", "none");
  const rapid::Routine& routine = structure_.routines[*main];
  recorder_.program().name = routine.name;
  run_routine(routine, {}, statements_[routine.header].line);
}

void Interpreter::declare(TokenCursor& statement, Scope& scope) {
  if (!statement.accept_name("LOCAL")) statement.accept_name("TASK");
  statement.next("VAR, PERS or CONST");
  Variable variable;
  variable.type = upper_name(statement.expect_name("a data type").text);
  const ProgramToken& name = statement.expect_name("a data name");
  variable.spelling = std::string(name.text);
  bool array = false;
  if (statement.accept_symbol("{")) {
    array = true;
    while (!statement.accept_symbol("}")) statement.next("'}' closing the dimensions");
  }
  Evaluator evaluator(statement, lookup());
  const bool initialised = statement.accept_symbol(":=");
  variable.value = initialised ? evaluator.expression()
                               : Value::unknown(variable.spelling + ", declared without a value at line " +
                                                std::to_string(name.line));
  statement.expect_end("the declaration");
  Value& value = variable.value;
  if (array && !value.is_unknown()) {
    if (value.kind != Value::Kind::kAggregate) statement.fail_at(name.line, "an array value [..] for " + variable.spelling, rapid::describe(value));
    for (Value& item : value.elements) {
      if (const std::string problem = rapid::conform(item, variable.type); !problem.empty()) {
        statement.fail_at(name.line, problem + " in " + variable.spelling, rapid::describe(item));
      }
    }
    value.type = variable.type;
    value.array = true;
  } else if (const std::string problem = rapid::conform(value, variable.type); !problem.empty()) {
    statement.fail_at(name.line, problem + " for " + variable.spelling, rapid::describe(value));
  }
  if (initialised && value.is_unknown()) {
    warn(name.line, "'" + variable.spelling + "' is not computed: " + value.text);
  }
  scope[upper_name(name.text)] = std::move(variable);
}

void Interpreter::run_routine(const rapid::Routine& routine, Scope frame, int line) {
  CallScope scope(recorder_, file_, line, routine.name);
  frames_.push_back(std::move(frame));
  for (std::size_t i = routine.header + 1; i < routine.body_end; ++i) run_statement(i);
  if (routine.body_end != routine.end) {
    warn(statements_[routine.body_end].line,
         "not read: the " + upper_name(tokens_[statements_[routine.body_end].begin].text) + " handler of " + routine.name +
             " (lines " + std::to_string(statements_[routine.body_end].line) + " to " +
             std::to_string(statements_[routine.end].line) + ")");
  }
  frames_.pop_back();
}

void Interpreter::run_statement(std::size_t index) {
  recorder_.count_statement(file_, statements_[index].line);
  TokenCursor statement = cursor(index);
  dispatch(statement);
}

void Interpreter::dispatch(TokenCursor& statement) {
  const ProgramToken& first = statement.peek();
  const int line = first.line;
  if (statement.peek_symbol("%")) return warn(line, "not read: " + statement.statement_text() + " (a late-bound call)");
  if (first.kind != TokenKind::kName) statement.fail("a RAPID statement");
  if (rapid::is_rapid_declaration(statement)) return declare(statement, frames_.back());
  if (is_one_of(first.text, {"ENDIF", "ENDWHILE", "ENDFOR", "ENDTEST"})) return;
  const bool compact_if = same_name(first.text, "IF") && !same_name(tokens_[statement.range().end - 1].text, "THEN");
  if (compact_if) {
    statement.next("IF");
    Evaluator evaluator(statement, lookup());
    evaluator.expression();
    warn(line, "control flow not evaluated: " + statement.statement_text() + " (the statement is read as if the condition held)");
    TokenCursor inner(tokens_, {statement.position(), statement.range().end, statement.line()}, file_);
    if (inner.at_end() || inner.peek_name("IF")) {
      statement.fail("a statement after the IF condition (a compact IF holds one simple statement)");
    }
    return dispatch(inner);
  }
  const bool label = statement.peek_symbol(":", 1) && statement.range().end == statement.range().begin + 2;
  if (label || is_one_of(first.text, {"IF", "ELSEIF", "ELSE", "WHILE", "FOR", "TEST", "CASE", "DEFAULT", "GOTO",
                                      "RETURN", "EXIT", "RAISE", "RETRY", "TRYNEXT", "STOP", "BREAK"})) {
    return warn(line, "control flow not evaluated: " + statement.statement_text() + " (the statements inside are read once, in order)");
  }
  if (is_assignment(tokens_, statement.range())) return assignment(statement);
  if (const std::optional<MotionSpec> spec = motion_spec(first.text)) return motion(statement, *spec);
  call(statement);
}

void Interpreter::assignment(TokenCursor& statement) {
  Evaluator evaluator(statement, lookup());
  const ProgramToken& name = statement.expect_name("a data name");
  std::vector<Step> steps;
  while (!statement.peek_symbol(":=")) {
    if (statement.accept_symbol(".")) {
      steps.push_back({upper_name(statement.expect_name("a component name").text), Value()});
      continue;
    }
    statement.expect_symbol("{", "':=', '.' or '{' after the data name");
    steps.push_back({"", evaluator.expression()});
    statement.expect_symbol("}", "'}' after the index");
  }
  statement.next(":=");
  Value value = evaluator.expression();
  statement.expect_end("the assigned value");
  const std::string key = upper_name(name.text);
  Scope& scope = frames_.back().count(key) || !globals_.count(key) ? frames_.back() : globals_;
  Variable& variable = scope[key];
  if (variable.spelling.empty()) {
    variable.spelling = std::string(name.text);
    variable.value = Value::unknown(variable.spelling + ", which is declared nowhere in the program");
  }
  if (value.is_unknown()) warn(name.line, "'" + statement.statement_text() + "' is not computed: " + value.text);
  if (steps.empty()) {
    if (const std::string problem = rapid::conform(value, variable.type); !problem.empty()) {
      statement.fail_at(name.line, problem + " for " + variable.spelling, rapid::describe(value));
    }
    variable.value = std::move(value);
    return;
  }
  assign_path(variable.value, steps, 0, std::move(value), statement);
}

void Interpreter::assign_path(Value& holder, const std::vector<Step>& steps, std::size_t at, Value value,
                              const TokenCursor& statement) {
  const int line = statement.range().line;
  if (holder.is_unknown()) return;  // a part of an unknown value: the whole stays unknown
  if (at == steps.size()) {
    const std::string type = holder.type;
    const bool array = holder.array;
    if (const std::string problem = rapid::conform(value, type); !problem.empty()) {
      statement.fail_at(line, problem, rapid::describe(value));
    }
    holder = std::move(value);
    holder.type = type;
    holder.array = array;
    return;
  }
  std::size_t index = 0;
  std::string child_type;
  if (!steps[at].component.empty()) {
    const std::vector<rapid::Component>* record = rapid::record_components(holder.type);
    const bool conformed = record && holder.kind == Value::Kind::kAggregate && holder.elements.size() == record->size();
    const std::vector<rapid::Component>* components = conformed ? record : nullptr;
    const auto found = components && !holder.array
                           ? std::find_if(components->begin(), components->end(),
                                          [&](const rapid::Component& c) { return c.name == steps[at].component; })
                           : std::vector<rapid::Component>::const_iterator{};
    if (!components || holder.array || found == components->end()) {
      statement.fail_at(line, "a data type with a component " + steps[at].component, rapid::describe(holder));
    }
    index = static_cast<std::size_t>(found - components->begin());
    child_type = found->type;
  } else {
    const Value& i = steps[at].index;
    if (i.is_unknown()) {
      holder = Value::unknown("an element with an index that is not computed (" + i.text + ")");
      return;
    }
    // Range before the cast: converting NaN or a huge double to an integer is undefined.
    if (!holder.array || i.kind != Value::Kind::kNumber ||
        !(i.number >= 1 && i.number <= double(holder.elements.size())) || i.number != std::floor(i.number)) {
      statement.fail_at(line, "an index of an array of " + std::to_string(holder.elements.size()), rapid::describe(i));
    }
    index = static_cast<std::size_t>(i.number) - 1;
    child_type = holder.type;
  }
  Value child = holder.elements[index];
  child.type = child_type;
  child.array = false;
  assign_path(child, steps, at + 1, std::move(value), statement);
  holder.elements[index] = std::move(child);
}

void Interpreter::call(TokenCursor& statement) {
  const ProgramToken& name = statement.next("a procedure name");
  Evaluator evaluator(statement, lookup());
  const std::vector<Argument> arguments = evaluator.arguments("");
  statement.expect_end("the arguments");
  const auto found = structure_.index.find(upper_name(name.text));
  if (found == structure_.index.end() || structure_.routines[found->second].kind != "PROC") {
    if (is_unread_motion(name.text)) {
      statement.fail_at(name.line, "a motion instruction the reader reads (MoveAbsJ, MoveJ, MoveL, MoveC)", quote_source(name.text));
    }
    return warn(name.line, "not read: " + statement.statement_text());
  }
  const rapid::Routine& routine = structure_.routines[found->second];
  Scope frame;
  std::size_t positional = 0;
  for (const Argument& argument : arguments) {
    auto parameter = routine.parameters.end();
    if (argument.name.empty()) {
      parameter = std::find_if(routine.parameters.begin() + std::ptrdiff_t(std::min(positional, routine.parameters.size())),
                               routine.parameters.end(), [](const rapid::Parameter& p) { return !p.optional; });
      positional = static_cast<std::size_t>(parameter - routine.parameters.begin()) + 1;
    } else {
      parameter = std::find_if(routine.parameters.begin(), routine.parameters.end(),
                               [&](const rapid::Parameter& p) { return p.optional && p.name == argument.name; });
    }
    if (parameter == routine.parameters.end()) {
      statement.fail_at(name.line, "arguments matching the parameters of " + routine.name,
                        argument.name.empty() ? "one positional argument too many" : "\\" + argument.spelling);
    }
    Value value = evaluator.evaluate(argument);
    if (const std::string problem = rapid::conform(value, parameter->type); !problem.empty()) {
      statement.fail_at(name.line, problem + " for parameter " + parameter->name + " of " + routine.name, rapid::describe(value));
    }
    frame[parameter->name] = Variable{parameter->name, parameter->type, std::move(value)};
  }
  for (const rapid::Parameter& parameter : routine.parameters) {
    if (!parameter.optional && !frame.count(parameter.name)) {
      statement.fail_at(name.line, "a value for parameter " + parameter.name + " of " + routine.name, "none");
    }
  }
  run_routine(routine, std::move(frame), name.line);
}

/// The arguments of one motion instruction, checked, with their values and texts.
class MotionArguments {
 public:
  MotionArguments(TokenCursor& statement, Evaluator& evaluator, const std::vector<ProgramToken>& tokens,
                  const MotionSpec& spec, std::vector<ProgramWarning>& warnings);

  const std::string& instruction() const { return instruction_; }
  int line() const { return line_; }
  Value value(std::size_t position) const { return evaluator_.evaluate(*positional_[position]); }
  std::string text(std::size_t position) const { return text_of(*positional_[position]); }
  /// The data as written; "" for a literal aggregate.
  std::string name(std::size_t position) const {
    return tokens_[positional_[position]->begin].text == "[" ? std::string() : text(position);
  }
  bool has(const char* option) const { return optional_.count(option) > 0; }
  Value option_value(const char* option) const { return evaluator_.evaluate(*optional_.at(option)); }
  std::string option_text(const char* option) const { return text_of(*optional_.at(option)); }
  /// A non-negative num given as `\option:=`.
  double option_number(const char* option) const;
  rapid::Context context(const std::string& what) const { return {statement_, line_, what + " of " + instruction_}; }

 private:
  std::string text_of(const Argument& argument) const { return join_tokens(tokens_, argument.begin, argument.end); }

  TokenCursor& statement_;
  Evaluator& evaluator_;
  const std::vector<ProgramToken>& tokens_;
  std::string instruction_;
  int line_ = 0;
  std::vector<Argument> arguments_;
  std::vector<const Argument*> positional_;
  std::map<std::string, const Argument*> optional_;
};

MotionArguments::MotionArguments(TokenCursor& statement, Evaluator& evaluator,
                                 const std::vector<ProgramToken>& tokens, const MotionSpec& spec,
                                 std::vector<ProgramWarning>& warnings)
    : statement_(statement), evaluator_(evaluator), tokens_(tokens) {
  const ProgramToken& name = statement.next("a motion instruction");
  instruction_ = std::string(name.text);
  line_ = name.line;
  arguments_ = evaluator.arguments("");
  statement.expect_end("the arguments of " + instruction_);
  static const std::set<std::string> kKnown = {"CONC", "ID", "V", "T", "Z", "INPOS", "WOBJ", "TLOAD", "CORR", "NOEOFFS"};
  for (const Argument& argument : arguments_) {
    if (argument.name.empty()) {
      positional_.push_back(&argument);
      continue;
    }
    if (!kKnown.count(argument.name)) {
      statement.fail_at(line_, "an optional argument of " + instruction_ + " (\\V, \\T, \\Z, \\WObj, \\Conc, \\ID, \\Inpos, \\TLoad, \\Corr, \\NoEOffs)",
                        "\\" + argument.spelling);
    }
    if (!optional_.emplace(argument.name, &argument).second) statement.fail_at(line_, "each optional argument once", "\\" + argument.spelling + " twice");
    if (is_one_of(argument.name, {"CONC", "ID", "INPOS", "TLOAD", "CORR", "NOEOFFS"})) {
      warnings.push_back({statement.file_name(), line_, "the optional argument \\" + argument.spelling + " of " + instruction_ + " is not read"});
    }
  }
  if (positional_.size() != spec.positional) {
    statement.fail_at(line_, std::to_string(spec.positional) + " arguments for " + instruction_ +
                                 (spec.kind == MotionKind::kCircular ? " (CirPoint, ToPoint, Speed, Zone, Tool)" : " (ToPoint, Speed, Zone, Tool)"),
                      std::to_string(positional_.size()));
  }
}

double MotionArguments::option_number(const char* option) const {
  const Value value = option_value(option);
  if (value.kind != Value::Kind::kNumber || value.number < 0) {
    statement_.fail_at(line_, std::string("a non-negative num for \\") + option + " of " + instruction_,
                       value.kind == Value::Kind::kNumber ? number_text(value.number) : rapid::describe(value));
  }
  return value.number;
}

void Interpreter::motion(TokenCursor& statement, const MotionSpec& spec) {
  Evaluator evaluator(statement, lookup());
  std::vector<ProgramWarning> warnings;
  const MotionArguments arguments(statement, evaluator, tokens_, spec, warnings);
  for (ProgramWarning& warning : warnings) recorder_.warn(warning.file, warning.line, std::move(warning.text));
  ProgramMotion motion;
  motion.kind = spec.kind;
  motion_targets(arguments, spec, motion);
  const std::size_t speed = spec.kind == MotionKind::kCircular ? 2 : 1;
  motion.speed = rapid::speed_data(arguments.value(speed), arguments.context("the speed"));
  motion.speed.name = arguments.text(speed);
  if (arguments.has("V")) motion.speed.tcp_speed = arguments.option_number("V") / 1000.0;
  if (arguments.has("T")) motion.speed.duration = arguments.option_number("T");
  motion.blend = rapid::zone_data(arguments.value(speed + 1), arguments.context("the zone"));
  motion.blend.name = arguments.text(speed + 1);
  if (arguments.has("Z")) {
    motion.blend.kind = BlendKind::kDistance;
    motion.blend.radius = arguments.option_number("Z") / 1000.0;
  }
  motion.X_FT = rapid::tool_pose(arguments.value(speed + 2), arguments.context("the tool"));
  motion.tool_name = arguments.text(speed + 2);
  motion.base_name = "wobj0";
  if (arguments.has("WOBJ")) {
    motion.X_RB = rapid::work_object_pose(arguments.option_value("WOBJ"), arguments.context("the work object"));
    motion.base_name = arguments.option_text("WOBJ");
  }
  motion.file = file_;
  motion.line = arguments.line();
  recorder_.add_motion(std::move(motion));
}

void Interpreter::motion_targets(const MotionArguments& arguments, const MotionSpec& spec, ProgramMotion& motion) {
  const std::size_t to = spec.kind == MotionKind::kCircular ? 1 : 0;
  std::vector<std::string> external_axes;
  const rapid::Context context = arguments.context("the target");
  if (spec.joint_target) {
    motion.target = rapid::jointtarget_target(arguments.value(to), context, external_axes);
  } else {
    motion.target = rapid::robtarget_target(arguments.value(to), context, external_axes);
  }
  motion.target_name = arguments.name(to);
  if (spec.kind == MotionKind::kCircular) {
    motion.via = rapid::robtarget_target(arguments.value(0), arguments.context("the circle point"), external_axes);
    motion.via_name = arguments.name(0);
  }
  for (const std::string& axis : external_axes) warn(arguments.line(), "external axis not read: " + axis);
}

}  // namespace rapid_reader
}  // namespace

RobotProgram parse_rapid(std::string_view text, const std::string& file_name) {
  std::vector<ProgramToken> tokens = tokenize_program(text, file_name, ProgramDialect::kRapid);
  tokens.erase(std::remove_if(tokens.begin(), tokens.end(),
                              [](const ProgramToken& token) { return token.kind == TokenKind::kEndOfLine; }),
               tokens.end());
  ProgramRecorder recorder(ProgramLanguage::kRapid, 0);
  recorder.program().files.push_back(file_name);
  rapid_reader::Interpreter interpreter(std::move(tokens), file_name, line_after_text(text), recorder);
  interpreter.run();
  return recorder.take();
}

RobotProgram read_rapid_file(const std::string& path) {
  const std::string text = read_text_file(path);
  return parse_rapid(text, path);
}

}  // namespace grpvss::io

#include "grpvss/io/urscript_file.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/program_lexer.hpp"
#include "grpvss/io/text_file.hpp"
#include "program_recorder.hpp"
#include "urscript_blocks.hpp"
#include "urscript_value.hpp"

namespace grpvss::io {
namespace {
// Named: the program readers' interpreters share their names, and a unity batch would
// otherwise bring two of them into one anonymous namespace.
namespace urscript_reader {

using urscript::CallArgument;
using urscript::Evaluator;
using urscript::LineKind;
using urscript::Value;

/// A motion function's parameters and the defaults URScript gives them.
struct MotionSignature {
  MotionKind kind;
  std::vector<std::string> targets;                     ///< target parameters, in order
  std::vector<std::pair<std::string, double>> numbers;  ///< a, v, t, r, mode with defaults
};

const MotionSignature* motion_signature(std::string_view name) {
  static const std::map<std::string_view, MotionSignature> kMotions = {
      {"movej", {MotionKind::kJoint, {"q"}, {{"a", 1.4}, {"v", 1.05}, {"t", 0.0}, {"r", 0.0}}}},
      {"movel", {MotionKind::kLinear, {"pose"}, {{"a", 1.2}, {"v", 0.25}, {"t", 0.0}, {"r", 0.0}}}},
      {"movec",
       {MotionKind::kCircular,
        {"pose_via", "pose_to"},
        {{"a", 1.2}, {"v", 0.25}, {"r", 0.0}, {"mode", 0.0}}}}};
  const auto found = kMotions.find(name);
  return found == kMotions.end() ? nullptr : &found->second;
}

/// Motions the reader does not read: a program with one is rejected, never shortened.
bool is_unread_motion(std::string_view name) {
  static constexpr std::string_view kUnread[] = {"movep",  "servoj", "servoc",
                                                 "speedj", "speedl", "movejoints"};
  return std::find(std::begin(kUnread), std::end(kUnread), name) != std::end(kUnread);
}

bool is_warned_keyword(std::string_view word) {
  static constexpr std::string_view kWords[] = {
      "return", "break", "continue", "halt",          "pass",
      "run",    "kill",  "join",     "enter_critical", "exit_critical"};
  return std::find(std::begin(kWords), std::end(kWords), word) != std::end(kWords);
}


class Interpreter {
 public:
  Interpreter(std::vector<ProgramToken> tokens, std::vector<TokenRange> statements,
              urscript::Blocks blocks, std::string file)
      : tokens_(std::move(tokens)),
        statements_(std::move(statements)),
        blocks_(std::move(blocks)),
        file_(std::move(file)),
        recorder_(ProgramLanguage::kUrScript, statements_.size()) {}

  RobotProgram run(int end_line);

 private:
  using Frame = std::map<std::string, Value>;

  TokenCursor cursor(std::size_t statement) const {
    return TokenCursor(tokens_, statements_[statement], file_);
  }
  void run_range(std::size_t begin, std::size_t end);
  void run_statement(std::size_t index);
  void run_simple(std::size_t index);
  void assign(TokenCursor& cursor, const std::string& scope);
  void store(const std::string& name, const std::string& scope, Value value);
  void call(TokenCursor& cursor);
  void call_function(TokenCursor& cursor, const urscript::Function& function);
  void set_tcp(TokenCursor& cursor, const std::vector<CallArgument>& arguments);
  void motion(TokenCursor& cursor, const MotionSignature& signature);
  std::map<std::string, double> motion_numbers(TokenCursor& statement, const MotionSignature& signature,
                                               const std::map<std::string, CallArgument>& bound);
  std::map<std::string, CallArgument> bind(TokenCursor& cursor,
                                           const std::vector<std::string>& parameters,
                                           const std::vector<CallArgument>& arguments,
                                           const std::string& routine);
  double motion_number(TokenCursor& cursor, const CallArgument& argument, const std::string& name,
                       const std::string& routine);
  ProgramTarget target(TokenCursor& cursor, const CallArgument& argument,
                       const std::string& routine, const std::string& parameter);
  std::string argument_name(const CallArgument& argument) const;
  const Value* lookup(std::string_view name) const;
  Evaluator evaluator(TokenCursor& cursor) {
    return Evaluator(cursor, [this](std::string_view name) { return lookup(name); });
  }

  std::vector<ProgramToken> tokens_;
  std::vector<TokenRange> statements_;
  urscript::Blocks blocks_;
  std::string file_;
  ProgramRecorder recorder_;
  Frame globals_;
  std::vector<Frame> frames_;
  Eigen::Isometry3d X_FT_ = Eigen::Isometry3d::Identity();
  std::string tool_name_;
  bool tool_warned_ = false;
};

RobotProgram Interpreter::run(int end_line) {
  recorder_.program().files.push_back(file_);
  frames_.emplace_back();
  bool top_level = false;
  for (std::size_t i = 0; i < statements_.size(); ++i) {
    const LineKind kind = blocks_.kinds[i];
    top_level = top_level || (blocks_.depth[i] == 0 && kind != LineKind::kDef &&
                              kind != LineKind::kThread && kind != LineKind::kEnd);
  }
  if (top_level) {
    run_range(0, statements_.size());
    return recorder_.take();
  }
  for (std::size_t i = 0; i < statements_.size(); ++i) {
    if (blocks_.kinds[i] != LineKind::kDef) continue;
    const urscript::Function& main = blocks_.functions.at(std::string(tokens_[statements_[i].begin + 1].text));
    recorder_.program().name = main.name;
    run_range(main.header + 1, main.end);
    return recorder_.take();
  }
  throw InputError(file_, end_line, "a URScript program: statements, or a def ... end",
                   "no statement");
}

void Interpreter::run_range(std::size_t begin, std::size_t end) {
  for (std::size_t i = begin; i < end; ++i) {
    const LineKind kind = blocks_.kinds[i];
    if (kind == LineKind::kDef || kind == LineKind::kThread) {
      if (kind == LineKind::kThread) {
        recorder_.warn(file_, statements_[i].line,
                       "not read: " + cursor(i).statement_text() +
                           " (the body of a thread is not read)");
      }
      i = blocks_.block_end[i];  // a def's body runs where it is called
      continue;
    }
    run_statement(i);
  }
}

void Interpreter::run_statement(std::size_t index) {
  const int line = statements_[index].line;
  recorder_.count_statement(file_, line);
  switch (blocks_.kinds[index]) {
    case LineKind::kEnd: return;
    case LineKind::kOther: return run_simple(index);
    default: {
      TokenCursor statement = cursor(index);
      const ProgramToken& last = tokens_[statements_[index].end - 1];
      if (last.kind != TokenKind::kSymbol || last.text != ":") {
        statement.set_position(statements_[index].end - 1);
        statement.fail("':' at the end of the " + std::string(tokens_[statements_[index].begin].text) + " line");
      }
      recorder_.warn(file_, line,
                     "control flow not evaluated: " + statement.statement_text() +
                         " (the statements inside are read once, in order)");
    }
  }
}

void Interpreter::run_simple(std::size_t index) {
  TokenCursor statement = cursor(index);
  const ProgramToken& first = statement.peek();
  if (first.kind != TokenKind::kName) statement.fail("a statement");
  if (first.text == "global" || first.text == "local") {
    statement.next("a scope");
    return assign(statement, std::string(first.text));
  }
  if (is_warned_keyword(first.text)) {
    recorder_.warn(file_, first.line, "not read: " + statement.statement_text());
    return;
  }
  if (statement.peek_symbol("=", 1)) return assign(statement, "");
  if (statement.peek_symbol("(", 1)) return call(statement);
  if (statement.peek_symbol("[", 1) || statement.peek_symbol(".", 1)) {
    store(std::string(first.text), "",
          urscript::Unknown{"'" + std::string(first.text) + "' after a change of one element (line " +
                            std::to_string(first.line) + ", not read)"});
    recorder_.warn(file_, first.line, "not read: " + statement.statement_text());
    return;
  }
  recorder_.warn(file_, first.line, "not read: " + statement.statement_text());
}

void Interpreter::assign(TokenCursor& statement, const std::string& scope) {
  const ProgramToken& name = statement.expect_name("a variable name");
  statement.expect_symbol("=", "'=' after the variable name");
  Evaluator evaluate = evaluator(statement);
  Value value = evaluate.expression();
  statement.expect_end("the assigned value");
  if (const auto* unknown = std::get_if<urscript::Unknown>(&value)) {
    recorder_.warn(file_, name.line,
                   "'" + std::string(name.text) + "' is not computed: " + unknown->reason);
  }
  store(std::string(name.text), scope, std::move(value));
}

void Interpreter::store(const std::string& name, const std::string& scope, Value value) {
  if (scope == "global") {
    frames_.back().erase(name);
    globals_[name] = std::move(value);
    return;
  }
  if (scope.empty()) {
    for (auto frame = frames_.rbegin(); frame != frames_.rend(); ++frame) {
      if (auto found = frame->find(name); found != frame->end()) {
        found->second = std::move(value);
        return;
      }
    }
    if (auto found = globals_.find(name); found != globals_.end()) {
      found->second = std::move(value);
      return;
    }
  }
  frames_.back()[name] = std::move(value);
}

const Value* Interpreter::lookup(std::string_view name) const {
  const std::string key(name);
  for (auto frame = frames_.rbegin(); frame != frames_.rend(); ++frame) {
    if (auto found = frame->find(key); found != frame->end()) return &found->second;
  }
  if (auto found = globals_.find(key); found != globals_.end()) return &found->second;
  return nullptr;
}

void Interpreter::call(TokenCursor& statement) {
  const ProgramToken& name = statement.next("a function name");
  const std::string function(name.text);
  if (const MotionSignature* signature = motion_signature(function)) {
    return motion(statement, *signature);
  }
  if (is_unread_motion(function)) {
    statement.fail_at(name.line, "a motion the reader reads (movej, movel, movec)",
                      quote_source(function));
  }
  Evaluator evaluate = evaluator(statement);
  const std::vector<CallArgument> arguments = evaluate.call_arguments();
  statement.expect_end("the call of " + function);
  if (function == "set_tcp") return set_tcp(statement, arguments);
  if (auto found = blocks_.functions.find(function); found != blocks_.functions.end()) {
    statement.set_position(statement.range().begin + 1);
    return call_function(statement, found->second);
  }
  for (const CallArgument& argument : arguments) {
    evaluate.evaluate_range(argument.begin, argument.end);  // syntax errors still count
  }
  recorder_.warn(file_, name.line, "not read: " + statement.statement_text());
}

void Interpreter::call_function(TokenCursor& statement, const urscript::Function& function) {
  const int line = statement.line();
  Evaluator evaluate = evaluator(statement);
  const std::vector<CallArgument> arguments = evaluate.call_arguments();
  const auto bound = bind(statement, function.parameters, arguments, function.name);
  Frame frame;
  for (std::size_t i = 0; i < function.parameters.size(); ++i) {
    const std::string& parameter = function.parameters[i];
    const auto given = bound.find(parameter);
    const auto [begin, end] = given != bound.end()
                                  ? std::pair{given->second.begin, given->second.end}
                                  : function.defaults[i];
    if (begin == end) {
      statement.fail_at(line, "a value for parameter " + parameter + " of " + function.name,
                        "none");
    }
    frame[parameter] = evaluate.evaluate_range(begin, end);
  }
  CallScope scope(recorder_, file_, line, function.name);
  frames_.push_back(std::move(frame));
  run_range(function.header + 1, function.end);
  frames_.pop_back();
}

std::map<std::string, CallArgument> Interpreter::bind(TokenCursor& statement,
                                                      const std::vector<std::string>& parameters,
                                                      const std::vector<CallArgument>& arguments,
                                                      const std::string& routine) {
  std::map<std::string, CallArgument> bound;
  std::size_t positional = 0;
  for (const CallArgument& argument : arguments) {
    std::string parameter = argument.name;
    if (parameter.empty()) {
      if (positional >= parameters.size()) {
        statement.fail_at(statement.range().line,
                          "at most " + std::to_string(parameters.size()) + " arguments for " + routine,
                          std::to_string(arguments.size()));
      }
      parameter = parameters[positional++];
    } else if (std::find(parameters.begin(), parameters.end(), parameter) == parameters.end()) {
      statement.fail_at(tokens_[argument.begin].line, "a parameter of " + routine, quote_source(parameter));
    }
    if (!bound.emplace(parameter, argument).second) {
      statement.fail_at(tokens_[argument.begin].line, "one value for parameter " + parameter + " of " + routine,
                        "a second one");
    }
  }
  return bound;
}

void Interpreter::set_tcp(TokenCursor& statement, const std::vector<CallArgument>& arguments) {
  if (arguments.size() != 1) {
    statement.fail_at(statement.range().line, "one pose for set_tcp",
                      std::to_string(arguments.size()) + " arguments");
  }
  Evaluator evaluate = evaluator(statement);
  const Value value = evaluate.evaluate_range(arguments[0].begin, arguments[0].end);
  const auto* pose = std::get_if<Eigen::Isometry3d>(&value);
  if (!pose) {
    statement.fail_at(statement.range().line, "a pose the reader can compute for set_tcp",
                      urscript::describe(value));
  }
  X_FT_ = *pose;
  tool_name_ = statement.statement_text();
}

/// The target as written ("pick", "pose_trans(a, b)"); "" for a literal (p[...] or [...]).
std::string Interpreter::argument_name(const CallArgument& argument) const {
  const ProgramToken& first = tokens_[argument.begin];
  const bool literal = (first.kind == TokenKind::kSymbol && first.text == "[") ||
                       (first.text == "p" && argument.end > argument.begin + 1 && tokens_[argument.begin + 1].text == "[");
  return literal ? std::string() : join_tokens(tokens_, argument.begin, argument.end);
}

double Interpreter::motion_number(TokenCursor& statement, const CallArgument& argument,
                                  const std::string& name, const std::string& routine) {
  Evaluator evaluate = evaluator(statement);
  const Value value = evaluate.evaluate_range(argument.begin, argument.end);
  const double* number = std::get_if<double>(&value);
  if (!number || *number < 0.0) {
    statement.fail_at(tokens_[argument.begin].line,
                      "a non-negative number the reader can compute for " + name + " of " + routine,
                      number ? number_text(*number) : urscript::describe(value));
  }
  return *number;
}

ProgramTarget Interpreter::target(TokenCursor& statement, const CallArgument& argument,
                                  const std::string& routine, const std::string& parameter) {
  Evaluator evaluate = evaluator(statement);
  const Value value = evaluate.evaluate_range(argument.begin, argument.end);
  const int line = tokens_[argument.begin].line;
  if (const auto* joints = std::get_if<urscript::NumberList>(&value)) {
    if (joints->size() != 6) {
      statement.fail_at(line, "6 joint values for " + parameter + " of " + routine,
                        std::to_string(joints->size()));
    }
    return JointTarget{Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(joints->data(), 6))};
  }
  if (const auto* pose = std::get_if<Eigen::Isometry3d>(&value)) {
    CartesianTarget cartesian;
    cartesian.p_BT = pose->translation();
    cartesian.R_BT = Eigen::Quaterniond(pose->linear());
    return cartesian;
  }
  if (const auto* ik = std::get_if<urscript::InverseKinematics>(&value)) {
    CartesianTarget cartesian;
    cartesian.p_BT = ik->pose.translation();
    cartesian.R_BT = Eigen::Quaterniond(ik->pose.linear());
    cartesian.configuration = UrNearestJoints{Eigen::Map<const Eigen::VectorXd>(ik->qnear.data(), Eigen::Index(ik->qnear.size()))};
    return cartesian;
  }
  statement.fail_at(line, "a joint list or pose the reader can compute for " + parameter + " of " + routine,
                    urscript::describe(value));
}

std::map<std::string, double> Interpreter::motion_numbers(TokenCursor& statement, const MotionSignature& signature,
                                                          const std::map<std::string, CallArgument>& bound) {
  const std::string routine(tokens_[statement.range().begin].text);
  std::map<std::string, double> numbers;
  for (const auto& [name, fallback] : signature.numbers) {
    const auto given = bound.find(name);
    numbers[name] = given == bound.end() ? fallback : motion_number(statement, given->second, name, routine);
  }
  if (signature.kind != MotionKind::kCircular) return numbers;
  if (numbers["mode"] != 0.0 && numbers["mode"] != 1.0) {
    statement.fail_at(statement.range().line, "mode 0 or 1 for movec", number_text(numbers["mode"]));
  }
  if (numbers["mode"] == 1.0) {
    recorder_.warn(file_, statement.range().line,
                   "movec mode=1 (orientation fixed to the arc) is not represented: the orientation is read as interpolated");
  }
  return numbers;
}

void Interpreter::motion(TokenCursor& statement, const MotionSignature& signature) {
  const std::string routine(tokens_[statement.range().begin].text);
  const int line = statement.range().line;
  Evaluator evaluate = evaluator(statement);
  const std::vector<CallArgument> arguments = evaluate.call_arguments();
  statement.expect_end("the call of " + routine);
  std::vector<std::string> parameters = signature.targets;
  for (const auto& [name, fallback] : signature.numbers) parameters.push_back(name);
  const auto bound = bind(statement, parameters, arguments, routine);
  for (const std::string& target_parameter : signature.targets) {
    if (!bound.count(target_parameter)) statement.fail_at(line, "a value for " + target_parameter + " of " + routine, "none");
  }
  std::map<std::string, double> numbers = motion_numbers(statement, signature, bound);
  ProgramMotion motion;
  motion.kind = signature.kind;
  const CallArgument& to = bound.at(signature.targets.back());
  motion.target = target(statement, to, routine, signature.targets.back());
  motion.target_name = argument_name(to);
  if (signature.kind == MotionKind::kCircular) {
    const CallArgument& via = bound.at(signature.targets.front());
    motion.via = target(statement, via, routine, signature.targets.front());
    motion.via_name = argument_name(via);
  }
  // movej's a and v are the leading joint's; movel's and movec's the TCP's.
  const bool joint_speeds = signature.kind == MotionKind::kJoint;
  (joint_speeds ? motion.speed.joint_acceleration : motion.speed.tcp_acceleration) = numbers["a"];
  (joint_speeds ? motion.speed.joint_speed : motion.speed.tcp_speed) = numbers["v"];
  if (numbers["t"] > 0.0) motion.speed.duration = numbers["t"];
  if (numbers["r"] > 0.0) {
    motion.blend.kind = BlendKind::kDistance;
    motion.blend.radius = numbers["r"];
  }
  if (tool_name_.empty() && !tool_warned_) {
    tool_warned_ = true;
    recorder_.warn(file_, line, "no set_tcp before the first motion: the tool flange is taken as the TCP (the controller uses the installation's active TCP)");
  }
  motion.X_FT = X_FT_;
  motion.tool_name = tool_name_.empty() ? "flange (no set_tcp)" : tool_name_;
  motion.base_name = "base";
  motion.file = file_;
  motion.line = line;
  recorder_.add_motion(std::move(motion));
}

}  // namespace urscript_reader
}  // namespace

RobotProgram parse_urscript(std::string_view text, const std::string& file_name) {
  std::vector<ProgramToken> tokens = tokenize_program(text, file_name, ProgramDialect::kUrScript);
  std::vector<TokenRange> statements = split_line_statements(tokens, file_name);
  const int end_line = line_after_text(text);
  urscript::Blocks blocks = urscript::analyse_blocks(tokens, statements, file_name, end_line);
  urscript_reader::Interpreter interpreter(std::move(tokens), std::move(statements), std::move(blocks), file_name);
  return interpreter.run(end_line);
}

RobotProgram read_urscript_file(const std::string& path) {
  const std::string text = read_text_file(path);
  return parse_urscript(text, path);
}

}  // namespace grpvss::io

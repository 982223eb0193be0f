#include "grpvss/io/krl_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/program_lexer.hpp"
#include "grpvss/io/program_orientation.hpp"
#include "grpvss/io/text_file.hpp"
#include "grpvss/io/units.hpp"
#include "krl_data.hpp"
#include "krl_motion_state.hpp"
#include "krl_routines.hpp"
#include "krl_target.hpp"
#include "program_recorder.hpp"

namespace grpvss::io {
namespace {
// Named: the program readers' interpreters share their names, and a unity batch would
// otherwise bring two of them into one anonymous namespace.
namespace krl_reader {

using krl::Designator;
using krl::Evaluator;
using krl::Value;

bool is_one_of(std::string_view word, std::initializer_list<std::string_view> words) {
  return std::any_of(words.begin(), words.end(), [&](std::string_view w) { return same_name(w, word); });
}

bool is_unread_motion(std::string_view word) {
  return is_one_of(word, {"PTP_REL", "LIN_REL", "CIRC_REL", "SPTP", "SLIN", "SCIRC", "SPL",
                          "SPLINE", "PTP_SPLINE", "SPTP_REL", "SLIN_REL", "SCIRC_REL", "ASYPTP"});
}

bool is_control(std::string_view word) {
  return is_one_of(word, {"IF", "ELSE", "FOR", "WHILE", "LOOP", "REPEAT", "UNTIL", "SWITCH",
                          "CASE", "DEFAULT"});
}

bool closes_block(std::string_view word) {
  return is_one_of(word, {"ENDIF", "ENDFOR", "ENDWHILE", "ENDLOOP", "ENDSWITCH"});
}

bool is_current_position(std::string_view word) {
  return is_one_of(word, {"$AXIS_ACT", "$POS_ACT", "$AXIS_ACT_MES", "$POS_ACT_MES"});
}

Eigen::Isometry3d frame_pose(const std::optional<Value>& frame) {
  if (!frame) return Eigen::Isometry3d::Identity();
  const krl::FrameComponents f = krl::frame_components(*frame);
  return krl_frame_pose(f.x, f.y, f.z, f.a, f.b, f.c);
}

struct MotionStatement;

class Interpreter {
 public:
  Interpreter(std::string_view text, std::string file, krl::Scope module, ProgramRecorder& recorder)
      : tokens_(tokenize_program(text, file, ProgramDialect::kKrl)),
        statements_(split_line_statements(tokens_, file)),
        file_(std::move(file)),
        recorder_(recorder),
        module_(std::move(module)),
        routines_(krl::find_routines(tokens_, statements_, file_, line_after_text(text))) {}

  std::size_t statement_count() const { return statements_.size(); }

  void run() {
    const krl::Routine& main = routines_.in_order.front();
    recorder_.program().name = main.name;
    if (main.function) {
      throw InputError(file_, statements_[main.header].line, "a DEF as the first routine (the program)",
                       "DEFFCT " + main.name);
    }
    run_routine(main, {}, statements_[main.header].line);
  }

 private:
  TokenCursor cursor(std::size_t statement) const { return TokenCursor(tokens_, statements_[statement], file_); }
  krl::Lookup lookup() {
    return [this](const std::string& key, const std::string& spelling, int) {
      if (std::optional<Value> system = state_.system_value(key)) return *system;
      return krl::lookup_variable({&frames_.back(), &module_}, key, spelling);
    };
  }
  Value lookup_key(const std::string& key) { return lookup()(key, key, 0); }

  void run_routine(const krl::Routine& routine, krl::Scope frame, int line);
  void run_statement(std::size_t index);
  void assignment(TokenCursor& statement);
  void call(TokenCursor& statement);
  void bas(TokenCursor& statement);
  void bas_frame(const std::string& command, const Value& number, const TokenCursor& statement);
  void bas_frames_from_fdat(const std::string& command, const TokenCursor& statement);
  void set_system(const std::string& key, const Value& value, const std::string& text, const TokenCursor& statement);
  MotionStatement read_motion(TokenCursor& statement);
  void warn_unset_frames(int line);
  void motion(TokenCursor& statement);
  MotionBlend blend(const std::vector<std::string>& approximations, MotionKind kind, const TokenCursor& statement);
  void warn(int line, const std::string& text) { recorder_.warn(file_, line, text); }

  std::vector<ProgramToken> tokens_;
  std::vector<TokenRange> statements_;
  std::string file_;
  ProgramRecorder& recorder_;
  krl::Scope module_;
  krl::Routines routines_;
  std::vector<krl::Scope> frames_;
  krl::MotionState state_;
  std::optional<krl::PreviousTarget> previous_;
  bool tool_warned_ = false;
  bool base_warned_ = false;
};

void Interpreter::run_routine(const krl::Routine& routine, krl::Scope frame, int line) {
  CallScope scope(recorder_, file_, line, routine.name);
  frames_.push_back(std::move(frame));
  for (std::size_t i = routine.header + 1; i < routine.end; ++i) run_statement(i);
  frames_.pop_back();
}

void Interpreter::run_statement(std::size_t index) {
  const int line = statements_[index].line;
  recorder_.count_statement(file_, line);
  TokenCursor statement = cursor(index);
  const ProgramToken& first = statement.peek();
  if (first.kind != TokenKind::kName) statement.fail("a KRL statement");
  if (krl::is_declaration(statement)) return krl::read_declaration(statement, frames_.back(), lookup());
  if (is_one_of(first.text, {"PTP", "LIN", "CIRC"})) return motion(statement);
  if (is_unread_motion(first.text)) {
    statement.fail("a motion the reader reads (PTP, LIN, CIRC)");
  }
  if (closes_block(first.text)) return;
  if (is_control(first.text)) {
    return warn(line, "control flow not evaluated: " + statement.statement_text() +
                          " (the statements inside are read once, in order)");
  }
  if (same_name(first.text, "BAS") && statement.peek_symbol("(", 1)) return bas(statement);
  if (first.text[0] != '#' && statement.peek_symbol("(", 1)) return call(statement);
  if (statement.peek_symbol("=", 1) || statement.peek_symbol("[", 1) || statement.peek_symbol(".", 1)) {
    return assignment(statement);
  }
  warn(line, "not read: " + statement.statement_text());
}

void Interpreter::assignment(TokenCursor& statement) {
  Evaluator evaluator(statement, lookup());
  const Designator target = krl::read_designator(statement, evaluator);
  statement.expect_symbol("=", "'=' after " + target.spelling);
  const std::size_t value_begin = statement.position();
  const Value value = evaluator.expression();
  statement.expect_end("the assigned value");
  const std::string value_text = join_tokens(tokens_, value_begin, statement.range().end);
  if (!target.unknown_index.empty()) {
    return warn(target.line, "not read: " + statement.statement_text() + " (the index is not computed: " +
                                 target.unknown_index + ")");
  }
  if (target.key[0] == '$') {
    if (!krl::assign_system_variable(state_, target, value, value_text, statement, recorder_)) {
      warn(target.line, "not read: " + statement.statement_text());
    }
    return;
  }
  krl::Scope& scope = frames_.back().count(target.key) ? frames_.back() : module_;
  krl::assign(scope, target, value, file_);
}

void Interpreter::call(TokenCursor& statement) {
  const ProgramToken& name = statement.next("a routine name");
  Evaluator evaluator(statement, lookup());
  statement.expect_symbol("(", "'('");
  std::vector<Value> arguments;
  if (!statement.accept_symbol(")")) {
    do {
      arguments.push_back(evaluator.expression());
    } while (statement.accept_symbol(","));
    statement.expect_symbol(")", "',' or ')' after an argument");
  }
  statement.expect_end("the call");
  const auto found = routines_.index.find(upper_name(name.text));
  if (found == routines_.index.end() || routines_.in_order[found->second].function) {
    return warn(name.line, "not read: " + statement.statement_text());
  }
  const krl::Routine& routine = routines_.in_order[found->second];
  if (arguments.size() != routine.parameters.size()) {
    statement.fail_at(name.line, std::to_string(routine.parameters.size()) + " arguments for " + routine.name,
                      std::to_string(arguments.size()));
  }
  krl::Scope frame;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    krl::Variable parameter;
    parameter.spelling = routine.parameters[i];
    parameter.value = arguments[i];
    parameter.file = file_;
    parameter.line = name.line;
    frame[routine.parameters[i]] = std::move(parameter);
  }
  run_routine(routine, std::move(frame), name.line);
}

void Interpreter::set_system(const std::string& key, const Value& value, const std::string& text,
                             const TokenCursor& statement) {
  Designator target;
  target.key = key;
  target.spelling = key;
  target.line = statement.range().line;
  krl::assign_system_variable(state_, target, value, text, statement, recorder_);
}

void Interpreter::bas(TokenCursor& statement) {
  statement.next("BAS");
  statement.expect_symbol("(", "'(' after BAS");
  const ProgramToken& command = statement.expect_name("a BAS command (#INITMOV, #TOOL, ...)");
  if (command.text[0] != '#') statement.fail_at(command.line, "a BAS command (#INITMOV, #TOOL, ...)", quote_source(command.text));
  Evaluator evaluator(statement, lookup());
  const Value value = statement.accept_symbol(",") ? evaluator.expression() : Value::unknown("no value");
  statement.expect_symbol(")", "')' closing BAS");
  statement.expect_end("BAS(...)");
  const std::string name = upper_name(command.text.substr(1));
  if (name == "INITMOV") return state_.reset_motion_parameters();
  if (name == "TOOL" || name == "BASE") return bas_frame(name, value, statement);
  if (name == "VEL_PTP" || name == "ACC_PTP" || name == "PTP_PARAMS") {
    const std::string prefix = name == "ACC_PTP" ? "$ACC_AXIS" : "$VEL_AXIS";
    for (long long axis = 1; axis <= 6; ++axis) set_system(krl::element_key(prefix, {axis}), value, "", statement);
  }
  if (name == "VEL_CP" || name == "CP_PARAMS") {
    Designator target;
    target.key = "$VEL";
    target.components = {"CP"};
    krl::assign_system_variable(state_, target, value, "", statement, recorder_);
  }
  if (name == "PTP_PARAMS" || name == "CP_PARAMS" || name == "FRAMES") bas_frames_from_fdat(name, statement);
  if (name == "PTP_PARAMS" || name == "CP_PARAMS") {
    warn(command.line, "partly read: " + statement.statement_text() + " (the velocity and FDAT_ACT's tool and base are read; " +
                           (name == "PTP_PARAMS" ? "PDAT_ACT's" : "LDAT_ACT's") + " acceleration and approximation are not)");
  }
  if (!is_one_of(name, {"VEL_PTP", "ACC_PTP", "VEL_CP", "PTP_PARAMS", "CP_PARAMS", "FRAMES"})) {
    warn(command.line, "not read: " + statement.statement_text());
  }
}

void Interpreter::bas_frame(const std::string& command, const Value& number, const TokenCursor& statement) {
  const int line = statement.range().line;
  // Range before the cast: converting NaN or a huge double to an integer is undefined.
  if (number.kind != Value::Kind::kNumber || !(number.number >= 0 && number.number <= 1e6) ||
      number.number != std::floor(number.number)) {
    statement.fail_at(line, "a tool or base number for BAS(#" + command + ", n)", krl::describe(number));
  }
  const auto index = static_cast<long long>(number.number);
  const std::string data = krl::element_key(command == "TOOL" ? "TOOL_DATA" : "BASE_DATA", {index});
  const Value frame = index == 0 ? krl::frame_value({}) : lookup_key(data);
  set_system(command == "TOOL" ? "$TOOL" : "$BASE", frame, index == 0 ? "$NULLFRAME" : data, statement);
}

void Interpreter::bas_frames_from_fdat(const std::string& command, const TokenCursor& statement) {
  const int line = statement.range().line;
  const Value fdat = lookup_key("FDAT_ACT");
  if (fdat.is_unknown()) {
    statement.fail_at(line, "FDAT_ACT (the tool and base of BAS(#" + command + ")) the reader can compute", fdat.text);
  }
  const Value* ipo = fdat.component("IPO_FRAME");
  if (ipo && !(ipo->kind == Value::Kind::kEnum && ipo->text == "BASE")) {
    statement.fail_at(line, "FDAT_ACT.IPO_FRAME #BASE (a robot-held tool; an external TCP is not read)", krl::describe(*ipo));
  }
  for (const char* component : {"TOOL_NO", "BASE_NO"}) {
    const Value* number = fdat.component(component);
    if (!number) statement.fail_at(line, std::string("FDAT_ACT.") + component, "a FDAT_ACT without it");
    bas_frame(std::string(component) == "TOOL_NO" ? "TOOL" : "BASE", *number, statement);
  }
}

MotionBlend Interpreter::blend(const std::vector<std::string>& approximations, MotionKind kind,
                               const TokenCursor& statement) {
  MotionBlend blend;
  if (approximations.empty()) return blend;
  const std::string& first = approximations.front();
  const bool ptp = kind == MotionKind::kJoint;
  if ((first == "C_PTP" && !ptp) || ((first == "C_ORI" || first == "C_VEL") && ptp)) {
    statement.fail_at(statement.range().line, ptp ? "C_PTP or C_DIS after PTP" : "C_DIS, C_ORI or C_VEL after LIN or CIRC",
                      first);
  }
  for (std::size_t i = 1; i < approximations.size(); ++i) {
    warn(statement.range().line, "a further approximation " + approximations[i] + " is not read");
  }
  blend.name = first;
  if (first == "C_DIS") {
    blend.kind = BlendKind::kDistance;
    if (state_.apo_cdis) blend.radius = millimetres_to_metres(*state_.apo_cdis);
  } else if (first == "C_PTP") {
    blend.kind = BlendKind::kPtpPercent;
    blend.ptp_percent = state_.apo_cptp;
  } else if (first == "C_VEL") {
    blend.kind = BlendKind::kVelocityPercent;
    blend.velocity_percent = state_.apo_cvel;
  } else {
    blend.kind = BlendKind::kOrientationAngle;
    if (state_.apo_cori) blend.orientation_angle = degrees_to_radians(*state_.apo_cori);
  }
  return blend;
}

/// A motion statement as written: `PTP target [C_..]`, `CIRC aux, target [, CA a] [C_..]`.
struct MotionStatement {
  MotionKind kind = MotionKind::kJoint;
  std::string what;  ///< PTP, LIN, CIRC
  int line = 0;
  std::optional<Value> via;
  std::string via_name;
  Value target;
  std::string target_name;
  std::optional<double> circular_angle;  ///< rad
  std::vector<std::string> approximations;
};

MotionStatement Interpreter::read_motion(TokenCursor& statement) {
  MotionStatement motion;
  const ProgramToken& keyword = statement.next("a motion");
  motion.what = upper_name(keyword.text);
  motion.line = keyword.line;
  motion.kind = motion.what == "PTP" ? MotionKind::kJoint : motion.what == "LIN" ? MotionKind::kLinear : MotionKind::kCircular;
  Evaluator evaluator(statement, lookup());
  const auto point = [&](std::string& name) {  // as written; "" for a literal aggregate
    const std::size_t begin = statement.position();
    Value value = evaluator.expression();
    name = tokens_[begin].text == "{" ? std::string() : join_tokens(tokens_, begin, statement.position());
    return value;
  };
  if (motion.kind == MotionKind::kCircular) {
    motion.via = point(motion.via_name);
    statement.expect_symbol(",", "',' between the auxiliary point and the target of CIRC");
  }
  motion.target = point(motion.target_name);
  if (motion.kind == MotionKind::kCircular && statement.accept_symbol(",")) {
    if (!statement.accept_name("CA")) statement.fail("CA (the circular angle) after ','");
    const Value angle = evaluator.expression();
    if (angle.kind != Value::Kind::kNumber) statement.fail_at(motion.line, "a number for CA", krl::describe(angle));
    motion.circular_angle = degrees_to_radians(angle.number);
  }
  while (statement.peek().kind == TokenKind::kName && is_one_of(statement.peek().text, {"C_PTP", "C_DIS", "C_VEL", "C_ORI"})) {
    motion.approximations.push_back(upper_name(statement.next("an approximation").text));
  }
  if (statement.accept_name("WITH")) {
    warn(motion.line, "not read: the WITH clause of " + statement.statement_text());
    statement.set_position(statement.range().end);
  }
  statement.expect_end("the motion");
  return motion;
}

void Interpreter::warn_unset_frames(int line) {
  if (!state_.tool && !tool_warned_) {
    tool_warned_ = true;
    warn(line, "$TOOL is not set before this motion: the flange ($NULLFRAME) is taken (the controller keeps the $TOOL it had)");
  }
  if (!state_.base && !base_warned_) {
    base_warned_ = true;
    warn(line, "$BASE is not set before this motion: the robot base ($NULLFRAME, $WORLD = $ROBROOT) is taken");
  }
}

void Interpreter::motion(TokenCursor& statement) {
  const bool current_position = statement.range().end - statement.range().begin == 2 &&
                                is_current_position(statement.peek(1).text);
  if (current_position) {
    return warn(statement.range().line, "not read: " + statement.statement_text() +
                                            " (a move to the current position, which is not known before the run)");
  }
  const MotionStatement read = read_motion(statement);
  const int line = read.line;
  ProgramMotion motion;
  motion.kind = read.kind;
  motion.tool_name = state_.tool ? state_.tool_name : "$NULLFRAME (not set)";
  motion.base_name = state_.base ? state_.base_name : "$NULLFRAME (not set)";
  const krl::KrlTarget target = krl::krl_target(read.target, read.what, previous_, motion.tool_name, motion.base_name, statement, line);
  if (read.kind != MotionKind::kJoint && target.joint) {
    statement.fail_at(line, "a Cartesian target (POS, E6POS or FRAME) for " + read.what, "an AXIS");
  }
  if (read.via) {
    const krl::KrlTarget via = krl::krl_target(*read.via, "the auxiliary point of CIRC", previous_, motion.tool_name,
                                               motion.base_name, statement, line);
    if (via.joint) statement.fail_at(line, "a Cartesian auxiliary point (POS, E6POS or FRAME) for CIRC", "an AXIS");
    motion.via = via.target;
    motion.via_name = read.via_name;
  }
  for (const std::string& axis : target.external_axes) warn(line, "external axis not read: " + axis);
  if (!target.joint) warn_unset_frames(line);
  motion.target = target.target;
  motion.target_name = read.target_name;
  motion.circular_angle = read.circular_angle;
  motion.X_FT = frame_pose(state_.tool);
  motion.X_RB = frame_pose(state_.base);
  motion.speed = state_.speed();
  motion.blend = blend(read.approximations, read.kind, statement);
  motion.file = file_;
  motion.line = line;
  previous_ = krl::PreviousTarget{target.completed, target.joint, motion.tool_name, motion.base_name};
  recorder_.add_motion(std::move(motion));
}

/// The file in `directory` whose name equals `name` ignoring case, if any.
std::optional<std::string> find_beside(const std::filesystem::path& directory, const std::string& name) {
  std::error_code error;
  for (std::filesystem::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    if (same_name(it->path().filename().string(), name)) return it->path().string();
  }
  return std::nullopt;
}

}  // namespace krl_reader
}  // namespace

RobotProgram parse_krl(std::string_view src_text, const std::string& src_name,
                       const std::vector<KrlDataText>& data_files) {
  ProgramRecorder data_recorder(ProgramLanguage::kKrl, 0);
  krl::Scope module;
  for (const KrlDataText& data : data_files) {
    krl::read_data_file(data.text, data.file_name, module, data_recorder);
  }
  ProgramRecorder recorder(ProgramLanguage::kKrl, 0);
  krl_reader::Interpreter interpreter(src_text, src_name, std::move(module), recorder);
  recorder.set_statement_count(interpreter.statement_count());
  recorder.program().files.push_back(src_name);
  for (const KrlDataText& data : data_files) recorder.program().files.push_back(data.file_name);
  recorder.program().warnings = data_recorder.take().warnings;
  interpreter.run();
  return recorder.take();
}

std::vector<std::string> krl_data_files_beside(const std::string& src_path) {
  const std::filesystem::path path(src_path);
  const std::filesystem::path directory = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::vector<std::string> found_files;
  for (const std::string& name : {std::string("$config.dat"), path.stem().string() + ".dat"}) {
    if (const std::optional<std::string> found = krl_reader::find_beside(directory, name)) {
      found_files.push_back(path.has_parent_path() ? *found : std::filesystem::path(*found).filename().string());
    }
  }
  return found_files;
}

RobotProgram read_krl_file(const std::string& src_path) {
  const std::string text = read_text_file(src_path);
  std::vector<KrlDataText> data_files;
  for (const std::string& file_name : krl_data_files_beside(src_path)) {
    data_files.push_back({file_name, read_text_file(file_name)});
  }
  return parse_krl(text, src_path, data_files);
}

}  // namespace grpvss::io

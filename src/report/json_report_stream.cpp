#include "grpvss/report/json_report_stream.hpp"

#include <optional>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

#include "grpvss/report/atomic_output.hpp"
#include "grpvss/report/file_units.hpp"
#include "grpvss/report/json_report.hpp"
#include "grpvss/report/spill_file.hpp"
#include "grpvss/report/streamed_json.hpp"
#include "grpvss/report/thesis_output.hpp"

namespace grpvss::report {
namespace {

constexpr int kStepsPlaceholder = 0;
constexpr int kSceneStepsPlaceholder = 1;
constexpr int kSegmentsPlaceholder = 2;

/// The run without its steps and segments: what the report holds besides the long arrays.
certify::VerificationResult head_of(const certify::VerificationResult& result) {
  certify::VerificationResult head;
  head.tolerance = result.tolerance;
  head.mode = result.mode;
  head.verdict = result.verdict;
  head.path_file_label = result.path_file_label;
  head.motion_model = result.motion_model;
  head.start = result.start;
  head.errors = result.errors;
  head.link_clearances = result.link_clearances;
  head.interference_episodes = result.interference_episodes;
  head.self_collision_episodes = result.self_collision_episodes;
  head.collision_step = result.collision_step;
  head.total_cycle_time = result.total_cycle_time;
  head.claim = result.claim;
  head.tolerance_shortfall = result.tolerance_shortfall;
  return head;
}

/// The viewer page's escaping: "<" only occurs inside JSON strings, where \u003c means the same.
std::string script_safe(std::string text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '<') {
      out += "\\u003c";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

/// One printed form of the report: its two arrays in scratch files, then its template.
struct JsonReportStream::Form {
  Form(const std::string& scratch_path, int indent_, bool escape_)
      : indent(indent_),
        escape(escape_),
        steps(scratch_path),
        scene_steps(scratch_path),
        // Spaces before each array's key line: "steps" is a member of the report, "scene"'s
        // "steps" one level deeper (compact: none). finish() checks them against the template.
        steps_array(indent_, indent_ < 0 ? 0 : indent_),
        scene_steps_array(indent_, indent_ < 0 ? 0 : 2 * indent_) {}

  void add(const nlohmann::json& step, const nlohmann::json& scene_step) {
    steps.append(steps_array.next_element());
    steps.append(text(steps_array.dump_element(step)));
    scene_steps.append(scene_steps_array.next_element());
    scene_steps.append(text(scene_steps_array.dump_element(scene_step)));
  }

  std::string text(std::string piece) const { return escape ? script_safe(std::move(piece)) : piece; }

  void cut(const std::string& dumped) {
    cut_text = cut_at_placeholders(dumped, 3, indent);
    for (std::size_t i = 0; i < cut_text->placeholders.size(); ++i) {
      const int placeholder = cut_text->placeholders[i];
      if (placeholder == kSegmentsPlaceholder) continue;  // written at the end, any indentation
      const JsonArrayText& array = placeholder == kStepsPlaceholder ? steps_array : scene_steps_array;
      if (indent >= 0 && cut_text->pads[i] + indent != array.element_pad()) {
        throw std::logic_error("json report stream: an array's indentation is not the one streamed");
      }
    }
  }

  /// The report: the template's pieces, the streamed steps, and `segments` (few per step at
  /// most, but a path may have many: dumped one at a time too).
  void write(AtomicOutputFile& output, const std::vector<certify::SegmentRecord>& segments,
             const RobotModel& robot) {
    if (!cut_text) throw std::logic_error("json report stream: written before finish()");
    for (std::size_t i = 0; i < cut_text->placeholders.size(); ++i) {
      output.write(text(cut_text->pieces[i]));
      const int placeholder = cut_text->placeholders[i];
      if (placeholder == kSegmentsPlaceholder) {
        JsonArrayText array(indent, cut_text->pads[i]);
        for (const certify::SegmentRecord& segment : segments) {
          output.write(text(array.next_element()));
          output.write(text(array.dump_element(report_segment_to_json(segment, robot))));
        }
        output.write(array.close());
        continue;
      }
      const bool is_steps = placeholder == kStepsPlaceholder;
      (is_steps ? steps : scene_steps).copy_to(output);
      output.write((is_steps ? steps_array : scene_steps_array).close());
    }
    output.write(text(cut_text->pieces.back()));
  }

  int indent;
  bool escape;
  SpillFile steps;
  SpillFile scene_steps;
  JsonArrayText steps_array;
  JsonArrayText scene_steps_array;
  std::optional<TemplateCut> cut_text;
};

JsonReportStream::JsonReportStream(const RobotModel& robot, Outputs outputs)
    : robot_(robot),
      outputs_(std::move(outputs)),
      joint_types_(joint_types_of(robot)),
      poses_(robot) {
  // render_json_report(): 2-space indentation; the viewer page: compact.
  if (!outputs_.json_path.empty()) pretty_ = std::make_unique<Form>(outputs_.scratch_path, 2, false);
  if (outputs_.script_safe) script_safe_ = std::make_unique<Form>(outputs_.scratch_path, -1, true);
}

JsonReportStream::~JsonReportStream() = default;

void JsonReportStream::on_step(const certify::StepRecord& step) {
  if (step.index <= last_index_) throw std::logic_error("report: step indices do not increase");
  last_index_ = step.index;
  collisions_ |= step_reports_collision(step);
  const nlohmann::json step_json = report_step_to_json(step, joint_types_);
  const nlohmann::json scene_step_json = poses_.step(step);
  for (Form* form : {pretty_.get(), script_safe_.get()}) {
    if (form != nullptr) form->add(step_json, scene_step_json);
  }
}

void JsonReportStream::finish(const certify::VerificationResult& result,
                              const certify::RobotCell& cell, const InputDigests& digests,
                              const std::string& generated_at) {
  const certify::VerificationResult head = head_of(result);
  nlohmann::json document = report_to_json(head, robot_, digests, generated_at);
  document["scene"] = scene_to_json(head, cell);
  // What report_to_json() derives from the steps, from the steps seen here.
  document["collisions_detected"] = collisions_ || result.collision_step.has_value();
  document["total_steps"] = last_index_;
  document["steps"] = streamed_array_placeholder(kStepsPlaceholder);
  document["scene"]["steps"] = streamed_array_placeholder(kSceneStepsPlaceholder);
  document["segments"] = streamed_array_placeholder(kSegmentsPlaceholder);
  segments_ = &result.segments;
  if (script_safe_) {
    script_safe_->cut(document.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  }
  if (pretty_) {
    pretty_->cut(render_json_report(document));
    AtomicOutputFile output(outputs_.json_path, outputs_.force);
    pretty_->write(output, *segments_, robot_);
    output.commit();
  }
}

void JsonReportStream::write_script_safe_report(AtomicOutputFile& output) {
  if (!script_safe_) throw std::logic_error("json report stream: no script-safe form was kept");
  if (segments_ == nullptr) throw std::logic_error("json report stream: written before finish()");
  script_safe_->write(output, *segments_, robot_);
}

}  // namespace grpvss::report

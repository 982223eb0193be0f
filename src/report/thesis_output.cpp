#include "grpvss/report/thesis_output.hpp"

#include <algorithm>
#include <functional>
#include <unordered_set>
#include <stdexcept>
#include <utility>
#include <variant>

#include <fmt/core.h>

#include "grpvss/report/atomic_output.hpp"
#include "grpvss/report/file_units.hpp"
#include "thesis_fixed2.hpp"

namespace grpvss::report {

namespace {

std::string joined(const std::vector<double>& values, const char* separator) {
  std::string text;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += separator;
    text += fixed2(values[i]);
  }
  return text;
}

std::vector<double> in_file_units(const Eigen::VectorXd& q, const std::vector<JointType>& types) {
  return joint_values_in_file_units(q, types);
}

/// "link_4 hull 0 / post": the pair of an interference point, from the run's labels.
std::string pair_label(const ThesisNames& names, const certify::InterferencePoint& point) {
  const auto label = [](const std::vector<std::string>& labels, int index, const char* what) {
    const auto i = static_cast<std::size_t>(index);
    return index >= 0 && i < labels.size() ? labels[i] : fmt::format("{} {}", what, index);
  };
  return fmt::format("{} hull {} / {}", label(names.links, point.link, "link"), point.hull,
                     label(names.obstacles, point.obstacle, "obstacle"));
}

}  // namespace

ThesisNames ThesisNames::of(const RobotModel& robot, const Environment& environment) {
  ThesisNames names;
  const bool named_link = std::any_of(robot.links.begin(), robot.links.end(),
                                      [](const Link& link) { return !link.name.empty(); });
  if (!named_link && !environment.has_names()) return names;
  for (std::size_t i = 0; i < robot.links.size(); ++i) {
    names.links.push_back(link_label(robot, static_cast<int>(i)));
  }
  for (std::size_t o = 0; o < environment.obstacles.size(); ++o) {
    names.obstacles.push_back(obstacle_label(environment, static_cast<int>(o)));
  }
  return names;
}

std::string thesis_step_block(const certify::StepRecord& step,
                              const std::vector<JointType>& joint_types,
                              const ThesisNames& names) {
  std::string out = fmt::format("IN {}TH STEP, THE JOINT VALUES ARE\n", step.index);
  out += joined(in_file_units(step.q, joint_types), " ") + "\n\n";
  out += fmt::format("THERE ARE {} INTERFERENCE POINTS IN THIS STEP\n\n",
                     step.interference_points.size());
  if (step.interference_points.empty()) return out;
  for (const certify::InterferencePoint& point : step.interference_points) {
    out += joined({point.p_W.x(), point.p_W.y(), point.p_W.z()}, "\t");
    // Only a cell's run names the pair: thesis files keep A.3's three numbers.
    if (!names.empty()) out += "\t" + pair_label(names, point);
    out += "\n";
  }
  out += "\n";
  return out;
}

namespace {

/// A.3 prints two decimals (0.50 in); a tolerance they would misstate (0.005 m as 0.01) is
/// printed with the digits it needs.
std::string tolerance_text(double tolerance) {
  const std::string two_decimals = fixed2(tolerance);
  return std::stod(two_decimals) == tolerance ? two_decimals : fmt::format("{}", tolerance);
}

/// The A.3 layout around the steps; where the steps come from (the result, or a stream's
/// scratch file) and where the text goes are the caller's.
class ThesisWriter {
 public:
  using Sink = std::function<void(const std::string&)>;
  using StepsOf = std::function<void(int segment)>;

  /// `named_model`: the run names its links and obstacles (a cell), so it is not a thesis
  /// file's run and its header may state the motion model.
  ThesisWriter(const certify::VerificationResult& result, const std::vector<JointType>& types,
               bool named_model, Sink sink)
      : result_(result), types_(types), named_model_(named_model), sink_(std::move(sink)) {}

  /// `steps_of(k)` emits segment k's step blocks; `total`, `collisions`: the closing lines.
  void render(const StepsOf& steps_of, int total, bool collisions) {
    line(fmt::format("THE TOLERANCE VALUE = {}", tolerance_text(result_.tolerance)));
    blank();
    // The only line A.3 does not have: a certified run steps differently from the thesis.
    if (result_.mode == certify::ResolutionMode::kCertified) {
      line("THE RESOLUTION MODE = CERTIFIED");
      blank();
    }
    // A cell's run and a joint trajectory state their motion (issue 20.1); thesis files keep
    // A.3's header byte for byte.
    if (!result_.motion_model.empty() && (named_model_ || has_trajectory_pieces())) {
      line("THE MOTION MODEL = " + result_.motion_model);
      blank();
    }
    for (const certify::SegmentRecord& segment : result_.segments) {
      segment_block(segment);
      steps_of(segment.number);
      for (const certify::PathError& error : result_.errors) {
        if (error.segment == segment.number) error_block(error);
      }
    }
    for (const certify::PathError& error : result_.errors) {
      if (!has_segment(error.segment)) error_block(error);
    }
    line(fmt::format("TOTAL {} STEPS IN THIS PATH", total));
    line(collisions ? "COLLISIONS DETECTED IN THIS PATH" : "NO COLLISION DETECTED IN THIS PATH");
  }

  void emit(const std::string& text) { sink_(text); }

  bool has_trajectory_pieces() const {
    for (const auto& segment : result_.segments) {
      if (segment.trajectory_piece) return true;
    }
    return false;
  }

  bool has_segment(int number) const {
    for (const auto& segment : result_.segments) {
      if (segment.number == number) return true;
    }
    return false;
  }

 private:
  void line(const std::string& text) { sink_(text + '\n'); }
  void blank() { sink_("\n"); }

  std::vector<double> in_file_units(const Eigen::VectorXd& q) const {
    return joint_values_in_file_units(q, types_);
  }

  void world_target_line(const WorldTarget& target) {
    line(joined({target.position_W.x(), target.position_W.y(), target.position_W.z(),
                 target.axis_W.x(), target.axis_W.y(), target.axis_W.z(), degrees(target.angle)},
                " "));
    if (target.orientation_is_absolute) line("(THE ORIENTATION ABOVE IS THE END-EFFECTOR'S IN THE WORLD FRAME, NOT A CHANGE)");
  }

  void segment_block(const certify::SegmentRecord& segment) {
    line(fmt::format("THE {}TH SEGMENT OF THE PATH INPUT FROM FILE {}", segment.number,
                     result_.path_file_label));
    blank();
    std::visit([&](const auto& spec) { spec_block(segment, spec); }, segment.input.spec);
  }

  void spec_block(const certify::SegmentRecord&, const PtpWorldSegment& spec) {
    line("--- PTP (WCS)---");
    blank();
    line("ENDING POSITION ORIENTATION CHANGE AXIS ROTATING ANGLE");
    blank();
    world_target_line(spec.target);
    blank();
    line("JOINT VELOCITY " + joined(in_file_units(spec.velocity), " "));
    blank();
  }

  void spec_block(const certify::SegmentRecord&, const CpLineSegment& spec) {
    line("--- CP ---");
    line("ENDING POSITION ORIENTATION CHANGE AXIS ROTATING ANGLE");
    world_target_line(spec.target);
    blank();
  }

  // A piece of a joint trajectory: from one waypoint to the next, no desired speeds.
  void trajectory_piece_block(const certify::SegmentRecord& segment, const PtpJointSegment& spec) {
    line("--- JOINT TRAJECTORY PIECE ---");
    line(" STARTING JOINT VALUE FINAL JOINT VALUE");
    blank();
    const std::vector<double> start = in_file_units(segment.start_q);
    const std::vector<double> target = in_file_units(spec.target);
    for (std::size_t i = 0; i < start.size(); ++i) {
      line(fmt::format("JOINT {}\t{}\t{}", i + 1, fixed2(start[i]), fixed2(target[i])));
    }
    blank();
  }

  void spec_block(const certify::SegmentRecord& segment, const PtpJointSegment& spec) {
    if (segment.trajectory_piece) return trajectory_piece_block(segment, spec);
    line("--- PTP (JCS)---");
    line(" STARTING JOINT VALUE FINAL JOINT VALUE DESIRED VELOCITY");
    blank();
    const std::vector<double> start = in_file_units(segment.start_q);
    const std::vector<double> target = in_file_units(spec.target);
    const std::vector<double> velocity = in_file_units(spec.velocity);
    for (std::size_t i = 0; i < start.size(); ++i) {
      line(fmt::format("JOINT {}\t{}\t{}\t{}", i + 1, fixed2(start[i]), fixed2(target[i]),
                       fixed2(velocity[i])));
    }
    blank();
  }

  void error_block(const certify::PathError& error) {
    line("THIS PATH IS NOT QUALIFIED.");
    line(fmt::format("THE ERROR IS TYPE {}", error.code));
    line("CHECK THE USER GUIDE FOR DETAILED ERROR DESCRIPTIONS");
    blank();
  }

  const certify::VerificationResult& result_;
  const std::vector<JointType>& types_;
  bool named_model_;
  Sink sink_;
};

}  // namespace

bool step_reports_collision(const certify::StepRecord& step) {
  return !step.interference_points.empty() || step.expanded_interferes || step.unexpanded_collides;
}

bool thesis_reports_collision(const certify::VerificationResult& result) {
  if (result.collision_step) return true;
  for (const certify::StepRecord& step : result.steps) {
    if (step_reports_collision(step)) return true;
  }
  return false;
}

int total_steps(const certify::VerificationResult& result) {
  int previous = 0;
  for (const auto& step : result.steps) {
    if (step.index <= previous) throw std::logic_error("report: step indices do not increase");
    previous = step.index;
  }
  return previous;
}

std::string render_thesis_output(const certify::VerificationResult& result,
                                 const std::vector<JointType>& joint_types,
                                 const ThesisNames& names) {
  std::string out;
  ThesisWriter writer(result, joint_types, !names.empty(),
                      [&out](const std::string& text) { out += text; });
  std::size_t steps_written = 0;
  const auto steps_of = [&](int segment) {
    for (const certify::StepRecord& step : result.steps) {
      if (step.segment != segment) continue;
      out += thesis_step_block(step, joint_types, names);
      ++steps_written;
    }
  };
  writer.render(steps_of, total_steps(result), thesis_reports_collision(result));
  if (steps_written != result.steps.size()) {
    throw std::logic_error("thesis output: a step belongs to no segment record");
  }
  return out;
}

ThesisOutputStream::ThesisOutputStream(std::string path, bool force,
                                       std::vector<JointType> joint_types, ThesisNames names)
    : path_(std::move(path)), force_(force), joint_types_(std::move(joint_types)),
      names_(std::move(names)), steps_(path_) {}

ThesisOutputStream::~ThesisOutputStream() = default;

void ThesisOutputStream::on_step(const certify::StepRecord& step) {
  if (step.index <= last_index_) throw std::logic_error("report: step indices do not increase");
  last_index_ = step.index;
  collisions_ |= step_reports_collision(step);
  if (ranges_.empty() || ranges_.back().segment != step.segment) {
    // The verifier runs the segments in order: increasing numbers keep the lookup a search.
    if (!ranges_.empty() && step.segment < ranges_.back().segment) {
      throw std::logic_error("thesis output stream: the steps' segments do not increase");
    }
    ranges_.push_back({step.segment, steps_.size(), steps_.size()});
  }
  steps_.append(thesis_step_block(step, joint_types_, names_));
  ranges_.back().end = steps_.size();
}

void ThesisOutputStream::finish(const certify::VerificationResult& result) {
  AtomicOutputFile output(path_, force_);
  ThesisWriter writer(result, joint_types_, !names_.empty(),
                      [&output](const std::string& text) { output.write(text); });
  std::unordered_set<int> recorded;
  for (const certify::SegmentRecord& segment : result.segments) recorded.insert(segment.number);
  for (const SegmentRange& range : ranges_) {
    if (recorded.count(range.segment) == 0) {
      throw std::logic_error("thesis output: a step belongs to no segment record");
    }
  }
  const auto steps_of = [&](int segment) {
    const auto found = std::lower_bound(
        ranges_.begin(), ranges_.end(), segment,
        [](const SegmentRange& range, int number) { return range.segment < number; });
    if (found != ranges_.end() && found->segment == segment) {
      steps_.copy_to(output, found->begin, found->end);
    }
  };
  writer.render(steps_of, last_index_, collisions_ || result.collision_step.has_value());
  output.commit();
}

std::string render_thesis_output(const certify::VerificationResult& result,
                                 const RobotModel& robot) {
  return render_thesis_output(result, joint_types_of(robot));
}

}  // namespace grpvss::report

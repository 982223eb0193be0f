#include "grpvss/report/thesis_output.hpp"

#include <stdexcept>
#include <variant>

#include <fmt/core.h>

#include "grpvss/report/file_units.hpp"

namespace grpvss::report {

namespace {

/// `%.2f` as FORTRAN's F format printed it, without the "-0.00" a tiny negative would give.
std::string fixed2(double value) {
  std::string text = fmt::format("{:.2f}", value);
  if (text == "-0.00") text = "0.00";
  return text;
}

std::string joined(const std::vector<double>& values, const char* separator) {
  std::string text;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += separator;
    text += fixed2(values[i]);
  }
  return text;
}

class ThesisWriter {
 public:
  ThesisWriter(const certify::VerificationResult& result, const std::vector<JointType>& types)
      : result_(result), types_(types) {}

  std::string render() {
    line(fmt::format("THE TOLERANCE VALUE = {}", fixed2(result_.tolerance)));
    blank();
    // The only line A.3 does not have: a certified run steps differently from the thesis.
    if (result_.mode == certify::ResolutionMode::kCertified) {
      line("THE RESOLUTION MODE = CERTIFIED");
      blank();
    }
    std::size_t steps_written = 0;
    for (const certify::SegmentRecord& segment : result_.segments) {
      segment_block(segment);
      for (const certify::StepRecord& step : result_.steps) {
        if (step.segment != segment.number) continue;
        step_block(step);
        ++steps_written;
      }
      for (const certify::PathError& error : result_.errors) {
        if (error.segment == segment.number) error_block(error);
      }
    }
    if (steps_written != result_.steps.size()) {
      throw std::logic_error("thesis output: a step belongs to no segment record");
    }
    for (const certify::PathError& error : result_.errors) {
      if (!has_segment(error.segment)) error_block(error);
    }
    line(fmt::format("TOTAL {} STEPS IN THIS PATH", total_steps(result_)));
    line(thesis_reports_collision(result_) ? "COLLISIONS DETECTED IN THIS PATH"
                                           : "NO COLLISION DETECTED IN THIS PATH");
    return std::move(out_);
  }

 private:
  void line(const std::string& text) {
    out_ += text;
    out_ += '\n';
  }
  void blank() { out_ += '\n'; }

  bool has_segment(int number) const {
    for (const auto& segment : result_.segments) {
      if (segment.number == number) return true;
    }
    return false;
  }

  std::vector<double> in_file_units(const Eigen::VectorXd& q) const {
    return joint_values_in_file_units(q, types_);
  }

  void world_target_line(const WorldTarget& target) {
    line(joined({target.position_W.x(), target.position_W.y(), target.position_W.z(),
                 target.axis_W.x(), target.axis_W.y(), target.axis_W.z(), degrees(target.angle)},
                " "));
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

  void spec_block(const certify::SegmentRecord& segment, const PtpJointSegment& spec) {
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

  void step_block(const certify::StepRecord& step) {
    line(fmt::format("IN {}TH STEP, THE JOINT VALUES ARE", step.index));
    line(joined(in_file_units(step.q), " "));
    blank();
    line(fmt::format("THERE ARE {} INTERFERENCE POINTS IN THIS STEP",
                     step.interference_points.size()));
    blank();
    if (step.interference_points.empty()) return;
    for (const certify::InterferencePoint& point : step.interference_points) {
      line(joined({point.p_W.x(), point.p_W.y(), point.p_W.z()}, "\t"));
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
  std::string out_;
};

}  // namespace

bool thesis_reports_collision(const certify::VerificationResult& result) {
  if (result.collision_step) return true;
  for (const certify::StepRecord& step : result.steps) {
    if (!step.interference_points.empty() || step.expanded_interferes ||
        step.unexpanded_collides) {
      return true;
    }
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
                                 const std::vector<JointType>& joint_types) {
  return ThesisWriter(result, joint_types).render();
}

std::string render_thesis_output(const certify::VerificationResult& result,
                                 const RobotModel& robot) {
  return render_thesis_output(result, joint_types_of(robot));
}

}  // namespace grpvss::report

#include "grpvss/report/trajectory_report.hpp"

#include "grpvss/motion/joint_trajectory_source.hpp"

#include "grpvss/motion/profile_table.hpp"
#include "thesis_fixed2.hpp"

#include <cmath>

#include <fmt/core.h>

namespace grpvss::report {
namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

const char* segment_title(motion::SegmentKind kind) {
  switch (kind) {
    case motion::SegmentKind::kPtpJoint: return "PTP (JCS)";
    case motion::SegmentKind::kPtpWorld: return "PTP (WCS)";
    case motion::SegmentKind::kCpLine: return "CP";
    case motion::SegmentKind::kTrajectoryPiece: return "TRAJECTORY PIECE";
  }
  return "?";
}

// A length with two decimals when they show it exactly (0.50, the thesis's output), else with
// the digits its size needs (0.0127 m is not 0.01).
std::string length_text(double x) {
  if (std::round(x * 100.0) / 100.0 == x) return fixed2(x);
  return fmt::format("{:.6g}", x);
}

std::string joint_row(const RobotModel& robot, const Eigen::VectorXd& q) {
  std::string row;
  for (double value : display_joints(robot, q)) row += fmt::format(" {:>8}", fixed2(value));
  return row;
}

std::string ordinal(int n) { return fmt::format("{}TH", n); }  // the thesis writes 1TH, 2TH

nlohmann::json json_joints(const RobotModel& robot, const Eigen::VectorXd& q) {
  return display_joints(robot, q);
}

}  // namespace

std::vector<double> display_joints(const RobotModel& robot, const Eigen::VectorXd& q) {
  std::vector<double> values;
  for (int j = 0; j < robot.joint_count(); ++j)
    values.push_back(robot.joints[j].type == JointType::kRevolute ? q[j] * kDegreesPerRadian : q[j]);
  return values;
}

std::string trajectory_text(const RobotModel& robot, const motion::Trajectory& trajectory,
                            const TrajectoryReportSettings& settings) {
  const motion::MotionModel& model = trajectory.motion_model();
  std::string out;
  if (const motion::JointTrajectoryMotion* joint_motion = trajectory.joint_motion()) {
    out += fmt::format("GRPVSS JOINT TRAJECTORY {} FOR ROBOT {}\n", settings.path_file,
                       settings.robot_file);
    out += fmt::format("MOTION: {}\n", motion::describe_motion_model(*joint_motion, settings.path_file));
  } else {
    out += fmt::format("GRPVSS TRAJECTORY OF PATH {} FOR ROBOT {}\n", settings.path_file,
                       settings.robot_file);
    out += fmt::format("PTP TIMING: {}   PROFILES: {}   IK: {}\n",
                       model.timing == motion::PtpTiming::kSynchronized ? "SYNCHRONIZED" : "INDEPENDENT",
                       model.table ? "TABLE " + model.table->file_name() : "IDEAL TRAPEZOIDS",
                       settings.ik_name);
    out += fmt::format("CP SEGMENTS: NOMINAL SPEED {} PER S, SAMPLE SPACING {}\n",
                       fixed2(model.cp_speed), length_text(model.cp_spacing));
  }
  out += "JOINT VALUES IN DEGREES (REVOLUTE) AND LENGTH UNITS (PRISMATIC)\n";
  out += fmt::format("\nHOME JOINT VALUES {}\n", joint_row(robot, trajectory.home()));
  for (const motion::SegmentTrajectory& piece : trajectory.segments()) {
    out += fmt::format("\nTHE {} SEGMENT --- {} ---\n", ordinal(piece.number),
                       segment_title(piece.kind));
    if (piece.cp)
      out += fmt::format("LINE LENGTH {}   {} CP SAMPLES\n", fixed2(piece.cp->length()),
                         piece.cp_samples.size());
    out += fmt::format("START TIME {} S   CYCLE TIME {} S   END TIME {} S\n",
                       fixed2(piece.start_time), fixed2(piece.duration), fixed2(piece.end_time()));
    out += fmt::format("ENDING JOINT VALUES {}\n", joint_row(robot, piece.q_end));
  }
  if (!settings.times.empty()) {
    out += "\nJOINT VALUES AT PATH TIMES\n";
    for (double t : settings.times) {
      const auto q = trajectory.joints_at(t);
      const std::string where =
          trajectory.segment_at(t) > 0 ? fmt::format("SEGMENT {}", trajectory.segment_at(t)) : "HOME";
      out += fmt::format("T = {:>9.3f} S  {:<10} {}\n", t, where,
                         q ? joint_row(robot, *q) : std::string(" UNREACHABLE (NO IK SOLUTION)"));
    }
  }
  out += fmt::format("\nTOTAL CYCLE TIME {} S FOR {} SEGMENTS\n", fixed2(trajectory.duration()),
                     trajectory.segments().size());
  for (const motion::ThesisError& error : trajectory.errors()) {
    out += "\nTHIS PATH IS NOT QUALIFIED.\n";
    out += fmt::format("THE ERROR IS TYPE {}", error.code);
    if (error.segment > 0) out += fmt::format(" IN SEGMENT {}", error.segment);
    out += fmt::format("\n{}\n", error.message);
    if (!error.detail.empty()) out += fmt::format("DETAIL: {}\n", error.detail);
  }
  return out;
}

nlohmann::json trajectory_json(const RobotModel& robot, const motion::Trajectory& trajectory,
                               const TrajectoryReportSettings& settings) {
  nlohmann::json doc;
  doc["format"] = "grpvss-trajectory";
  doc["version"] = 1;
  doc["robot_file"] = settings.robot_file;
  doc["path_file"] = settings.path_file;
  const motion::MotionModel& model = trajectory.motion_model();
  doc["timing"] = motion::to_string(model.timing);
  doc["profile_table"] =
      model.table ? nlohmann::json(model.table->file_name()) : nlohmann::json(nullptr);
  doc["ik"] = settings.ik_name;
  if (const motion::JointTrajectoryMotion* joint_motion = trajectory.joint_motion()) {
    doc["motion_model"] = motion::describe_motion_model(*joint_motion, settings.path_file);
    doc["interpolation"] = motion::to_string(joint_motion->interpolation());
  }
  doc["cp_speed"] = model.cp_speed;
  doc["cp_spacing"] = model.cp_spacing;
  nlohmann::json units = nlohmann::json::array();
  for (const Joint& joint : robot.joints)
    units.push_back(joint.type == JointType::kRevolute ? "deg" : "length");
  doc["joint_units"] = units;
  doc["home"] = json_joints(robot, trajectory.home());
  doc["segments"] = nlohmann::json::array();
  for (const motion::SegmentTrajectory& piece : trajectory.segments()) {
    nlohmann::json segment;
    segment["number"] = piece.number;
    segment["ind"] = static_cast<int>(piece.kind);
    segment["type"] = segment_title(piece.kind);
    segment["start_time"] = piece.start_time;
    segment["cycle_time"] = piece.duration;
    segment["end_time"] = piece.end_time();
    segment["start_joints"] = json_joints(robot, piece.q_start);
    segment["end_joints"] = json_joints(robot, piece.q_end);
    if (piece.cp) {
      segment["cp_length"] = piece.cp->length();
      segment["cp_sample_count"] = piece.cp_samples.size();
    }
    doc["segments"].push_back(segment);
  }
  doc["total_cycle_time"] = trajectory.duration();
  doc["samples"] = nlohmann::json::array();
  for (double t : settings.times) {
    const auto q = trajectory.joints_at(t);
    doc["samples"].push_back({{"time", t},
                              {"segment", trajectory.segment_at(t)},
                              {"joints", q ? json_joints(robot, *q) : nlohmann::json(nullptr)}});
  }
  doc["errors"] = nlohmann::json::array();
  for (const motion::ThesisError& error : trajectory.errors())
    doc["errors"].push_back({{"code", error.code},
                             {"segment", error.segment},
                             {"message", error.message},
                             {"detail", error.detail}});
  doc["qualified"] = trajectory.errors().empty();
  return doc;
}

}  // namespace grpvss::report

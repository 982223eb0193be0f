#include "grpvss/report/json_report.hpp"

#include <chrono>
#include <cmath>
#include <ctime>
#include <stdexcept>
#include <variant>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "grpvss/report/file_units.hpp"
#include "grpvss/report/program_version.hpp"
#include "thesis_error_text.hpp"
#include "grpvss/report/thesis_output.hpp"

namespace grpvss::report {

namespace {

using nlohmann::json;

/// A number the report must hold: NaN means a bug upstream, never a value to print.
double finite(double value, const char* what) {
  if (!std::isfinite(value)) {
    throw std::logic_error(fmt::format("json report: {} is {}", what, value));
  }
  return value;
}

/// A clearance: +infinity (nothing to collide with) is written as null.
json clearance(double value, const char* what) {
  if (std::isinf(value) && value > 0) return nullptr;
  return finite(value, what);
}

json optional_clearance(const std::optional<double>& value, const char* what) {
  return value ? clearance(*value, what) : json(nullptr);
}

json vector3(const Eigen::Vector3d& v, const char* what) {
  return json::array({finite(v.x(), what), finite(v.y(), what), finite(v.z(), what)});
}

class JsonWriter {
 public:
  JsonWriter(const certify::VerificationResult& result, const RobotModel& robot)
      : result_(result), robot_(robot), types_(joint_types_of(robot)) {}

  json joint_values(const Eigen::VectorXd& q, const char* what) const {
    json values = json::array();
    for (double value : joint_values_in_file_units(q, types_)) values.push_back(finite(value, what));
    return values;
  }

  json optional_joint_values(const Eigen::VectorXd& q, const char* what) const {
    return q.size() == 0 ? json(nullptr) : joint_values(q, what);
  }

  json robot() const {
    json types = json::array();
    for (JointType type : types_) {
      types.push_back(type == JointType::kRevolute ? "revolute" : "prismatic");
    }
    return {{"name", robot_.name}, {"joint_count", robot_.joint_count()}, {"joint_types", types}};
  }

  json segment(const certify::SegmentRecord& record) const {
    json out = {{"number", record.number},
                {"source_line", record.input.source_line},
                {"simulated", record.simulated},
                {"first_step", record.first_step},
                {"last_step", record.last_step},
                {"cycle_time", finite(record.cycle_time, "cycle_time")},
                {"start_joint_values", optional_joint_values(record.start_q, "start_q")},
                {"end_joint_values", optional_joint_values(record.end_q, "end_q")},
                {"target_position", nullptr},
                {"target_axis", nullptr},
                {"target_angle", nullptr},
                {"target_joint_values", nullptr},
                {"joint_velocity", nullptr}};
    const auto world_target = [&out](const WorldTarget& target) {
      out["target_position"] = vector3(target.position_W, "target position");
      out["target_axis"] = vector3(target.axis_W, "target axis");
      out["target_angle"] = finite(degrees(target.angle), "target angle");
      // Only YAML paths give absolute orientations; thesis reports keep their fields.
      if (target.orientation_is_absolute) out["target_orientation"] = "absolute";
    };
    if (record.trajectory_piece) {
      // A piece of a planner's joint trajectory: its target is the next waypoint.
      out["kind"] = "trajectory-piece";
      out["target_joint_values"] =
          joint_values(std::get<PtpJointSegment>(record.input.spec).target, "joint target");
    } else if (const auto* ptp_joint = std::get_if<PtpJointSegment>(&record.input.spec)) {
      out["kind"] = "ptp-joint";
      out["target_joint_values"] = joint_values(ptp_joint->target, "joint target");
      out["joint_velocity"] = joint_values(ptp_joint->velocity, "joint velocity");
    } else if (const auto* ptp_world = std::get_if<PtpWorldSegment>(&record.input.spec)) {
      out["kind"] = "ptp-world";
      world_target(ptp_world->target);
      out["joint_velocity"] = joint_values(ptp_world->velocity, "joint velocity");
    } else {
      out["kind"] = "cp-line";
      world_target(std::get<CpLineSegment>(record.input.spec).target);
    }
    return out;
  }

  static json link_record(int link, const certify::LinkStepRecord& record) {
    return {{"link", link},
            {"motion_bound", finite(record.motion_bound, "motion_bound")},
            {"allowance", finite(record.allowance, "allowance")},
            {"governing", certify::to_string(record.governing)},
            {"clearance", clearance(record.clearance, "clearance")},
            {"motion_clearance", optional_clearance(record.motion_clearance, "motion_clearance")}};
  }

  static json interference_point(const certify::InterferencePoint& point) {
    return {{"link", point.link},
            {"hull", point.hull},
            {"obstacle", point.obstacle},
            {"point", vector3(point.p_W, "interference point")},
            {"kind", geometry::to_string(point.kind)}};
  }

  static json contact(const certify::PairContact& pair) {
    return {{"link", pair.link},
            {"hull", pair.hull},
            {"obstacle", pair.obstacle},
            {"unexpanded_collides", pair.unexpanded_collides}};
  }

  static json episode(const certify::InterferenceEpisode& run) {
    const auto optional_step = [](const std::optional<int>& step) {
      return step ? json(*step) : json(nullptr);
    };
    const json cleared_time =
        run.cleared_time ? json(finite(*run.cleared_time, "episode cleared_time")) : json(nullptr);
    return {{"link", run.link},
            {"hull", run.hull},
            {"obstacle", run.obstacle},
            {"first_step", run.first_step},
            {"last_step", run.last_step},
            {"first_segment", run.first_segment},
            {"last_segment", run.last_segment},
            {"first_time", finite(run.first_time, "episode first_time")},
            {"last_time", finite(run.last_time, "episode last_time")},
            {"first_collision_step", optional_step(run.first_collision_step)},
            {"last_collision_step", optional_step(run.last_collision_step)},
            {"cleared_step", optional_step(run.cleared_step)},
            {"cleared_time", cleared_time}};
  }

  json step(const certify::StepRecord& record) const {
    return step_json(record, types_);
  }

  static json step_json(const certify::StepRecord& record, const std::vector<JointType>& types) {
    const auto joint_values = [&types](const Eigen::VectorXd& q, const char* what) {
      json values = json::array();
      for (double value : joint_values_in_file_units(q, types)) values.push_back(finite(value, what));
      return values;
    };
    json links = json::array();
    for (std::size_t k = 0; k < record.links.size(); ++k) {
      links.push_back(link_record(static_cast<int>(k), record.links[k]));
    }
    json points = json::array();
    for (const auto& point : record.interference_points) points.push_back(interference_point(point));
    json contacts = json::array();
    for (const auto& pair : record.contacts) contacts.push_back(contact(pair));
    json item = {{"index", record.index},
            {"segment", record.segment},
            {"path_time", finite(record.path_time, "path_time")},
            {"segment_parameter", finite(record.segment_parameter, "segment_parameter")},
            {"joint_values", joint_values(record.q, "step joint values")},
            {"end_effector", vector3(record.end_effector_W, "end effector")},
            {"links", links},
            {"interference_points", points},
            {"contacts", contacts},
            {"expanded_interferes", record.expanded_interferes},
            {"unexpanded_collides", record.unexpanded_collides},
            {"refinement", record.refinement}};
    // Only with self-collision: reports of robots without it keep their bytes.
    if (!record.self_contacts.empty()) {
      json self = json::array();
      for (const SelfCollisionPair& pair : record.self_contacts) self.push_back(self_pair(pair));
      item["self_contacts"] = self;
    }
    return item;
  }

  static json self_pair(const SelfCollisionPair& pair) {
    return {{"link_a", pair.link_a}, {"hull_a", pair.hull_a},
            {"link_b", pair.link_b}, {"hull_b", pair.hull_b}};
  }

  // What the run verified about self-collision: written only for robots that have self pairs
  // or unverified link pairs (URDF cells), so thesis reports keep their bytes.
  json self_collision() const {
    json not_verified = json::array();
    for (const UnverifiedLinkPair& pair : robot_.unverified_link_pairs) {
      not_verified.push_back({{"first", pair.first}, {"second", pair.second},
                              {"reason", pair.reason}});
    }
    json episodes = json::array();
    for (const certify::SelfCollisionEpisode& run : result_.self_collision_episodes) {
      json item = self_pair(run.pair);
      item["name"] = self_pair_label(robot_, run.pair);
      item["first_step"] = run.first_step;
      item["last_step"] = run.last_step;
      item["first_time"] = finite(run.first_time, "first_time");
      item["last_time"] = finite(run.last_time, "last_time");
      episodes.push_back(item);
    }
    return {{"pairs_verified", robot_.self_collision_pairs.size()},
            {"not_verified", not_verified},
            {"episodes", episodes}};
  }

  static json error(const certify::PathError& record) {
    const bool thesis = is_thesis_error_code(record.code) && (record.code < 3 || record.segment > 0);
    return {{"code", record.code},
            {"segment", record.segment},
            {"step", record.step},
            {"message", record.message},
            {"thesis_text", thesis ? json(thesis_error_text(record.code, record.segment))
                                   : json(nullptr)}};
  }

  static json link_clearance(const certify::LinkClearanceSummary& summary) {
    return {{"link", summary.link},
            {"min_clearance", clearance(summary.min_clearance, "min_clearance")},
            {"step", summary.step},
            {"obstacle", summary.obstacle < 0 ? json(nullptr) : json(summary.obstacle)},
            {"min_motion_clearance",
             optional_clearance(summary.min_motion_clearance, "min_motion_clearance")},
            {"motion_step", summary.min_motion_clearance ? json(summary.motion_step)
                                                         : json(nullptr)}};
  }

  json render(const InputDigests& digests, const std::string& generated_at) const {
    json segments = json::array();
    for (const auto& record : result_.segments) segments.push_back(segment(record));
    json steps = json::array();
    for (const auto& record : result_.steps) steps.push_back(step(record));
    json errors = json::array();
    for (const auto& record : result_.errors) errors.push_back(error(record));
    json clearances = json::array();
    for (const auto& summary : result_.link_clearances) clearances.push_back(link_clearance(summary));
    json episodes = json::array();
    for (const auto& run : result_.interference_episodes) episodes.push_back(episode(run));
    const auto input = [](const InputFileDigest& digest) {
      return json{{"file", digest.file}, {"sha256", digest.sha256}};
    };
    json report = {
        {"schema", kReportSchemaId},
        {"program", {{"name", "grpvss"}, {"version", program_version()}}},
        {"generated_at", generated_at},
        {"inputs",
         {{"robot", input(digests.robot)},
          {"environment", input(digests.environment)},
          {"path", input(digests.path)}}},
        {"units",
         {{"length", digests.length_unit.empty() ? std::string("unit of the input files")
                                                 : digests.length_unit},
          {"revolute_joint", "deg"},
          {"prismatic_joint", "length"},
          {"revolute_joint_velocity", "deg/s"},
          {"prismatic_joint_velocity", "length/s"},
          {"angle", "deg"},
          {"time", "s"},
          {"segment_parameter", "s for PTP segments, length for CP segments"}}},
        {"robot", robot()},
        {"tolerance", finite(result_.tolerance, "tolerance")},
        {"mode", certify::to_string(result_.mode)},
        {"verdict", certify::to_string(result_.verdict)},
        {"collisions_detected", thesis_reports_collision(result_)},
        {"collision_step",
         result_.collision_step ? json(*result_.collision_step) : json(nullptr)},
        {"path_file_label", result_.path_file_label},
        {"total_steps", total_steps(result_)},
        {"total_cycle_time", finite(result_.total_cycle_time, "total_cycle_time")},
        {"segments", segments},
        {"steps", steps},
        {"errors", errors},
        {"link_clearances", clearances},
        {"interference_episodes", episodes},
    };
    if (!robot_.self_collision_pairs.empty() || !robot_.unverified_link_pairs.empty()) {
      report["self_collision"] = self_collision();
    }
    // Only a trajectory run states it: path reports stay as they were.
    if (!result_.motion_model.empty()) report["motion_model"] = result_.motion_model;
    if (result_.mode == certify::ResolutionMode::kCertified) {
      report["claim"] = certify::to_string(result_.claim);  // docs/verification.md#claim
    }
    if (result_.tolerance_shortfall) {
      const certify::ToleranceShortfall& shortfall = *result_.tolerance_shortfall;
      report["tolerance_shortfall"] = {
          {"step", shortfall.step},
          {"link", shortfall.link},
          {"obstacle", shortfall.obstacle >= 0 ? json(shortfall.obstacle) : json(nullptr)},
          {"motion_clearance", shortfall.motion_clearance}};
      // A self pair (proofs/two-ball-cover.md#corollary-self-tolerance-along-motion).
      if (shortfall.other_link >= 0) report["tolerance_shortfall"]["other_link"] = shortfall.other_link;
    }
    return report;
  }

 private:
  const certify::VerificationResult& result_;
  const RobotModel& robot_;
  std::vector<JointType> types_;
};

}  // namespace

nlohmann::json report_to_json(const certify::VerificationResult& result, const RobotModel& robot,
                              const InputDigests& digests, const std::string& generated_at) {
  return JsonWriter(result, robot).render(digests, generated_at);
}

nlohmann::json report_segment_to_json(const certify::SegmentRecord& segment,
                                      const RobotModel& robot) {
  static const certify::VerificationResult kNoRun;
  return JsonWriter(kNoRun, robot).segment(segment);
}

nlohmann::json report_step_to_json(const certify::StepRecord& step,
                                   const std::vector<JointType>& joint_types) {
  return JsonWriter::step_json(step, joint_types);
}

nlohmann::json report_to_json(const certify::VerificationResult& result, const RobotModel& robot,
                              const InputDigests& digests) {
  return report_to_json(result, robot, digests, utc_timestamp_now());
}

std::string render_json_report(const nlohmann::json& report) {
  // Invalid UTF-8 (a file name from a foreign locale) becomes U+FFFD instead of throwing.
  return report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string utc_timestamp_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace grpvss::report

#include "grpvss/report/json_report.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <regex>
#include <set>
#include <stdexcept>
#include <string>

#include <fmt/core.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/report/program_version.hpp"
#include "report/thesis_error_text.hpp"
#include "grpvss/report/thesis_output.hpp"
#include "support/json_structure_check.hpp"
#include "support/text_files.hpp"
#include "support/thesis_sample_result.hpp"

namespace grpvss::report {
namespace {

using nlohmann::json;

const std::string kSourceDir = GRPVSS_SOURCE_DIR;
constexpr const char* kPinnedTime = "2026-11-21T00:00:00Z";

InputDigests sample_digests() {
  return {{"robot.txt", sha256_hex("robot")},
          {"environment.txt", sha256_hex("environment")},
          {"path.txt", sha256_hex("path")}};
}

/// The A.3 sample plus what only a GRPVSS run has: per-link step records, a clearance
/// summary (one link with nothing near: +infinity), a collision step, path times.
certify::VerificationResult rich_sample_result() {
  auto result = test::thesis_a3_sample_result();
  result.mode = certify::ResolutionMode::kCertified;
  result.collision_step = 41;
  result.total_cycle_time = 61.25;
  for (auto& segment : result.segments) segment.cycle_time = 0.5 * segment.number;
  for (auto& step : result.steps) {
    step.path_time = 0.75 * step.index;
    step.segment_parameter = 0.25 * step.index;
    step.end_effector_W = Eigen::Vector3d(1.0, -2.0, 0.5 * step.index);
    for (int link = 0; link <= 4; ++link) {
      certify::LinkStepRecord record;
      record.motion_bound = 0.125 * link;
      record.allowance = 2.0;
      record.governing = link % 2 == 0 ? certify::GoverningTerm::kTolerance
                                       : certify::GoverningTerm::kClearance;
      record.clearance = step.interference_points.empty() ? 1.5 : 0.0;
      if (link == 1) record.motion_clearance = 0.0625;  // others: none (null)
      step.links.push_back(record);
    }
    for (std::size_t i = 0; i < step.interference_points.size(); ++i) {
      auto& point = step.interference_points[i];
      point.link = 4;
      point.hull = static_cast<int>(i % 2);
      point.obstacle = static_cast<int>(i % 3);
      point.kind = geometry::InterferenceKind::kEdgeOfAOnFaceOfB;
    }
  }
  result.link_clearances = {{1, 0.75, 12, 2, 0.0625, 11},
                            {2, std::numeric_limits<double>::infinity(), 0, -1, std::nullopt, 0}};
  return result;
}

json load_schema() { return json::parse(test::read_text_file(kSourceDir + "/docs/report.schema.json")); }

json sample_report() {
  return report_to_json(rich_sample_result(), test::ibm7545_joint_type_model(), sample_digests(),
                        kPinnedTime);
}

TEST(JsonReport, SampleReportSatisfiesTheSchema) {
  const auto violations = test::check_json_structure(sample_report(), load_schema());
  EXPECT_TRUE(violations.empty()) << ::testing::PrintToString(violations);
}

TEST(JsonReport, EmptyRunSatisfiesTheSchema) {
  certify::VerificationResult empty;
  const json report = report_to_json(empty, test::ibm7545_joint_type_model(), sample_digests());
  const auto violations = test::check_json_structure(report, load_schema());
  EXPECT_TRUE(violations.empty()) << ::testing::PrintToString(violations);
  EXPECT_EQ(report["total_steps"], 0);
  EXPECT_EQ(report["verdict"], "CLEAR");
  EXPECT_EQ(report["collisions_detected"], false);
}

// The checker must be able to fail, or the two tests above prove nothing.
TEST(JsonReport, StructureCheckerCatchesMissingWrongAndUndocumentedFields) {
  const json schema = load_schema();
  json missing = sample_report();
  missing["steps"][3]["links"][1].erase("governing");
  EXPECT_EQ(test::check_json_structure(missing, schema),
            std::vector<std::string>{"/steps/3/links/1: missing \"governing\""});

  json wrong_type = sample_report();
  wrong_type["segments"][0]["target_angle"] = "30";
  EXPECT_EQ(test::check_json_structure(wrong_type, schema),
            std::vector<std::string>{"/segments/0/target_angle: type is not [\"number\",\"null\"]"});

  json undocumented = sample_report();
  undocumented["steps"][0]["secret"] = 1;
  EXPECT_EQ(test::check_json_structure(undocumented, schema),
            std::vector<std::string>{"/steps/0: undocumented field \"secret\""});

  json bad_digest = sample_report();
  bad_digest["inputs"]["path"]["sha256"] = "ABC";
  EXPECT_EQ(test::check_json_structure(bad_digest, schema).size(), 1u);
}

std::string without_generated_at(json report) {
  report.erase("generated_at");
  return render_json_report(report);
}

TEST(JsonReport, RendersAreByteIdenticalExceptGeneratedAt) {
  const auto robot = test::ibm7545_joint_type_model();
  const json first = report_to_json(rich_sample_result(), robot, sample_digests());
  const json second = report_to_json(rich_sample_result(), robot, sample_digests(), "other");
  EXPECT_EQ(second["generated_at"], "other");
  EXPECT_EQ(without_generated_at(first), without_generated_at(second));
  EXPECT_EQ(render_json_report(sample_report()), render_json_report(sample_report()));
  // ... and generated_at is the ONLY field that may differ: everything else is pinned.
  json pinned = first;
  pinned["generated_at"] = "other";
  EXPECT_EQ(render_json_report(pinned), render_json_report(second));
}

TEST(JsonReport, GeneratedAtIsAnIsoUtcTimestamp) {
  EXPECT_TRUE(std::regex_match(utc_timestamp_now(),
                               std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  const json report = report_to_json(certify::VerificationResult{},
                                     test::ibm7545_joint_type_model(), sample_digests());
  EXPECT_TRUE(std::regex_match(report["generated_at"].get<std::string>(),
                               std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
}

TEST(JsonReport, HeaderFieldsNameProgramInputsAndUnits) {
  const json report = sample_report();
  EXPECT_EQ(report["schema"], kReportSchemaId);
  EXPECT_EQ(report["program"]["name"], "grpvss");
  EXPECT_EQ(report["program"]["version"], program_version());
  EXPECT_TRUE(std::regex_match(std::string(program_version()), std::regex(R"(\d+\.\d+\.\d+)")));
  EXPECT_EQ(report["inputs"]["robot"]["file"], "robot.txt");
  EXPECT_EQ(report["inputs"]["robot"]["sha256"], sha256_hex("robot"));
  EXPECT_EQ(report["inputs"]["environment"]["sha256"], sha256_hex("environment"));
  EXPECT_EQ(report["inputs"]["path"]["file"], "path.txt");
  EXPECT_EQ(report["units"]["revolute_joint"], "deg");
  EXPECT_EQ(report["robot"]["joint_types"],
            json({"revolute", "revolute", "prismatic", "revolute"}));
  EXPECT_EQ(report["mode"], "certified");
  EXPECT_EQ(report["verdict"], "ERROR");
  EXPECT_EQ(report["collision_step"], 41);
  EXPECT_EQ(report["total_steps"], 83);
  EXPECT_EQ(report["total_cycle_time"], 61.25);
}

TEST(JsonReport, JointValuesAreInFileUnits) {
  const json report = sample_report();
  const json& step1 = report["steps"][0];
  const double expected[] = {1.05, 1.05, 0.24, 1.05};  // A.3 step 1: degrees, inches
  ASSERT_EQ(step1["joint_values"].size(), 4u);
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(step1["joint_values"][j].get<double>(), expected[j], 1e-12);
  const json& segment1 = report["segments"][0];
  EXPECT_EQ(segment1["kind"], "ptp-world");
  EXPECT_NEAR(segment1["target_angle"].get<double>(), 30.0, 1e-12);
  EXPECT_NEAR(segment1["joint_velocity"][2].get<double>(), 0.3, 1e-15);  // prismatic: as is
  EXPECT_NEAR(segment1["joint_velocity"][3].get<double>(), 3.0, 1e-12);
  EXPECT_TRUE(segment1["target_joint_values"].is_null());
  const json& segment3 = report["segments"][2];
  EXPECT_EQ(segment3["kind"], "ptp-joint");
  EXPECT_NEAR(segment3["target_joint_values"][0].get<double>(), 50.0, 1e-12);
  EXPECT_TRUE(segment3["target_position"].is_null());
  EXPECT_TRUE(report["segments"][3]["end_joint_values"].is_null());  // refused segment
  EXPECT_TRUE(report["segments"][3]["joint_velocity"].is_null());    // CP has none
}

TEST(JsonReport, StepsCarryLinkRecordsAndInterferenceIds) {
  const json report = sample_report();
  const json& step41 = report["steps"][9];
  EXPECT_EQ(step41["index"], 41);
  EXPECT_EQ(step41["path_time"], 30.75);
  EXPECT_EQ(step41["segment_parameter"], 10.25);
  EXPECT_EQ(step41["end_effector"], json({1.0, -2.0, 20.5}));
  ASSERT_EQ(step41["links"].size(), 5u);
  EXPECT_EQ(step41["links"][3],
            json({{"link", 3}, {"motion_bound", 0.375}, {"allowance", 2.0},
                  {"governing", "clearance"}, {"clearance", 0.0}, {"motion_clearance", nullptr}}));
  EXPECT_EQ(step41["links"][1]["motion_clearance"], 0.0625);
  ASSERT_EQ(step41["interference_points"].size(), 8u);
  EXPECT_EQ(step41["interference_points"][5],
            json({{"link", 4}, {"hull", 1}, {"obstacle", 2}, {"point", {-14.10, 2.85, 9.00}},
                  {"kind", "edge-of-A/face-of-B"}}));
  EXPECT_EQ(step41["expanded_interferes"], true);
}

TEST(JsonReport, ErrorsAndClearances) {
  const json report = sample_report();
  ASSERT_EQ(report["errors"].size(), 1u);
  EXPECT_EQ(report["errors"][0],
            json({{"code", 3}, {"segment", 4}, {"step", 83},
                  {"message", "final position of segment 4 is out of the workspace"},
                  {"thesis_text", thesis_error_text(3, 4)}}));
  EXPECT_EQ(report["link_clearances"][0],
            json({{"link", 1}, {"min_clearance", 0.75}, {"step", 12}, {"obstacle", 2},
                  {"min_motion_clearance", 0.0625}, {"motion_step", 11}}));
  // Nothing near link 2: infinite clearance and no obstacle, both null; no motion clearance.
  EXPECT_EQ(report["link_clearances"][1],
            json({{"link", 2}, {"min_clearance", nullptr}, {"step", 0}, {"obstacle", nullptr},
                  {"min_motion_clearance", nullptr}, {"motion_step", nullptr}}));
}

TEST(JsonReport, NewErrorCodesHaveNoThesisText) {
  auto result = test::thesis_a3_sample_result();
  result.errors[0].code = 9;
  const json report = report_to_json(result, test::ibm7545_joint_type_model(), sample_digests(), kPinnedTime);
  EXPECT_TRUE(report["errors"][0]["thesis_text"].is_null());
}

TEST(JsonReport, NanWrongJointCountAndUnorderedStepsAreLogicErrors) {
  const auto robot = test::ibm7545_joint_type_model();
  auto nan_time = test::thesis_a3_sample_result();
  nan_time.steps[2].path_time = std::nan("");
  EXPECT_THROW(report_to_json(nan_time, robot, sample_digests(), kPinnedTime), std::logic_error);
  auto unordered = test::thesis_a3_sample_result();
  unordered.steps[1].index = 1;
  EXPECT_THROW(report_to_json(unordered, robot, sample_digests(), kPinnedTime), std::logic_error);
  auto short_q = test::thesis_a3_sample_result();
  short_q.steps[0].q = Eigen::Vector3d(0, 0, 0);
  EXPECT_THROW(report_to_json(short_q, robot, sample_digests(), kPinnedTime), std::logic_error);
}

// "The JSON holds all of the thesis file's content": rebuild the A.3 text from the JSON
// alone and compare it with the golden file.
std::string fixed2(double value) {
  std::string text = fmt::format("{:.2f}", value);
  return text == "-0.00" ? "0.00" : text;
}

std::string numbers(const json& values, const char* separator) {
  std::string text;
  for (std::size_t i = 0; i < values.size(); ++i) {
    text += (i ? separator : "") + fixed2(values[i].get<double>());
  }
  return text;
}

// Two decimals as A.3, unless they would misstate the tolerance (docs/thesis-output.md).
std::string tolerance_from_json(const json& report) {
  const double tolerance = report["tolerance"].get<double>();
  const std::string two = fixed2(report["tolerance"]);
  return std::stod(two) == tolerance ? two : fmt::format("{}", tolerance);
}

std::string thesis_text_from_json(const json& report) {
  std::string out = "THE TOLERANCE VALUE = " + tolerance_from_json(report) + "\n\n";
  if (report["mode"] == "certified") out += "THE RESOLUTION MODE = CERTIFIED\n\n";
  for (const json& segment : report["segments"]) {
    out += fmt::format("THE {}TH SEGMENT OF THE PATH INPUT FROM FILE {}\n\n",
                       segment["number"].get<int>(), report["path_file_label"].get<std::string>());
    json world = segment["target_position"];
    for (const json& v : segment["target_axis"]) world.push_back(v);
    world.push_back(segment["target_angle"]);
    if (segment["kind"] == "ptp-world") {
      out += "--- PTP (WCS)---\n\nENDING POSITION ORIENTATION CHANGE AXIS ROTATING ANGLE\n\n" +
             numbers(world, " ") + "\n\nJOINT VELOCITY " + numbers(segment["joint_velocity"], " ") +
             "\n\n";
    } else if (segment["kind"] == "cp-line") {
      out += "--- CP ---\nENDING POSITION ORIENTATION CHANGE AXIS ROTATING ANGLE\n" +
             numbers(world, " ") + "\n\n";
    } else {
      out += "--- PTP (JCS)---\n STARTING JOINT VALUE FINAL JOINT VALUE DESIRED VELOCITY\n\n";
      for (std::size_t j = 0; j < segment["start_joint_values"].size(); ++j) {
        out += fmt::format("JOINT {}\t{}\t{}\t{}\n", j + 1, fixed2(segment["start_joint_values"][j]),
                           fixed2(segment["target_joint_values"][j]),
                           fixed2(segment["joint_velocity"][j]));
      }
      out += "\n";
    }
    for (const json& step : report["steps"]) {
      if (step["segment"] != segment["number"]) continue;
      out += fmt::format("IN {}TH STEP, THE JOINT VALUES ARE\n{}\n\nTHERE ARE {} INTERFERENCE "
                         "POINTS IN THIS STEP\n\n",
                         step["index"].get<int>(), numbers(step["joint_values"], " "),
                         step["interference_points"].size());
      for (const json& point : step["interference_points"]) out += numbers(point["point"], "\t") + "\n";
      if (!step["interference_points"].empty()) out += "\n";
    }
    for (const json& error : report["errors"]) {
      if (error["segment"] != segment["number"]) continue;
      out += fmt::format("THIS PATH IS NOT QUALIFIED.\nTHE ERROR IS TYPE {}\nCHECK THE USER GUIDE "
                         "FOR DETAILED ERROR DESCRIPTIONS\n\n",
                         error["code"].get<int>());
    }
  }
  for (const json& error : report["errors"]) {
    bool has_segment = false;
    for (const json& segment : report["segments"]) has_segment |= segment["number"] == error["segment"];
    if (has_segment) continue;
    out += fmt::format("THIS PATH IS NOT QUALIFIED.\nTHE ERROR IS TYPE {}\nCHECK THE USER GUIDE "
                       "FOR DETAILED ERROR DESCRIPTIONS\n\n",
                       error["code"].get<int>());
  }
  out += fmt::format("TOTAL {} STEPS IN THIS PATH\n{}\n", report["total_steps"].get<int>(),
                     report["collisions_detected"] ? "COLLISIONS DETECTED IN THIS PATH"
                                                   : "NO COLLISION DETECTED IN THIS PATH");
  return out;
}

TEST(JsonReport, HoldsEverythingTheThesisOutputFileHolds) {
  const json report = report_to_json(test::thesis_a3_sample_result(),
                                     test::ibm7545_joint_type_model(), sample_digests(), kPinnedTime);
  EXPECT_EQ(thesis_text_from_json(report),
            test::read_text_file(kSourceDir + "/tests/report/golden/thesis_output_sample.txt"));
}

/// A random but consistent run: 1-6 joints of random types, 0-4 segments of random kinds,
/// 0-5 steps each, 0-3 interference points per step, 0-2 errors (some tied to no segment),
/// values that include tiny negatives (the "-0.00" case).
struct RandomRun {
  certify::VerificationResult result;
  RobotModel robot;
};

RandomRun random_run(std::mt19937& rng) {
  const auto uniform_int = [&rng](int low, int high) {
    return std::uniform_int_distribution<int>(low, high)(rng);
  };
  const auto value = [&rng, &uniform_int]() {
    switch (uniform_int(0, 3)) {
      case 0: return -1e-7 * std::uniform_real_distribution<double>(0.0, 1.0)(rng);
      case 1: return std::round(std::uniform_real_distribution<double>(-200.0, 200.0)(rng));
      default: return std::uniform_real_distribution<double>(-200.0, 200.0)(rng);
    }
  };
  const auto vector = [&value](int size) {
    Eigen::VectorXd v(size);
    for (int i = 0; i < size; ++i) v[i] = value();
    return v;
  };
  RandomRun run;
  const int joints = uniform_int(1, 6);
  for (int j = 0; j < joints; ++j) {
    Joint joint;
    joint.type = uniform_int(0, 1) == 0 ? JointType::kRevolute : JointType::kPrismatic;
    run.robot.joints.push_back(joint);
  }
  run.robot.links.resize(static_cast<std::size_t>(joints) + 1);
  auto& result = run.result;
  result.tolerance = std::abs(value());
  result.mode = uniform_int(0, 1) == 0 ? certify::ResolutionMode::kThesis
                                       : certify::ResolutionMode::kCertified;
  result.path_file_label = uniform_int(0, 1) == 0 ? "PATH" : "paths/p 2.txt";
  const auto world = [&vector]() {
    WorldTarget target;
    target.position_W = vector(3);
    target.axis_W = vector(3);
    target.angle = vector(1)[0];
    return target;
  };
  int step_index = 0;
  const int segments = uniform_int(0, 4);
  for (int k = 1; k <= segments; ++k) {
    certify::SegmentRecord segment;
    segment.number = k;
    switch (uniform_int(0, 2)) {
      case 0: segment.input.spec = PtpJointSegment{vector(joints), vector(joints)}; break;
      case 1: segment.input.spec = PtpWorldSegment{world(), vector(joints)}; break;
      default: segment.input.spec = CpLineSegment{world()}; break;
    }
    segment.start_q = vector(joints);
    if (uniform_int(0, 3) > 0) segment.end_q = vector(joints);
    const int steps = uniform_int(0, 5);
    for (int s = 0; s < steps; ++s) {
      certify::StepRecord step;
      step.index = ++step_index;
      step.segment = k;
      step.q = vector(joints);
      const int points = uniform_int(0, 3);
      for (int p = 0; p < points; ++p) {
        certify::InterferencePoint point;
        point.p_W = vector(3);
        step.interference_points.push_back(point);
      }
      step.unexpanded_collides = uniform_int(0, 9) == 0;
      result.steps.push_back(step);
    }
    result.segments.push_back(segment);
  }
  const int errors = uniform_int(0, 2);
  for (int e = 0; e < errors; ++e) {
    certify::PathError error;
    error.code = uniform_int(1, 9);
    error.segment = uniform_int(0, segments + 1);
    result.errors.push_back(error);
  }
  return run;
}

// Property, fixed seeds: for any run, the JSON holds what the thesis file prints (an
// independent re-rendering from the JSON equals render_thesis_output()).
TEST(JsonReport, ThesisFileRebuiltFromJsonEqualsRenderedThesisFileOnRandomRuns) {
  for (unsigned seed = 1; seed <= 300; ++seed) {
    std::mt19937 rng(seed);
    const RandomRun run = random_run(rng);
    const json report = report_to_json(run.result, run.robot, sample_digests(), kPinnedTime);
    ASSERT_EQ(thesis_text_from_json(report), render_thesis_output(run.result, run.robot))
        << "seed " << seed;
    ASSERT_TRUE(test::check_json_structure(report, load_schema()).empty()) << "seed " << seed;
  }
}

// docs/report-schema.md documents every field of docs/report.schema.json.
void collect_property_names(const json& schema, std::set<std::string>& names) {
  if (!schema.is_object()) return;
  if (schema.contains("properties")) {
    for (const auto& [name, member] : schema["properties"].items()) {
      names.insert(name);
      collect_property_names(member, names);
    }
  }
  if (schema.contains("$defs")) {
    for (const auto& [name, member] : schema["$defs"].items()) collect_property_names(member, names);
  }
  if (schema.contains("items")) collect_property_names(schema["items"], names);
}

TEST(JsonReport, SchemaDocumentExampleSatisfiesTheSchema) {
  const std::string doc = test::read_text_file(kSourceDir + "/docs/report-schema.md");
  const std::size_t begin = doc.find("```json\n");
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = doc.find("```", begin + 8);
  const json example = json::parse(doc.substr(begin + 8, end - begin - 8));
  const auto violations = test::check_json_structure(example, load_schema());
  EXPECT_TRUE(violations.empty()) << ::testing::PrintToString(violations);
}

TEST(JsonReport, SchemaDocumentNamesEveryField) {
  std::set<std::string> names;
  collect_property_names(load_schema(), names);
  EXPECT_GE(names.size(), 60u);
  const std::string doc = test::read_text_file(kSourceDir + "/docs/report-schema.md");
  for (const std::string& name : names) {
    EXPECT_NE(doc.find("`" + name + "`"), std::string::npos) << name << " undocumented";
  }
}

}  // namespace
}  // namespace grpvss::report

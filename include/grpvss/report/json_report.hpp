#pragma once
/// \file
/// \brief The machine-readable report of a verification run (schema: docs/report-schema.md,
/// docs/report.schema.json).
///
/// It holds everything the thesis output file holds (A.3) plus the verdict, the resolution
/// mode, per-step path time, per-link motion bounds, allowances, governing terms and
/// clearances, interference points with link/hull/obstacle ids, errors, per-link minimum
/// clearances, cycle times, input file names and SHA-256 digests and the program version.
/// Values are in the units of the input files (degrees for revolute joints; the `units`
/// object says so). The report is deterministic: the same inputs give byte-identical text,
/// except for the one field `generated_at`.

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/report/input_digests.hpp"

namespace grpvss::report {

/// The value of the report's `schema` field; bumped when a field changes meaning or goes away.
inline constexpr const char* kReportSchemaId = "grpvss-report/1";

/// \brief The JSON report, `generated_at` = now (UTC, utc_timestamp_now()).
/// \throws std::logic_error if `result` is inconsistent with `robot` (joint vector sizes) or
///         holds a NaN.
nlohmann::json report_to_json(const certify::VerificationResult& result, const RobotModel& robot,
                              const InputDigests& digests);

/// Same with a given `generated_at` (any string; tests and reproducible builds pin it).
nlohmann::json report_to_json(const certify::VerificationResult& result, const RobotModel& robot,
                              const InputDigests& digests, const std::string& generated_at);

/// One element of the report's `segments` array, as report_to_json() writes it.
/// \throws std::logic_error on a NaN or a wrong-sized joint vector.
nlohmann::json report_segment_to_json(const certify::SegmentRecord& segment,
                                      const RobotModel& robot);

/// One element of the report's `steps` array, as report_to_json() writes it; `joint_types[i]`
/// is the type of joint i+1. \throws std::logic_error on a NaN or a wrong-sized joint vector.
nlohmann::json report_step_to_json(const certify::StepRecord& step,
                                   const std::vector<JointType>& joint_types);

/// The report as text: 2-space indentation, keys sorted, final newline.
std::string render_json_report(const nlohmann::json& report);

/// The current UTC time as ISO 8601, e.g. "2026-11-21T05:06:29Z".
std::string utc_timestamp_now();

}  // namespace grpvss::report

// Results: Verdict, Result (a finished run: verdict, exit code, per-step numpy arrays,
// per-link clearances, episodes, errors, segments, the JSON report) and the records it lists.
// Arrays are in library units (radians for revolute joints); the JSON report is in the input
// files' units, exactly as `grpvss verify --json` writes it.
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "grpvss/report/input_digests.hpp"
#include "grpvss/report/json_report.hpp"
#include "grpvss/report/scene_json.hpp"

namespace py = pybind11;

namespace grpvss::python {
namespace {

using certify::StepRecord;
using Steps = std::vector<StepRecord>;

const Steps& steps_of(const RunRecord& record) { return record.run.result.steps; }

// One number per step.
template <typename T, typename F>
py::array_t<T> per_step(const RunRecord& record, F value) {
  const Steps& steps = steps_of(record);
  py::array_t<T> out(static_cast<py::ssize_t>(steps.size()));
  auto view = out.template mutable_unchecked<1>();
  for (std::size_t k = 0; k < steps.size(); ++k) view(k) = value(steps[k]);
  return out;
}

// One row per step, `columns` numbers per row.
template <typename T, typename F>
py::array_t<T> per_step_rows(const RunRecord& record, py::ssize_t columns, F value) {
  const Steps& steps = steps_of(record);
  py::array_t<T> out({static_cast<py::ssize_t>(steps.size()), columns});
  auto view = out.template mutable_unchecked<2>();
  for (std::size_t k = 0; k < steps.size(); ++k) {
    for (py::ssize_t c = 0; c < columns; ++c) view(k, c) = value(steps[k], c);
  }
  return out;
}

py::ssize_t link_columns(const RunRecord& record) {
  return static_cast<py::ssize_t>(record.session->robot().model.links.size());
}

py::ssize_t joint_columns(const RunRecord& record) {
  return record.session->robot().model.joint_count();
}

int exit_code_of(certify::Verdict verdict) {
  switch (verdict) {  // src/app/exit_codes.hpp, docs/user-guide.md#exit-codes
    case certify::Verdict::kClear: return 0;
    case certify::Verdict::kCollision: return 1;
    case certify::Verdict::kWithinTolerance: return 3;
    case certify::Verdict::kError: return 4;
    case certify::Verdict::kUndecided: return 5;
  }
  return 70;
}

report::InputDigests digests_of(const RunRecord& record) {
  return {{record.session->robot().file, record.session->robot().sha256},
          {record.session->environment().file, record.session->environment().sha256},
          {record.motion_file(), record.motion_sha256()},
          record.session->robot().length_unit};
}

// The report `grpvss verify --json` writes: report_to_json() plus the scene of the cell the
// run used (report/json_report_stream.hpp gives the same bytes).
std::string json_report(const RunRecord& record, const std::optional<std::string>& generated_at) {
  const certify::VerificationResult& result = record.run.result;
  nlohmann::json json = report::report_to_json(result, record.session->robot().model,
                                               digests_of(record),
                                               generated_at.value_or(report::utc_timestamp_now()));
  json["scene"] = report::scene_to_json(result, record.session->cell());
  return report::render_json_report(json);
}

double motion_clearance_or_nan(const StepRecord& step, py::ssize_t link) {
  const auto& value = step.links[static_cast<std::size_t>(link)].motion_clearance;
  return value ? *value : std::numeric_limits<double>::quiet_NaN();
}

void bind_verdict(py::module_& module) {
  py::enum_<certify::Verdict>(module, "Verdict")
      .value("CLEAR", certify::Verdict::kClear)
      .value("COLLISION", certify::Verdict::kCollision)
      .value("WITHIN_TOLERANCE", certify::Verdict::kWithinTolerance)
      .value("UNDECIDED", certify::Verdict::kUndecided)
      .value("ERROR", certify::Verdict::kError, "the path is not qualified (errors 1-9)")
      .value("NOT_QUALIFIED", certify::Verdict::kError, "another name of ERROR (exit code 4)");
  module.def("exit_code_of", &exit_code_of, py::arg("verdict"),
             "The exit code `grpvss verify` gives for a verdict");
}

void bind_records(py::module_& module) {
  using namespace certify;
  py::class_<InterferenceEpisode>(module, "Episode")
      .def_readonly("link", &InterferenceEpisode::link)
      .def_readonly("hull", &InterferenceEpisode::hull)
      .def_readonly("obstacle", &InterferenceEpisode::obstacle)
      .def_readonly("first_step", &InterferenceEpisode::first_step)
      .def_readonly("last_step", &InterferenceEpisode::last_step)
      .def_readonly("first_segment", &InterferenceEpisode::first_segment)
      .def_readonly("last_segment", &InterferenceEpisode::last_segment)
      .def_readonly("first_time", &InterferenceEpisode::first_time)
      .def_readonly("last_time", &InterferenceEpisode::last_time)
      .def_readonly("first_collision_step", &InterferenceEpisode::first_collision_step)
      .def_readonly("last_collision_step", &InterferenceEpisode::last_collision_step)
      .def_readonly("cleared_step", &InterferenceEpisode::cleared_step)
      .def_readonly("cleared_time", &InterferenceEpisode::cleared_time);
  py::class_<PathError>(module, "PathError")
      .def_readonly("code", &PathError::code)
      .def_readonly("segment", &PathError::segment)
      .def_readonly("step", &PathError::step)
      .def_readonly("message", &PathError::message);
  py::class_<LinkClearanceSummary>(module, "LinkClearance")
      .def_readonly("link", &LinkClearanceSummary::link)
      .def_readonly("min_clearance", &LinkClearanceSummary::min_clearance)
      .def_readonly("step", &LinkClearanceSummary::step)
      .def_readonly("obstacle", &LinkClearanceSummary::obstacle)
      .def_readonly("min_motion_clearance", &LinkClearanceSummary::min_motion_clearance)
      .def_readonly("motion_step", &LinkClearanceSummary::motion_step);
  py::class_<SegmentRecord>(module, "Segment")
      .def_readonly("number", &SegmentRecord::number)
      .def_readonly("start_q", &SegmentRecord::start_q)
      .def_readonly("end_q", &SegmentRecord::end_q)
      .def_readonly("first_step", &SegmentRecord::first_step)
      .def_readonly("last_step", &SegmentRecord::last_step)
      .def_readonly("cycle_time", &SegmentRecord::cycle_time)
      .def_readonly("simulated", &SegmentRecord::simulated);
  py::class_<InterferencePoint>(module, "InterferencePoint")
      .def_readonly("link", &InterferencePoint::link)
      .def_readonly("hull", &InterferencePoint::hull)
      .def_readonly("obstacle", &InterferencePoint::obstacle)
      .def_readonly("p_W", &InterferencePoint::p_W)
      .def_property_readonly("kind", [](const InterferencePoint& p) { return geometry::to_string(p.kind); });
}

void bind_step_arrays(py::class_<RunRecord, std::shared_ptr<RunRecord>>& result) {
  result
      .def_property_readonly("step_count", [](const RunRecord& r) { return steps_of(r).size(); })
      .def_property_readonly("step_indices", [](const RunRecord& r) {
        return per_step<int>(r, [](const StepRecord& s) { return s.index; });
      })
      .def_property_readonly("step_segments", [](const RunRecord& r) {
        return per_step<int>(r, [](const StepRecord& s) { return s.segment; });
      })
      .def_property_readonly("times", [](const RunRecord& r) {
        return per_step<double>(r, [](const StepRecord& s) { return s.path_time; });
      }, "path time of each step, s")
      .def_property_readonly("configurations", [](const RunRecord& r) {
        return per_step_rows<double>(r, joint_columns(r),
                                     [](const StepRecord& s, py::ssize_t j) { return s.q[j]; });
      }, "steps x N joint values (rad / length)")
      .def_property_readonly("end_effector_positions", [](const RunRecord& r) {
        return per_step_rows<double>(
            r, 3, [](const StepRecord& s, py::ssize_t c) { return s.end_effector_W[c]; });
      })
      .def_property_readonly("clearances", [](const RunRecord& r) {
        return per_step_rows<double>(r, link_columns(r), [](const StepRecord& s, py::ssize_t l) {
          return s.links[static_cast<std::size_t>(l)].clearance;
        });
      }, "steps x (N+1): certified lower bound of each link's distance at each step")
      .def_property_readonly("motion_clearances", [](const RunRecord& r) {
        return per_step_rows<double>(r, link_columns(r), &motion_clearance_or_nan);
      }, "steps x (N+1): clearance proven along the transition into each step (NaN: none)")
      .def_property_readonly("nearest_obstacles", [](const RunRecord& r) {
        return per_step_rows<int>(r, link_columns(r), [](const StepRecord& s, py::ssize_t l) {
          return s.links[static_cast<std::size_t>(l)].nearest_obstacle;
        });
      })
      .def_property_readonly("expanded_interferes", [](const RunRecord& r) {
        return per_step<bool>(r, [](const StepRecord& s) { return s.expanded_interferes; });
      })
      .def_property_readonly("unexpanded_collides", [](const RunRecord& r) {
        return per_step<bool>(r, [](const StepRecord& s) { return s.unexpanded_collides; });
      })
      .def("interference_points", [](const RunRecord& r, int index) {
        for (const StepRecord& s : steps_of(r)) {
          if (s.index == index) return s.interference_points;
        }
        throw py::index_error("no step " + std::to_string(index));
      }, py::arg("step"), "the interference points of step `step` (1-based)");
}

}  // namespace

void bind_results(py::module_& module) {
  bind_verdict(module);
  bind_records(module);
  py::class_<RunRecord, std::shared_ptr<RunRecord>> result(module, "Result",
                                                           "One finished verification");
  result
      .def_property_readonly("verdict", [](const RunRecord& r) { return r.run.result.verdict; })
      .def_property_readonly("exit_code",
                             [](const RunRecord& r) { return exit_code_of(r.run.result.verdict); })
      .def_property_readonly("mode", [](const RunRecord& r) { return certify::to_string(r.run.result.mode); })
      .def_property_readonly("tolerance", [](const RunRecord& r) { return r.run.result.tolerance; })
      .def_property_readonly("ik", [](const RunRecord& r) { return r.ik_name; })
      .def_property_readonly("path", [](const RunRecord& r) { return r.path; },
                             "The Path verified (None for a trajectory)")
      .def_property_readonly("trajectory", [](const RunRecord& r) { return r.trajectory; },
                             "The JointTrajectory verified (None for a path)")
      .def_property_readonly("program", [](const RunRecord& r) { return r.program; },
                             "The RobotProgram verified (None for a path or a trajectory)")
      .def_property_readonly("warnings", [](const RunRecord& r) {
        return r.program ? program_warnings(*r.program) : py::list();
      }, "The program reader's warnings as (file, line, text) ([] for a path or a trajectory)")
      .def_property_readonly("motion_model",
                             [](const RunRecord& r) { return r.run.result.motion_model; },
                             "'joint trajectory T, cubic Hermite interpolation, ...' ('' for a path)")
      .def_property_readonly("total_cycle_time",
                             [](const RunRecord& r) { return r.run.result.total_cycle_time; })
      .def_property_readonly("collision_step",
                             [](const RunRecord& r) { return r.run.result.collision_step; })
      .def_property_readonly("start_configuration", [](const RunRecord& r) -> std::optional<Eigen::VectorXd> {
        if (!r.run.result.start) return std::nullopt;
        return r.run.result.start->q;
      })
      .def_property_readonly("segments", [](const RunRecord& r) { return r.run.result.segments; })
      .def_property_readonly("errors", [](const RunRecord& r) { return r.run.result.errors; })
      .def_property_readonly("link_clearances",
                             [](const RunRecord& r) { return r.run.result.link_clearances; })
      .def_property_readonly("episodes",
                             [](const RunRecord& r) { return r.run.result.interference_episodes; })
      .def_property_readonly("certificate", &certificate_of,
                             "The certificate (None in thesis mode: it proves nothing)")
      .def("json_report", &json_report, py::arg("generated_at") = py::none(),
           "The JSON report `grpvss verify --json` writes (docs/report-schema.md)");
  bind_step_arrays(result);
}

}  // namespace grpvss::python

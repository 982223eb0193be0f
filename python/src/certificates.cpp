// Certificates: Result.certificate (to_json(), save()) and check_certificate(), which mirrors
// `grpvss check-certificate`: the checker stage re-verifies the certificate from the inputs
// alone through the same certify::check_certificate_file() as the CLI, with the GIL released.
#include <memory>
#include <optional>
#include <string>

#include <fmt/core.h>
#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "grpvss/batch/robot_program_input.hpp"
#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/checker/certificate_file_check.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/profile_table_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/report/atomic_output.hpp"
#include "grpvss/report/certificate_output.hpp"

namespace py = pybind11;

namespace grpvss::python {
namespace {

/// A run's certificate (certified mode only).
struct CertificateView {
  std::shared_ptr<RunRecord> record;

  std::string text() const {
    const RunRecord& r = *record;
    nlohmann::json inputs = {{"robot", r.session->robot().sha256},
                             {"environment", r.session->environment().sha256},
                             {"ik", r.ik_name}};
    if (r.program) {  // as `grpvss verify --program` records it
      for (const auto& [name, value] : batch::program_certificate_inputs(r.program->program)) {
        inputs[name] = value;
      }
    } else {
      inputs[r.motion_key()] = r.motion_sha256();
    }
    return report::render_certificate(r.run.certificate, inputs);
  }
};

/// The inputs a certificate is checked against: a path, or a joint trajectory (`trajectory`
/// set; then no timing and no profile table: the trajectory is the motion).
struct CheckInputs {
  std::shared_ptr<LoadedRobot> robot;
  std::shared_ptr<LoadedEnvironment> environment;
  std::shared_ptr<LoadedPath> path;
  std::shared_ptr<LoadedTrajectory> trajectory;
  std::shared_ptr<LoadedProgram> program;  ///< a robot program (synchronized PTP)
  std::optional<std::string> timing;  ///< unset: the certificate's
  std::optional<std::string> ik;      ///< unset: "auto"
  std::string profile_table;
};

// --timing and --ik name what the caller expects: a certificate made otherwise is refused
// (as `grpvss check-certificate` refuses it).
void refuse_other_motion(const CheckInputs& inputs, const certify::Certificate& header,
                         const std::string& ik_name) {
  if (inputs.timing && *inputs.timing != motion::to_string(header.timing)) {
    throw InputError("timing", 0,
                     fmt::format("the timing the certificate was made with ({}); it certifies "
                                 "nothing about {} timing",
                                 motion::to_string(header.timing), *inputs.timing),
                     *inputs.timing);
  }
  const auto named = header.inputs.find("ik");
  if (named == header.inputs.end() || named->second == ik_name) return;
  throw InputError("ik", 0, fmt::format("the IK the certificate was made with ('{}')", named->second),
                   fmt::format("'{}' ({})", inputs.ik.value_or("auto"), ik_name));
}

// The motion the checker replays and its digest's key: the path program, or the trajectory.
const PathProgram& motion_of(const CheckInputs& inputs, certify::CheckOptions& options) {
  static const PathProgram no_program;
  if (inputs.program) {
    if (inputs.program->robot != inputs.robot) {
      throw std::invalid_argument("the program was loaded for another robot");
    }
    options.input_digests["program"] = inputs.program->program.digest;
    return inputs.program->program.path.path;
  }
  if (inputs.trajectory) {
    if (inputs.trajectory->robot != inputs.robot) {
      throw std::invalid_argument("the trajectory was loaded for another robot");
    }
    options.joint_trajectory = inputs.trajectory->motion;
    options.input_digests["trajectory"] = inputs.trajectory->sha256;
    return no_program;
  }
  if (inputs.path->robot != inputs.robot) {
    throw std::invalid_argument("the path was loaded for another robot");
  }
  options.input_digests["path"] = inputs.path->sha256;
  return inputs.path->program;
}

certify::CheckReport check_file(const CheckInputs& inputs, const std::string& certificate_file) {
  const RobotModel& robot = inputs.robot->model;
  certify::CheckOptions options;
  const PathProgram& program = motion_of(inputs, options);
  if (!inputs.profile_table.empty()) {
    options.profile_table = std::make_shared<const motion::ProfileTable>(
        io::read_profile_table_file(inputs.profile_table));
  }
  const kinematics::IkChoice choice = parse_ik_choice(inputs.ik.value_or("auto"));
  py::gil_scoped_release release;
  const auto ik = motion::select_ik(choice, robot, inputs.robot->file);
  const motion::KinematicsAccess kinematics = motion::make_kinematics_access(robot, ik);
  options.input_digests["robot"] = inputs.robot->sha256;
  options.input_digests["environment"] = inputs.environment->sha256;
  return certify::check_certificate_file(
      certificate_file, robot, inputs.environment->model, program, kinematics,
      options, [&](const certify::Certificate& header) {
        refuse_other_motion(inputs, header, ik->name());
      });
}

void bind_certificate(py::module_& module) {
  py::class_<CertificateView>(module, "Certificate",
                              "The certificate of a certified run (docs/certificate.md)")
      .def_property_readonly("claim",
                             [](const CertificateView& c) { return c.record->run.certificate.claim; })
      .def_property_readonly("segment_count", [](const CertificateView& c) {
        return c.record->run.certificate.segments.size();
      })
      .def("to_json", &CertificateView::text,
           "The certificate file's text, as `grpvss verify --certificate` writes it")
      .def("save", [](const CertificateView& c, const std::string& file, bool force) {
        report::write_file_atomically(file, c.text(), force);
      }, py::arg("file"), py::arg("force") = false,
         "Writes the file atomically; an existing file is refused unless force");
}

void bind_check_report(py::module_& module) {
  using certify::CheckReport;
  py::class_<certify::CheckedMotionClearance>(module, "CheckedMotionClearance")
      .def_readonly("link", &certify::CheckedMotionClearance::link)
      .def_readonly("lower_bound", &certify::CheckedMotionClearance::lower_bound)
      .def_readonly("step", &certify::CheckedMotionClearance::step);
  py::class_<CheckReport>(module, "CheckReport", "The checker's decision on a certificate")
      .def_readonly("accepted", &CheckReport::accepted)
      .def_readonly("claim", &CheckReport::claim)
      .def_readonly("failures", &CheckReport::failures)
      .def_property_readonly("messages", [](const CheckReport& r) { return r.failures; })
      .def_readonly("inequalities_checked", &CheckReport::inequalities_checked)
      .def_property_readonly("timing", [](const CheckReport& r) { return motion::to_string(r.timing); })
      .def_readonly("cp_speed", &CheckReport::cp_speed)
      .def_readonly("ik", &CheckReport::ik)
      .def_readonly("motion_clearances", &CheckReport::motion_clearances)
      .def_property_readonly("exit_code", [](const CheckReport& r) { return r.accepted ? 0 : 1; });
}

}  // namespace

py::object certificate_of(const std::shared_ptr<RunRecord>& record) {
  if (record->run.result.mode != certify::ResolutionMode::kCertified) return py::none();
  return py::cast(CertificateView{record});
}

void bind_certificates(py::module_& module) {
  bind_certificate(module);
  bind_check_report(module);
  module.def(
      "_check_certificate_file",
      [](std::shared_ptr<LoadedRobot> robot, std::shared_ptr<LoadedEnvironment> environment,
         std::shared_ptr<LoadedPath> path, const std::string& certificate,
         std::optional<std::string> timing, std::optional<std::string> ik,
         const std::string& profile_table) {
        return check_file({robot, environment, path, nullptr, nullptr, timing, ik, profile_table},
                          certificate);
      },
      py::arg("robot"), py::arg("environment"), py::arg("path"), py::arg("certificate"),
      py::arg("timing") = py::none(), py::arg("ik") = py::none(), py::arg("profile_table") = "");
  module.def(
      "_check_trajectory_certificate_file",
      [](std::shared_ptr<LoadedRobot> robot, std::shared_ptr<LoadedEnvironment> environment,
         std::shared_ptr<LoadedTrajectory> trajectory, const std::string& certificate,
         std::optional<std::string> ik) {
        return check_file({robot, environment, nullptr, trajectory, nullptr, std::nullopt, ik, ""},
                          certificate);
      },
      py::arg("robot"), py::arg("environment"), py::arg("trajectory"), py::arg("certificate"),
      py::arg("ik") = py::none());
  // The program was resolved with its IK (RobotProgram.ik): the check uses the same.
  module.def(
      "_check_program_certificate_file",
      [](std::shared_ptr<LoadedRobot> robot, std::shared_ptr<LoadedEnvironment> environment,
         std::shared_ptr<LoadedProgram> program, const std::string& certificate) {
        return check_file({robot, environment, nullptr, nullptr, program, std::nullopt, program->ik,
                           ""},
                          certificate);
      },
      py::arg("robot"), py::arg("environment"), py::arg("program"), py::arg("certificate"));
}

}  // namespace grpvss::python

// Verification: Session (the prepared cell: RobotCell built once for a robot, environment,
// tolerance, mode and offset shape) and Session.verify(path, ...), which runs certify::verify
// with the GIL released, so Python threads verify in parallel against one shared cell.
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "grpvss/batch/motion_statement.hpp"
#include "grpvss/batch/verify_options.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/profile_table_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/profile_table.hpp"
#include "grpvss/motion/trajectory.hpp"

namespace py = pybind11;

namespace grpvss::python {
namespace {

std::string file_label(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// How many verifications run now (GIL released) and the most at once: lets a test show that
// Python threads overlap without timing anything. With a rendezvous of n, a verification
// waits (at most 30 s) until n are active before it starts: two threads can only meet there
// if the GIL is released.
struct ActivityMonitor {
  std::mutex mutex;
  std::condition_variable changed;
  int active = 0;
  int peak = 0;
  int rendezvous = 0;

  void enter() {
    std::unique_lock<std::mutex> lock(mutex);
    ++active;
    if (active > peak) peak = active;
    changed.notify_all();
    if (rendezvous > 1) {
      changed.wait_for(lock, std::chrono::seconds(30), [this] { return active >= rendezvous; });
    }
  }
  void leave() {
    std::lock_guard<std::mutex> lock(mutex);
    --active;
    changed.notify_all();
  }
};

ActivityMonitor& monitor() {
  static ActivityMonitor instance;
  return instance;
}

struct ActiveVerification {
  ActiveVerification() { monitor().enter(); }
  ~ActiveVerification() { monitor().leave(); }
  ActiveVerification(const ActiveVerification&) = delete;
  ActiveVerification& operator=(const ActiveVerification&) = delete;
};

// Verifies the record's path or trajectory against the session's cell, as `grpvss verify`
// does, with the GIL released.
std::shared_ptr<RunRecord> verify_motion(const std::shared_ptr<const Session>& session,
                                         std::shared_ptr<RunRecord> record,
                                         const RunOptions& options) {
  const LoadedRobot* motion_robot = record->path         ? record->path->robot.get()
                                    : record->trajectory ? record->trajectory->robot.get()
                                                         : record->program->robot.get();
  if (motion_robot != &session->robot()) {
    throw std::invalid_argument(std::string("the ") + record->motion_key() +
                                " was loaded for another robot than the session's");
  }
  if (record->trajectory && session->request().mode == certify::ResolutionMode::kThesis) {
    throw InputError("mode", 0,
                     "no mode thesis with a trajectory (the thesis step rule is defined for PTP "
                     "and CP segments)",
                     "thesis");
  }
  certify::SetupRequest request = session->request();
  request.motion = parse_motion(options);
  const auto claim = certify::clear_claim_from_string(options.claim);
  if (!claim) throw InputError("claim", 0, "motion or steps", "'" + options.claim + "'");
  request.claim = *claim;
  request.path_label = file_label(record->motion_file());
  if (record->program) request.motion.start = options.start;
  certify::VerificationSetup setup = certify::resolve_setup(request);
  const kinematics::IkChoice ik_choice = parse_ik_choice(options.ik);
  record->session = session;
  {
    py::gil_scoped_release release;
    ActiveVerification active;
    const RobotModel& robot = session->robot().model;
    const auto ik = motion::select_ik(ik_choice, robot, session->robot().file);
    record->ik_name = ik->name();
    const motion::KinematicsAccess kinematics = motion::make_kinematics_access(robot, ik);
    if (!record->trajectory) {  // a trajectory states its own (certify::verify)
      setup.run.motion_model = batch::describe_path_motion(setup.run, request.path_label, ik->name());
    }
    if (record->trajectory) {
      record->run = certify::verify(
          session->cell(), motion::Trajectory::from_joint_motion(robot, record->trajectory->motion),
          kinematics, setup.run);
    } else {
      const PathProgram& program =
          record->path ? record->path->program : record->program->program.path.path;
      record->run = certify::verify(session->cell(), program, kinematics, setup.run);
    }
    // As `grpvss verify --program` states it.
    if (record->program) record->run.result.motion_model = record->program->program.description;
  }
  return record;
}

}  // namespace

certify::ResolutionMode parse_mode(const std::string& text) {
  const auto mode = certify::resolution_mode_from_string(text);
  if (!mode) throw InputError("mode", 0, "certified or thesis", "'" + text + "'");
  return *mode;
}

certify::SetupRequest base_request(double tolerance, const std::string& mode,
                                   const std::string& offset) {
  if (!std::isfinite(tolerance) || tolerance <= 0.0) {
    throw InputError("tolerance", 0, "a finite number > 0", std::to_string(tolerance));
  }
  certify::SetupRequest request;
  request.tolerance = tolerance;
  request.mode = parse_mode(mode);
  if (offset != "auto") {
    request.offset_shape = geometry::offset_shape_from_string(offset);
    if (!request.offset_shape) {
      throw InputError("offset", 0, "auto, cube or rhombicuboctahedron", "'" + offset + "'");
    }
  }
  return request;
}

motion::MotionModel parse_motion(const RunOptions& options) {
  motion::MotionModel model;
  const auto timing = motion::ptp_timing_from_string(options.timing);
  if (!timing) throw InputError("timing", 0, "independent or synchronized", "'" + options.timing + "'");
  model.timing = *timing;
  if (!std::isfinite(options.cp_speed) || options.cp_speed <= 0.0) {
    throw InputError("cp_speed", 0, "a finite number > 0", std::to_string(options.cp_speed));
  }
  model.cp_speed = options.cp_speed;
  if (!options.profile_table.empty()) {
    model.table = std::make_shared<const motion::ProfileTable>(
        io::read_profile_table_file(options.profile_table));
  }
  return model;
}

// The words of `grpvss verify --ik` (batch/verify_options.hpp), errors named after the keyword.
kinematics::IkChoice parse_ik_choice(const std::string& text) {
  try {
    return batch::parse_ik_choice(text);
  } catch (const InputError& error) {
    throw InputError("ik", 0, error.expected(), error.found());
  }
}

Session::Session(std::shared_ptr<LoadedRobot> robot,
                 std::shared_ptr<LoadedEnvironment> environment, double tolerance,
                 const std::string& mode, const std::string& offset)
    : robot_(std::move(robot)),
      environment_(std::move(environment)),
      request_(base_request(tolerance, mode, offset)) {
  const certify::CellSettings settings = certify::resolve_setup(request_).cell;
  py::gil_scoped_release release;
  cell_ = std::make_unique<const certify::RobotCell>(robot_->model, environment_->model, settings);
}

void bind_verification(py::module_& module) {
  SessionClass session(
      module, "Session",
      "The prepared cell for one robot, environment, tolerance, mode and offset: built once, "
      "then any number of paths verified against it (from any thread)");
  session
      .def(py::init<std::shared_ptr<LoadedRobot>, std::shared_ptr<LoadedEnvironment>, double,
                    const std::string&, const std::string&>(),
           py::arg("robot"), py::arg("environment"), py::arg("tolerance"),
           py::arg("mode") = "certified", py::arg("offset") = "auto")
      .def_property_readonly("robot", &Session::robot_pointer)
      .def_property_readonly("environment", &Session::environment_pointer)
      .def("_verify",
           [](const std::shared_ptr<Session>& session, const std::shared_ptr<LoadedPath>& path,
              const std::string& timing, double cp_speed, const std::string& ik,
              const std::string& profile_table, const std::string& claim) {
             auto record = std::make_shared<RunRecord>();
             record->path = path;
             return verify_motion(session, record,
                                  RunOptions{timing, cp_speed, ik, profile_table, std::nullopt, claim});
           },
           py::arg("path"), py::arg("timing"), py::arg("cp_speed"), py::arg("ik"),
           py::arg("profile_table"), py::arg("claim") = "motion")
      .def("_verify_trajectory",
           [](const std::shared_ptr<Session>& session,
              const std::shared_ptr<LoadedTrajectory>& trajectory, const std::string& timing,
              double cp_speed, const std::string& ik, const std::string& claim) {
             auto record = std::make_shared<RunRecord>();
             record->trajectory = trajectory;
             return verify_motion(session, record,
                                  RunOptions{timing, cp_speed, ik, "", std::nullopt, claim});
           },
           py::arg("trajectory"), py::arg("timing"), py::arg("cp_speed"), py::arg("ik"),
           py::arg("claim") = "motion")
      .def("_verify_program",
           [](const std::shared_ptr<Session>& session, const std::shared_ptr<LoadedProgram>& program,
              double cp_speed, const std::string& claim) {
             auto record = std::make_shared<RunRecord>();
             record->program = program;
             RunOptions options{"synchronized", cp_speed, program->ik, "", program->start, claim};
             return verify_motion(session, record, options);
           },
           py::arg("program"), py::arg("cp_speed"), py::arg("claim") = "motion")
      .def_property_readonly("tolerance", [](const Session& s) { return s.cell().tolerance(); })
      .def_property_readonly("mode",
                             [](const Session& s) { return certify::to_string(s.request().mode); })
      .def_property_readonly("offset", [](const Session& s) {
        return geometry::to_string(s.cell().offset_shape());
      });
  bind_configuration_check(module, session);

  module.def("_activity", [] {
    std::lock_guard<std::mutex> lock(monitor().mutex);
    return py::make_tuple(monitor().active, monitor().peak);
  }, "(active, peak) verifications with the GIL released (for tests)");
  module.def("_reset_activity", [](int rendezvous) {
    std::lock_guard<std::mutex> lock(monitor().mutex);
    monitor().peak = monitor().active;
    monitor().rendezvous = rendezvous;
  }, py::arg("rendezvous") = 0,
     "Resets the peak; with rendezvous n > 1 each verification waits (<= 30 s) for n active");
}

}  // namespace grpvss::python

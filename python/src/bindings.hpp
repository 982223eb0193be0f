#pragma once
// The Python module `_grpvss` (wrapped by the pure-Python package `grpvss`, python/grpvss/):
// the types the binding files share and the functions that register each topic.
// Every verification goes through the library's public API exactly as `grpvss verify` does
// (io readers, resolve_setup, RobotCell built once, certify::verify); docs/python.md.
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Geometry>
#include <pybind11/pybind11.h>

#include "grpvss/batch/robot_program_input.hpp"

#include "grpvss/kinematics/inverse_kinematics.hpp"

#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/evidence/setup.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/joint_trajectory_motion.hpp"

namespace grpvss::python {

/// A robot as loaded (a thesis robot file, or a cell file's robot), with the file name and
/// digest the reports record.
struct LoadedRobot {
  std::string file;    ///< as the caller named it (the cell file for a cell's robot)
  std::string sha256;  ///< of the bytes at load time
  RobotModel model;
  bool from_cell = false;
  /// Model units per unit of a thesis path file's lengths (a URDF robot in a cell in mm: 0.001).
  double path_length_scale = 1.0;
  /// The model's length unit a cell states ("m", "mm", "in"), the report's `units.length`;
  /// empty for thesis files (cell::ModelInputs::model_unit).
  std::string length_unit;
  /// A cell's `base` (X_WR) and `tool` (X_FE), m: where a robot program's targets are placed.
  Eigen::Isometry3d X_WR = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d X_FE = Eigen::Isometry3d::Identity();
};

struct LoadedEnvironment {
  std::string file;
  std::string sha256;
  Environment model;
};

/// A path file, read for one robot (which fixes N and the joint types).
struct LoadedPath {
  std::string file;
  std::string sha256;
  PathProgram program;
  std::shared_ptr<LoadedRobot> robot;
};

/// A planner's joint trajectory, matched to one robot's joints and checked against its limits
/// (batch::joint_motion_of, the loader `grpvss verify --trajectory` uses): read from a file, or
/// given as arrays, which are verified as their canonical CSV text (io::render_trajectory_csv).
struct LoadedTrajectory {
  std::string file;    ///< the file read; for arrays, the label naming them in reports and errors
  std::string sha256;  ///< of the file's bytes, or of `csv` for arrays
  std::string csv;     ///< arrays only: the canonical CSV text (empty for a file)
  std::shared_ptr<const motion::JointTrajectoryMotion> motion;
  std::shared_ptr<LoadedRobot> robot;
};

/// A robot program resolved against one robot by batch::load_robot_program (the loader
/// `grpvss verify --program` uses) with the IK `ik` names, which its runs and checks use too.
struct LoadedProgram {
  std::string file;
  std::string sha256;  ///< of the program file itself (the JSON report's inputs.path)
  std::string ik = "auto";
  std::optional<Eigen::VectorXd> start;  ///< rad; unset: the robot's home
  batch::LoadedRobotProgram program;
  std::shared_ptr<LoadedRobot> robot;
};

/// The per-run choices that do not change the cell (`grpvss verify`'s --timing, --cp-speed,
/// --ik, --profile-table, --claim).
struct RunOptions {
  std::string timing = "independent";
  double cp_speed = 1.0;
  std::string ik = "auto";
  std::string profile_table;  ///< empty: the ideal trapezoids
  std::optional<Eigen::VectorXd> start;  ///< a robot program's start (rad); unset: home
  std::string claim = "motion";  ///< --claim: motion | steps (docs/verification.md#claim)
};

/// \brief The prepared set-up (a RobotCell: exact hulls and tolerance offsets) for one robot,
/// environment, tolerance, mode and offset shape: built once, then shared read-only by every
/// verification against it, from any number of threads.
class Session {
 public:
  Session(std::shared_ptr<LoadedRobot> robot,
          std::shared_ptr<LoadedEnvironment> environment, double tolerance,
          const std::string& mode, const std::string& offset);

  const LoadedRobot& robot() const { return *robot_; }
  const LoadedEnvironment& environment() const { return *environment_; }
  std::shared_ptr<LoadedRobot> robot_pointer() const { return robot_; }
  std::shared_ptr<LoadedEnvironment> environment_pointer() const { return environment_; }
  const certify::RobotCell& cell() const { return *cell_; }
  const certify::SetupRequest& request() const { return request_; }

 private:
  std::shared_ptr<LoadedRobot> robot_;
  std::shared_ptr<LoadedEnvironment> environment_;
  certify::SetupRequest request_;  ///< tolerance, mode, offset; the motion is per run
  std::unique_ptr<const certify::RobotCell> cell_;
};

/// One finished verification: what it ran on (kept alive) and what it produced.
struct RunRecord {
  std::shared_ptr<const Session> session;
  std::shared_ptr<LoadedPath> path;              ///< null for a trajectory's run
  std::shared_ptr<LoadedTrajectory> trajectory;  ///< null for a path's run
  std::shared_ptr<LoadedProgram> program;        ///< set for a robot program's run
  /// The motion's file (or label) and digest, and the certificate's key for it.
  const std::string& motion_file() const {
    return path ? path->file : trajectory ? trajectory->file : program->file;
  }
  const std::string& motion_sha256() const {
    return path ? path->sha256 : trajectory ? trajectory->sha256 : program->sha256;
  }
  const char* motion_key() const { return path ? "path" : trajectory ? "trajectory" : "program"; }
  std::string ik_name;
  certify::VerificationRun run;
};

/// Reads a `verify`-style word ("certified", "cube", ...) or throws InputError naming `option`.
certify::ResolutionMode parse_mode(const std::string& text);
certify::SetupRequest base_request(double tolerance, const std::string& mode,
                                   const std::string& offset);
motion::MotionModel parse_motion(const RunOptions& options);
kinematics::IkChoice parse_ik_choice(const std::string& text);

/// The run's certificate object, None in thesis mode (it proves nothing).
pybind11::object certificate_of(const std::shared_ptr<RunRecord>& record);

void bind_errors(pybind11::module_& module);
using RobotClass = pybind11::class_<LoadedRobot, std::shared_ptr<LoadedRobot>>;

/// Registers Robot (returned, for bind_kinematics), Environment, Path and the loaders.
RobotClass bind_model_loading(pybind11::module_& module);
void bind_kinematics(RobotClass& robot);
void bind_verification(pybind11::module_& module);
using SessionClass = pybind11::class_<Session, std::shared_ptr<Session>>;
/// Session._check_configurations and the classes of its answer.
void bind_configuration_check(pybind11::module_& module, SessionClass& session);
void bind_results(pybind11::module_& module);
void bind_certificates(pybind11::module_& module);
void bind_trajectories(pybind11::module_& module);
void bind_programs(pybind11::module_& module);
/// A program's reader warnings as a list of (file, line, text).
pybind11::list program_warnings(const LoadedProgram& program);

}  // namespace grpvss::python

#pragma once
/// \file
/// \brief A robot program (URScript, KUKA KRL, ABB RAPID) made into the motion a verification
/// certifies: the one loader `grpvss verify|trajectory|check-certificate --program`, batch
/// manifests' `program` jobs and the Python module share
/// (docs/robot-programs.md#verifying-a-program).

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "grpvss/cell/model_inputs.hpp"
#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/model/robot_program.hpp"
#include "grpvss/motion/program_path.hpp"

namespace grpvss::batch {

/// \brief The program as the motion verified, and what the reports record about it.
struct LoadedRobotProgram {
  std::string file;          ///< the program as named by the caller
  motion::ProgramPath path;  ///< its `path` is what the verifier and the checker plan
  std::string digest;        ///< SHA-256 over every file the program read, in order
  std::string description;   ///< describe_program_motion(): the run's motion model
  /// The reader's warnings (lines it did not read), as data: the CLI prints them.
  std::vector<ProgramWarning> warnings;
};

/// \brief Where the program's robot stands: the cell's base X_WR and tool X_FE (m).
struct ProgramPlacement {
  Eigen::Isometry3d X_WR = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d X_FE = Eigen::Isometry3d::Identity();
};

/// \brief Reads `file` (io::read_robot_program) and resolves it against `robot` placed by
/// `placement`, from `start` (rad), else the robot's home.
/// \throws InputError(file, 0, ...) for a robot without joint names (programs need a URDF
/// robot in a cell: their lengths are metres), InputError(file, line, ...) for a refused or
/// unreachable motion or a defect of the file.
LoadedRobotProgram load_robot_program(const std::string& file, const RobotModel& robot,
                                      const ProgramPlacement& placement,
                                      const kinematics::InverseKinematics& ik,
                                      const std::optional<Eigen::VectorXd>& start = std::nullopt);

/// As above, placed by the model's cell (its X_WR and X_FE).
LoadedRobotProgram load_robot_program(const std::string& file, const cell::ModelInputs& model,
                                      const kinematics::InverseKinematics& ik,
                                      const std::optional<Eigen::VectorXd>& start = std::nullopt);

/// The certificate's "inputs" entries of a program: its digest, language and joint targets.
std::map<std::string, std::string> program_certificate_inputs(const LoadedRobotProgram& program);

}  // namespace grpvss::batch

#pragma once
/// \file
/// \brief The UR5e self-collision cells' inputs (tests/data/cells/ur5e-self*.yaml and a path
/// file), their certified run and the checker against them; and a search of a check report's
/// failures. Shared by the self-collision and revolution-route tests.

#include <string>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/checker/certificate_checker.hpp"

namespace grpvss::test {

struct Ur5eSelfInputs {
  cell::LoadedCell cell;
  PathProgram program;
  motion::KinematicsAccess kinematics;
};

/// tests/data/cells/<cell_file> loaded.
cell::LoadedCell load_test_cell(const std::string& cell_file);

/// The certified cell of `loaded` at the cell's own tolerance (it keeps pointers into `loaded`).
certify::RobotCell certified_cell(const cell::LoadedCell& loaded);

/// Both files name files in tests/data/cells/.
Ur5eSelfInputs load_ur5e_self(const std::string& cell_file, const std::string& path_file);

/// The certified run with the cell's tolerance and the default setup.
certify::VerificationRun verify_ur5e_self(const Ur5eSelfInputs& inputs);

/// check_certificate of `certificate` against the inputs.
certify::CheckReport check_ur5e_self(const Ur5eSelfInputs& inputs,
                                     const certify::Certificate& certificate);

/// Whether some failure of the report contains `text`.
bool has_failure(const certify::CheckReport& report, const std::string& text);

}  // namespace grpvss::test

#include "support/ur5e_self_run.hpp"

#include <algorithm>

#include "grpvss/io/path_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"

namespace grpvss::test {

cell::LoadedCell load_test_cell(const std::string& cell_file) {
  return cell::load_cell(std::string(GRPVSS_SOURCE_DIR) + "/tests/data/cells/" + cell_file);
}

certify::RobotCell certified_cell(const cell::LoadedCell& loaded) {
  certify::CellSettings settings;
  settings.tolerance = loaded.tolerance;
  return certify::RobotCell(loaded.robot, loaded.environment, settings);
}

Ur5eSelfInputs load_ur5e_self(const std::string& cell_file, const std::string& path_file) {
  const std::string cells = std::string(GRPVSS_SOURCE_DIR) + "/tests/data/cells/";
  Ur5eSelfInputs inputs{cell::load_cell(cells + cell_file), {}, {}};
  inputs.program = io::read_path_file(cells + path_file, inputs.cell.robot);
  inputs.kinematics =
      motion::make_kinematics_access(inputs.cell.robot, motion::select_ik({}, inputs.cell.robot, "ur5e"));
  return inputs;
}

certify::VerificationRun verify_ur5e_self(const Ur5eSelfInputs& inputs) {
  certify::SetupRequest request;
  request.tolerance = inputs.cell.tolerance;
  return certify::verify(inputs.cell.robot, inputs.cell.environment, inputs.program,
                         inputs.kinematics, certify::resolve_setup(request));
}

certify::CheckReport check_ur5e_self(const Ur5eSelfInputs& inputs,
                                     const certify::Certificate& certificate) {
  return certify::check_certificate(inputs.cell.robot, inputs.cell.environment, inputs.program,
                                    inputs.kinematics, certificate);
}

bool has_failure(const certify::CheckReport& report, const std::string& text) {
  return std::any_of(report.failures.begin(), report.failures.end(),
                     [&](const std::string& f) { return f.find(text) != std::string::npos; });
}

}  // namespace grpvss::test

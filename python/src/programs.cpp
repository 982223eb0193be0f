// Robot programs (docs/python.md#robot-programs): a URScript, KRL or RAPID program resolved
// against a cell's robot by the loader `grpvss verify --program` and batch `program` jobs use
// (batch::load_robot_program), with the reader's warnings as (file, line, text).
#include <memory>
#include <optional>
#include <string>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "grpvss/batch/robot_program_input.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/report/input_digests.hpp"

namespace py = pybind11;

namespace grpvss::python {
namespace {

std::shared_ptr<LoadedProgram> load_program(const std::string& file,
                                            const std::shared_ptr<LoadedRobot>& robot,
                                            const std::string& ik,
                                            const std::optional<Eigen::VectorXd>& start) {
  auto loaded = std::make_shared<LoadedProgram>();
  loaded->file = file;
  loaded->ik = ik;
  loaded->start = start;
  loaded->robot = robot;
  const kinematics::IkChoice choice = parse_ik_choice(ik);
  py::gil_scoped_release release;
  const auto solver = motion::select_ik(choice, robot->model, robot->file);
  loaded->program = batch::load_robot_program(
      file, robot->model, batch::ProgramPlacement{robot->X_WR, robot->X_FE}, *solver, start);
  loaded->sha256 = report::sha256_hex_of_file(file);
  return loaded;
}

}  // namespace

py::list program_warnings(const LoadedProgram& program) {
  py::list warnings;
  for (const ProgramWarning& w : program.program.warnings) {
    warnings.append(py::make_tuple(w.file, w.line, w.text));
  }
  return warnings;
}

void bind_programs(py::module_& module) {
  using P = LoadedProgram;
  py::class_<P, std::shared_ptr<P>>(
      module, "RobotProgram",
      "A robot program resolved into synchronized PTP motions "
      "(docs/robot-programs.md#verifying-a-program)")
      .def_property_readonly("file", [](const P& p) { return p.file; })
      .def_property_readonly("sha256", [](const P& p) { return p.sha256; },
                             "Of the program file itself")
      .def_property_readonly("digest", [](const P& p) { return p.program.digest; },
                             "Over every file the program read (the certificate's inputs.program)")
      .def_property_readonly("robot", [](const P& p) { return p.robot; })
      .def_property_readonly("ik", [](const P& p) { return p.ik; })
      .def_property_readonly("language",
                             [](const P& p) { return motion::to_string(p.program.path.language); })
      .def_property_readonly("motion_model", [](const P& p) { return p.program.description; })
      .def_property_readonly("warnings", &program_warnings,
                             "The reader's warnings as (file, line, text)")
      .def_property_readonly("targets", [](const P& p) {
        py::list targets;
        for (const motion::ResolvedMotion& m : p.program.path.motions) {
          targets.append(py::make_tuple(m.file, m.line, m.cartesian, m.q));
        }
        return targets;
      }, "(file, line, cartesian, q) per motion, q in rad")
      .def("__repr__", [](const P& p) {
        return "<grpvss.RobotProgram " + p.file + ": " +
               std::to_string(p.program.path.motions.size()) + " motions>";
      });
  module.def("_load_program", &load_program, py::arg("file"), py::arg("robot"), py::arg("ik"),
             py::arg("start"));
}

}  // namespace grpvss::python

// Model loading: load_robot, load_environment, load_path (the thesis formats of Appendix A, read
// by the io stage as `grpvss verify` reads them) and the read-only Robot, Environment and Path
// objects. Revolute joint values are radians here (the files hold degrees).
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include <variant>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "grpvss/cell/model_inputs.hpp"
#include "grpvss/io/length_unit.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/io/text_file.hpp"
#include "grpvss/report/input_digests.hpp"

namespace py = pybind11;

namespace grpvss::python {
namespace {

std::shared_ptr<LoadedRobot> load_robot(const std::string& file) {
  auto robot = std::make_shared<LoadedRobot>();
  robot->file = file;
  robot->model = io::read_robot_file(file);
  robot->sha256 = report::sha256_hex_of_file(file);
  return robot;
}

std::shared_ptr<LoadedEnvironment> load_environment(const std::string& file) {
  auto environment = std::make_shared<LoadedEnvironment>();
  environment->file = file;
  environment->model = io::read_environment_file(file);
  environment->sha256 = report::sha256_hex_of_file(file);
  return environment;
}

std::shared_ptr<LoadedPath> load_path(const std::string& file,
                                            std::shared_ptr<LoadedRobot> robot) {
  auto path = std::make_shared<LoadedPath>();
  path->file = file;
  path->program = cell::parse_model_path(
      io::read_text_file(file), file, robot->model, robot->path_length_scale,
      io::PathPlacement{io::length_unit_from_name(robot->length_unit), robot->X_WR});
  path->sha256 = report::sha256_hex_of_file(file);
  path->robot = std::move(robot);
  return path;
}

/// A cell file read as `grpvss verify --cell` reads it: (robot, environment, tolerance or None,
/// CP speed or None, warnings as (file, line, text)). Both models carry the cell file's name and
/// digest, which is what the reports and certificates bind a cell's model to.
py::tuple load_cell(const std::string& file, const std::vector<std::string>& package_paths) {
  cell::ModelSources sources;
  sources.cell_file = file;
  sources.package_paths = package_paths;
  cell::ModelInputs inputs = cell::load_model_inputs(sources);
  const std::string digest = report::sha256_hex_of_file(file);
  auto robot = std::make_shared<LoadedRobot>();
  robot->file = file;
  robot->sha256 = digest;
  robot->model = std::move(inputs.robot);
  robot->from_cell = true;
  robot->path_length_scale = inputs.model_units_per_cell_unit;
  robot->X_WR = inputs.X_WR;
  robot->X_FE = inputs.X_FE;
  if (inputs.model_unit) robot->length_unit = io::length_unit_name(*inputs.model_unit);
  auto environment = std::make_shared<LoadedEnvironment>();
  environment->file = file;
  environment->sha256 = digest;
  environment->model = std::move(inputs.environment);
  py::list warnings;
  for (const io::InputWarning& w : inputs.warnings) warnings.append(py::make_tuple(w.file, w.line, w.text));
  const auto optional = [](const std::optional<double>& value) -> py::object {
    return value ? py::object(py::float_(*value)) : py::object(py::none());
  };
  return py::make_tuple(robot, environment, optional(inputs.tolerance), optional(inputs.cp_speed),
                        warnings);
}

bool has_general_frames(const RobotModel& robot) {
  for (const Joint& joint : robot.joints) {
    if (joint.frames) return true;
  }
  return false;
}

const char* joint_type_name(JointType type) {
  return type == JointType::kRevolute ? "revolute" : "prismatic";
}

const char* segment_kind(const PathSegment& segment) {
  if (std::holds_alternative<PtpJointSegment>(segment.spec)) return "ptp_joint";
  if (std::holds_alternative<PtpWorldSegment>(segment.spec)) return "ptp_world";
  return "cp_line";
}

RobotClass bind_robot(py::module_& module) {
  using Robot = LoadedRobot;
  return RobotClass(module, "Robot",
                                            "A robot loaded from a thesis robot file (A.1.1.1) or a cell file")
      .def_property_readonly("file", [](const Robot& r) { return r.file; })
      .def_property_readonly("sha256", [](const Robot& r) { return r.sha256; })
      .def_property_readonly("name", [](const Robot& r) { return r.model.name; })
      .def_property_readonly("joint_count", [](const Robot& r) { return r.model.joint_count(); })
      .def_property_readonly("link_count",
                             [](const Robot& r) { return static_cast<int>(r.model.links.size()); })
      .def_property_readonly("joint_indices",
                             [](const Robot& r) {
                               py::list indices;
                               for (int i = 1; i <= r.model.joint_count(); ++i) indices.append(i);
                               return indices;
                             })
      .def_property_readonly("joint_types",
                             [](const Robot& r) {
                               py::list types;
                               for (const Joint& j : r.model.joints) types.append(joint_type_name(j.type));
                               return types;
                             })
      .def_property_readonly("home",
                             [](const Robot& r) {
                               Eigen::VectorXd q(r.model.joint_count());
                               for (int i = 0; i < q.size(); ++i) q[i] = r.model.joints[i].home;
                               return q;
                             })
      .def_property_readonly("limits",
                             [](const Robot& r) {
                               Eigen::MatrixXd limits(r.model.joint_count(), 2);
                               for (int i = 0; i < limits.rows(); ++i) {
                                 limits(i, 0) = r.model.joints[i].minimum;
                                 limits(i, 1) = r.model.joints[i].maximum;
                               }
                               return limits;
                             })
      .def_property_readonly("from_cell", [](const Robot& r) { return r.from_cell; })
      .def_property_readonly("joint_names",
                             [](const Robot& r) {
                               py::list names;
                               for (const Joint& j : r.model.joints) names.append(j.name);
                               return names;
                             },
                             "URDF joint names (empty strings for a thesis robot)")
      .def_property_readonly("link_names",
                             [](const Robot& r) {
                               py::list names;
                               for (int i = 0; i < static_cast<int>(r.model.links.size()); ++i) {
                                 names.append(link_label(r.model, i));
                               }
                               return names;
                             },
                             "Names of link frames 0..N (URDF link names; 'link i' for thesis robots)")
      .def_property_readonly("dh",
                             [](const Robot& r) {
                               if (has_general_frames(r.model)) {
                                 throw py::value_error(r.file + ": a URDF robot's joints have general "
                                                       "frames (origin, axis), not DH parameters");
                               }
                               Eigen::MatrixXd dh(r.model.joint_count(), 4);
                               for (int i = 0; i < dh.rows(); ++i) {
                                 const DhParameters& p = r.model.joints[i].dh;
                                 dh.row(i) << p.theta, p.d, p.a, p.alpha;
                               }
                               return dh;
                             },
                             "Standard DH (theta offset, d, a, alpha) per joint, radians")
      .def("__repr__", [](const Robot& r) {
        return "<grpvss.Robot " + r.file + ": " + std::to_string(r.model.joint_count()) + " joints>";
      });
}

void bind_environment(py::module_& module) {
  using Env = LoadedEnvironment;
  py::class_<Env, std::shared_ptr<Env>>(module, "Environment",
                                        "Static convex obstacles (thesis environment file A.1.1.2)")
      .def_property_readonly("file", [](const Env& e) { return e.file; })
      .def_property_readonly("sha256", [](const Env& e) { return e.sha256; })
      .def_property_readonly("obstacle_count",
                             [](const Env& e) { return static_cast<int>(e.model.obstacles.size()); })
      .def_property_readonly("smallest_angle", [](const Env& e) { return e.model.smallest_angle; })
      .def_property_readonly("smallest_thickness",
                             [](const Env& e) { return e.model.smallest_thickness; })
      .def_property_readonly("obstacle_names",
                             [](const Env& e) {
                               py::list names;
                               for (int i = 0; i < static_cast<int>(e.model.obstacles.size()); ++i) {
                                 names.append(obstacle_label(e.model, i));
                               }
                               return names;
                             },
                             "Per obstacle hull: its name ('post', 'fixture part 2') or 'obstacle i'")
      .def("__repr__", [](const Env& e) {
        return "<grpvss.Environment " + e.file + ": " +
               std::to_string(e.model.obstacles.size()) + " obstacles>";
      });
}

void bind_path(py::module_& module) {
  using Path = LoadedPath;
  py::class_<Path, std::shared_ptr<Path>>(module, "Path", "A path file (A.1.3) read for one robot")
      .def_property_readonly("file", [](const Path& p) { return p.file; })
      .def_property_readonly("sha256", [](const Path& p) { return p.sha256; })
      .def_property_readonly("robot", [](const Path& p) { return p.robot; })
      .def_property_readonly("segment_count",
                             [](const Path& p) { return static_cast<int>(p.program.segments.size()); })
      .def_property_readonly("segment_kinds",
                             [](const Path& p) {
                               py::list kinds;
                               for (const auto& s : p.program.segments) kinds.append(segment_kind(s));
                               return kinds;
                             })
      .def("__repr__", [](const Path& p) {
        return "<grpvss.Path " + p.file + ": " + std::to_string(p.program.segments.size()) +
               " segments>";
      });
}

}  // namespace

RobotClass bind_model_loading(py::module_& module) {
  RobotClass robot = bind_robot(module);
  bind_environment(module);
  bind_path(module);
  module.def("load_robot", &load_robot, py::arg("file"),
             "Reads a thesis robot file. Raises grpvss.InputError on a defect.");
  module.def("load_environment", &load_environment, py::arg("file"),
             "Reads a thesis environment file. Raises grpvss.InputError on a defect.");
  module.def("_load_cell", &load_cell, py::arg("file"), py::arg("package_paths"),
             "Reads a cell file. Raises grpvss.InputError on a defect.");
  module.def("load_path", &load_path, py::arg("file"), py::arg("robot"),
             "Reads a thesis path file for `robot`. Raises grpvss.InputError on a defect.");
  return robot;
}

}  // namespace grpvss::python

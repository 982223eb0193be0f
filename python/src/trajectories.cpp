// Joint trajectories (docs/python.md#joint-trajectories): a planner's trajectory read from a
// file (CSV or ROS JSON) or given as numpy arrays, made into the motion a verification
// certifies by the loader `grpvss verify --trajectory` and batch jobs use
// (batch::joint_motion_of). Arrays are verified as their canonical CSV text: the reader
// validates them (errors name the line of that text, see JointTrajectory.to_csv()) and its
// digest binds the certificate.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "grpvss/batch/joint_trajectory_input.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/trajectory_csv_text.hpp"
#include "grpvss/io/trajectory_file.hpp"
#include "grpvss/motion/joint_trajectory_source.hpp"
#include "grpvss/report/atomic_output.hpp"
#include "grpvss/report/input_digests.hpp"

namespace py = pybind11;

namespace grpvss::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string shape_text(const Array& array) {
  std::string text = "shape (";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    text += (d > 0 ? ", " : "") + std::to_string(array.shape(d));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

// `name` must have shape (rows,) or (rows, columns); the error names the argument.
void require_shape(const Array& array, const char* name, py::ssize_t rows,
                   std::optional<py::ssize_t> columns, const std::string& meaning) {
  const bool ok = columns ? array.ndim() == 2 && array.shape(0) == rows && array.shape(1) == *columns
                          : array.ndim() == 1 && array.shape(0) == rows;
  if (ok) return;
  const std::string wanted = columns ? fmt::format("({}, {})", rows, *columns)
                                     : fmt::format("({},)", rows);
  throw InputError(name, 0, fmt::format("an array of shape {} ({})", wanted, meaning),
                   shape_text(array));
}

std::vector<Eigen::VectorXd> rows_of(const Array& array) {
  std::vector<Eigen::VectorXd> rows(static_cast<std::size_t>(array.shape(0)));
  const auto view = array.unchecked<2>();
  for (py::ssize_t k = 0; k < array.shape(0); ++k) {
    rows[static_cast<std::size_t>(k)].resize(array.shape(1));
    for (py::ssize_t j = 0; j < array.shape(1); ++j) rows[static_cast<std::size_t>(k)][j] = view(k, j);
  }
  return rows;
}

std::vector<std::string> robot_joint_names(const LoadedRobot& robot, const std::string& label) {
  std::vector<std::string> names;
  for (const Joint& joint : robot.model.joints) {
    if (joint.name.empty()) {
      throw InputError(label, 0,
                       "joint_names, or a robot with named joints (a URDF robot in a cell): a "
                       "trajectory's joints are matched by name",
                       "a robot file without joint names");
    }
    names.push_back(joint.name);
  }
  return names;
}

/// The arrays as a JointTrajectory (shapes checked, values not: the reader checks them).
JointTrajectory from_arrays(const Array& times, const Array& positions,
                            const std::optional<Array>& velocities,
                            std::vector<std::string> joint_names) {
  if (times.ndim() != 1 || times.shape(0) < 1) {
    throw InputError("times", 0, "an array of shape (N,) with N >= 1 waypoint times (s)",
                     shape_text(times));
  }
  const py::ssize_t n = times.shape(0);
  const auto joints = static_cast<py::ssize_t>(joint_names.size());
  require_shape(positions, "positions", n, joints, "N waypoints from times, J joints from joint_names");
  if (velocities) {
    require_shape(*velocities, "velocities", n, joints, "the shape of positions");
  }
  JointTrajectory trajectory;
  trajectory.joint_names = std::move(joint_names);
  trajectory.times.assign(times.data(), times.data() + n);
  trajectory.positions = rows_of(positions);
  if (velocities) trajectory.velocities = rows_of(*velocities);
  return trajectory;
}

std::shared_ptr<LoadedTrajectory> trajectory_from_arrays(
    const Array& times, const Array& positions, const std::optional<Array>& velocities,
    const std::optional<std::vector<std::string>>& joint_names,
    const std::shared_ptr<LoadedRobot>& robot, const std::string& label) {
  auto loaded = std::make_shared<LoadedTrajectory>();
  loaded->file = label;
  loaded->robot = robot;
  loaded->csv = io::render_trajectory_csv(from_arrays(
      times, positions, velocities, joint_names ? *joint_names : robot_joint_names(*robot, label)));
  loaded->sha256 = report::sha256_hex(loaded->csv);
  loaded->motion =
      batch::joint_motion_of(io::parse_trajectory_csv(loaded->csv, label), robot->model);
  return loaded;
}

std::shared_ptr<LoadedTrajectory> load_trajectory(const std::string& file,
                                                  const std::shared_ptr<LoadedRobot>& robot) {
  auto loaded = std::make_shared<LoadedTrajectory>();
  loaded->file = file;
  loaded->robot = robot;
  loaded->motion = batch::load_joint_trajectory(file, robot->model);
  loaded->sha256 = report::sha256_hex_of_file(file);
  return loaded;
}

std::vector<double> waypoint_times(const LoadedTrajectory& t) {
  const std::vector<double>& breaks = t.motion->piece_breaks();
  return {breaks.begin(), breaks.end()};
}

}  // namespace

void bind_trajectories(py::module_& module) {
  using T = LoadedTrajectory;
  py::class_<T, std::shared_ptr<T>>(
      module, "JointTrajectory",
      "A planner's joint trajectory matched to a robot's joints and checked against its limits "
      "(docs/trajectories.md#verifying-a-trajectory)")
      .def_property_readonly("file", [](const T& t) { return t.file; },
                             "The file read, or the label of arrays")
      .def_property_readonly("sha256", [](const T& t) { return t.sha256; })
      .def_property_readonly("robot", [](const T& t) { return t.robot; })
      .def_property_readonly("from_arrays", [](const T& t) { return !t.csv.empty(); })
      .def_property_readonly("waypoint_times", &waypoint_times, "s")
      .def_property_readonly("interpolation",
                             [](const T& t) { return motion::to_string(t.motion->interpolation()); })
      .def_property_readonly("motion_model", [](const T& t) {
        const auto slash = t.file.find_last_of('/');
        return motion::describe_motion_model(
            *t.motion, slash == std::string::npos ? t.file : t.file.substr(slash + 1));
      })
      .def("to_csv", [](const T& t) {
        if (t.csv.empty()) throw py::value_error(t.file + ": read from a file (no CSV form)");
        return t.csv;
      }, "Arrays only: the canonical CSV text verified (and digested); line k+2 is waypoint k")
      .def("save", [](const T& t, const std::string& file, bool force) {
        if (t.csv.empty()) throw py::value_error(t.file + ": read from a file (no CSV form)");
        report::write_file_atomically(file, t.csv, force);
      }, py::arg("file"), py::arg("force") = false,
         "Arrays only: writes to_csv() for `grpvss verify --trajectory FILE`")
      .def("__repr__", [](const T& t) {
        return "<grpvss.JointTrajectory " + t.file + ": " +
               std::to_string(t.motion->piece_breaks().size()) + " waypoints>";
      });
  module.def("_trajectory_from_arrays", &trajectory_from_arrays, py::arg("times"),
             py::arg("positions"), py::arg("velocities"), py::arg("joint_names"),
             py::arg("robot"), py::arg("label"));
  module.def("_load_trajectory", &load_trajectory, py::arg("file"), py::arg("robot"));
}

}  // namespace grpvss::python

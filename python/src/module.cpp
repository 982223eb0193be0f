// The native module `_grpvss`; the package `grpvss` (python/grpvss/__init__.py) re-exports it.
#include <pybind11/pybind11.h>

#include "bindings.hpp"

PYBIND11_MODULE(_grpvss, module) {
  module.doc() = "GRPVSS native bindings (use the package `grpvss`)";
  grpvss::python::bind_errors(module);
  auto robot = grpvss::python::bind_model_loading(module);
  grpvss::python::bind_kinematics(robot);
  grpvss::python::bind_trajectories(module);
  grpvss::python::bind_programs(module);
  grpvss::python::bind_results(module);
  grpvss::python::bind_certificates(module);
  grpvss::python::bind_verification(module);
}

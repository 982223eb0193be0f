// Exceptions: grpvss::InputError (and OutputExistsError, a kind of it) becomes the package's
// grpvss.InputError (a ValueError carrying file, line, expected, found); other standard
// exceptions take pybind11's usual mapping (std::invalid_argument -> ValueError, others ->
// RuntimeError).
#include <exception>

#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "grpvss/common/input_error.hpp"

namespace py = pybind11;

namespace grpvss::python {
namespace {

// The class lives in the pure-Python package; imported without it (the bare `_grpvss`),
// the error is a ValueError with the same text.
void raise_input_error(const InputError& error) {
  try {
    const py::object type = py::module_::import("grpvss").attr("InputError");
    const py::object instance =
        type(error.what(), error.file(), error.line(), error.expected(), error.found());
    PyErr_SetObject(type.ptr(), instance.ptr());
  } catch (const py::error_already_set&) {
    PyErr_SetString(PyExc_ValueError, error.what());
  }
}

}  // namespace

void bind_errors(py::module_& /*module*/) {
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InputError& error) {
      raise_input_error(error);
    }
  });
}

}  // namespace grpvss::python

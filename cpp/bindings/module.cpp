// nonobtuse._core: thin conversion layer. One file per API area; errors are mapped to nonobtuse.errors types.
// Results cross as read-only classes over the core's result structs (their attribute names are defined once,
// here in the bindings); src/nonobtuse/_core.pyi is generated from this module (make stubs), never by hand.
#include <pybind11/pybind11.h>

#include "nonobtuse/types.h"

namespace py = pybind11;

namespace nonobtuse::bindings {
void bind_mesh2d(py::module_& m);
void bind_check2d(py::module_& m);
void bind_validate2d(py::module_& m);
void bind_quality2d(py::module_& m);
void bind_refine2d(py::module_& m);
void bind_gabriel3d(py::module_& m);
void bind_plc(py::module_& m);
void bind_control_volumes3d(py::module_& m);
void bind_quality3d(py::module_& m);
void bind_numeric_rows(py::module_& m);
}

PYBIND11_MODULE(_core, m) {
  m.doc() = "nonobtuse C++ core (CGAL, exact predicates)";
  static py::object invalid_input = py::module_::import("nonobtuse.errors").attr("InvalidInputError");
  static py::object internal_error = py::module_::import("nonobtuse.errors").attr("InternalError");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const nonobtuse::InvalidInput& e) {
      PyErr_SetString(invalid_input.ptr(), e.what());
    } catch (const nonobtuse::InternalError& e) {
      PyErr_SetString(internal_error.ptr(), e.what());
    }
  });
  nonobtuse::bindings::bind_mesh2d(m);
  nonobtuse::bindings::bind_check2d(m);
  nonobtuse::bindings::bind_validate2d(m);
  nonobtuse::bindings::bind_quality2d(m);
  nonobtuse::bindings::bind_refine2d(m);
  nonobtuse::bindings::bind_gabriel3d(m);
  nonobtuse::bindings::bind_plc(m);
  nonobtuse::bindings::bind_control_volumes3d(m);
  nonobtuse::bindings::bind_quality3d(m);
  nonobtuse::bindings::bind_numeric_rows(m);
}

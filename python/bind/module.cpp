// finseg._finseg: the C++ part of the Python module `finseg` (python/finseg/__init__.py
// re-exports it; docs/python.md).
#include <pybind11/pybind11.h>

#include "core/version.hpp"
#include "py_errors.hpp"
#include "py_scene.hpp"

PYBIND11_MODULE(_finseg, m) {
  m.doc() = "finseg: finite-segment simulation of folded flexible sheets (C++ core)";
  m.attr("__version__") = finseg::version();
  m.attr("git_revision") = finseg::git_revision();
  finseg::py::register_error_translator();
  finseg::py::bind_scene(m);
}

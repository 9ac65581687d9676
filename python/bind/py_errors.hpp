// The library's errors as the Python exceptions of finseg/_errors.py: InputError (a
// ValueError with file, field, message), DivergenceError, OutputError.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace finseg::py {

/// Registers the translator of InputError, DivergenceError and OutputError.
void register_error_translator();

/// Raises finseg._errors.<name>(*args) as the pending Python exception and throws
/// pybind11::error_already_set.
[[noreturn]] void raise_python(const char* name, const pybind11::tuple& args);

}  // namespace finseg::py

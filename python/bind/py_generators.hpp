// finseg.cantilever(**options) and finseg.zigzag(**options): the options of
// `finseg gen cantilever|zigzag` as keyword arguments (dashes as underscores; --no-gravity and
// --no-contact as gravity=False, contact=False), mapped onto the structs the CLI fills.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace finseg::py {

/// Scene text of the cantilever generator for `options`; InputError("<python>", name, ...)
/// for an unknown option or a value of the wrong type.
std::string cantilever_text(const pybind11::kwargs& options);

/// Scene text of the zigzag generator for `options` (same errors).
std::string zigzag_text(const pybind11::kwargs& options);

}  // namespace finseg::py

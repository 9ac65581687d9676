#include "py_errors.hpp"

#include "core/error.hpp"

namespace finseg::py {

namespace pyb = pybind11;

namespace {

// The message of an InputError without its "file: field: " prefix.
std::string message_of(const InputError& e) {
  const std::string all = e.what();
  const std::string prefix = e.file() + ": " + e.field() + ": ";
  return all.rfind(prefix, 0) == 0 ? all.substr(prefix.size()) : all;
}

// Sets finseg._errors.<name>(*args) as the pending exception (inside a translator).
void set_python_error(const char* name, const pyb::tuple& args) {
  const pyb::object cls = pyb::module_::import("finseg._errors").attr(name);
  const pyb::object exc = cls(*args);
  PyErr_SetObject(cls.ptr(), exc.ptr());
}

}  // namespace

void raise_python(const char* name, const pyb::tuple& args) {
  set_python_error(name, args);
  throw pyb::error_already_set();
}

void register_error_translator() {
  pyb::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      set_python_error("InputError", pyb::make_tuple(e.file(), e.field(), message_of(e)));
    } catch (const DivergenceError& e) {
      set_python_error("DivergenceError", pyb::make_tuple(e.what()));
    } catch (const OutputError& e) {
      set_python_error("OutputError", pyb::make_tuple(e.what()));
    }
  });
}

}  // namespace finseg::py

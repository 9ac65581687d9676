// finseg.Scene: a scene's YAML text, where it came from and the overrides on it, with the
// Scene (model and run settings) the library reads from them (docs/python.md).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

#include "model/state.hpp"
#include "scene/scene_reader.hpp"

namespace finseg::py {

/// A scene as Python holds it; immutable (with_set gives a new one).
struct PyScene {
  std::string text;                 ///< the YAML as read or generated, before overrides
  std::string file;                 ///< its path, or "<finseg.zigzag>" etc. when generated
  std::vector<Override> overrides;  ///< applied in order, as `finseg run --set`
  std::shared_ptr<const Scene> scene;

  /// Parses `text` with `overrides` (throws InputError as `finseg run` would).
  PyScene(std::string text, std::string file, std::vector<Override> overrides);
};

/// A State with the scene it belongs to and the scene's input hash (docs/state-file.md).
struct PyState {
  std::shared_ptr<const Scene> scene;
  State state;
  std::string scene_hash;
};

/// Overrides from Python: None, a dict {"key.path": value} or a list of "key.path=value"
/// strings. Values: str as YAML text, bool as true/false, numbers in round-trip form,
/// lists and tuples as YAML flow lists.
std::vector<Override> overrides_from(const pybind11::object& set);

/// `state` of `s`'s model, tagged with the scene's input hash.
PyState state_of(const PyScene& s, State state);

/// A JSON value as Python objects (dict, list, float, ...).
pybind11::object json_to_python(const nlohmann::json& j);

/// A numpy array of shape (n, 3) from vectors (m, m/s, rad/s as they are).
pybind11::array_t<double> rows3(const std::vector<Vec3>& v);

/// Adds read_fold() (py_patterns.cpp).
void bind_patterns(pybind11::module_& m);

/// Adds Scene.run and the Result class (py_run.cpp).
void bind_run(pybind11::module_& m, pybind11::class_<PyScene>& scene);

/// Adds Scene, State, load(), parse(), cantilever(), zigzag() to the module.
void bind_scene(pybind11::module_& m);

}  // namespace finseg::py

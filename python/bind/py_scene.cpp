#include "py_scene.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>

#include "core/error.hpp"
#include "core/text.hpp"
#include "py_generators.hpp"
#include "scene/state_file.hpp"
#include "writers/atomic_write.hpp"
#include "writers/provenance.hpp"
#include "writers/run_outputs.hpp"

namespace finseg::py {

namespace pyb = pybind11;

PyScene::PyScene(std::string text_, std::string file_, std::vector<Override> overrides_)
    : text(std::move(text_)), file(std::move(file_)), overrides(std::move(overrides_)) {
  scene = std::make_shared<const Scene>(parse_scene(text, file, overrides));
}

namespace {

// A Python value as the YAML text of an override value.
std::string yaml_value(const pyb::handle& v, const std::string& path) {
  if (pyb::isinstance<pyb::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (pyb::isinstance<pyb::int_>(v) || pyb::isinstance<pyb::float_>(v))
    return pyb::repr(v).cast<std::string>();
  if (pyb::isinstance<pyb::str>(v)) return v.cast<std::string>();
  if (pyb::isinstance<pyb::list>(v) || pyb::isinstance<pyb::tuple>(v)) {
    std::string out;
    for (const pyb::handle& x : v) out += (out.empty() ? "" : ", ") + yaml_value(x, path);
    return "[" + out + "]";
  }
  throw InputError("<python>", "set: " + path,
                   "a value must be a str, bool, number or list of them, not " +
                       pyb::str(pyb::type::of(v).attr("__name__")).cast<std::string>());
}

pyb::array_t<double> rotations(const std::vector<Mat3>& R) {
  pyb::array_t<double> a({static_cast<pyb::ssize_t>(R.size()), pyb::ssize_t{3}, pyb::ssize_t{3}});
  auto m = a.mutable_unchecked<3>();
  for (std::size_t i = 0; i < R.size(); ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m(i, r, c) = R[i](r, c);
  return a;
}

}  // namespace

PyState state_of(const PyScene& s, State state) {
  return {s.scene, std::move(state), scene_inputs_hash(s.text, *s.scene)};
}

// A numpy array of shape (n, 3) from vectors.
pyb::array_t<double> rows3(const std::vector<Vec3>& v) {
  pyb::array_t<double> a({static_cast<pyb::ssize_t>(v.size()), pyb::ssize_t{3}});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int k = 0; k < 3; ++k) m(i, k) = v[i][k];
  return a;
}

pyb::object json_to_python(const nlohmann::json& j) {
  return pyb::module_::import("json").attr("loads")(j.dump());
}

std::vector<Override> overrides_from(const pyb::object& set) {
  std::vector<Override> out;
  if (set.is_none()) return out;
  if (pyb::isinstance<pyb::dict>(set)) {
    for (const auto& [k, v] : set.cast<pyb::dict>()) {
      if (!pyb::isinstance<pyb::str>(k))
        throw InputError("<python>", "set", "keys must be strings like 'drives.0.speed'");
      const std::string path = k.cast<std::string>();
      out.push_back(parse_override(path + "=" + yaml_value(v, path)));
    }
    return out;
  }
  if (pyb::isinstance<pyb::list>(set) || pyb::isinstance<pyb::tuple>(set)) {
    for (const pyb::handle& x : set) {
      if (!pyb::isinstance<pyb::str>(x))
        throw InputError("<python>", "set", "list items must be strings 'key.path=value'");
      out.push_back(parse_override(x.cast<std::string>()));
    }
    return out;
  }
  throw InputError("<python>", "set",
                   "a dict {'key.path': value} or a list of 'key.path=value' strings");
}

void bind_scene(pyb::module_& m) {
  pyb::class_<PyState>(m, "State",
                       "Where the structure is: poses, velocities, drives, history "
                       "(docs/state-file.md). Arrays are copies, SI units.")
      .def_property_readonly(
          "t", [](const PyState& s) { return s.state.t; },
          "s (static solver: load scale or pull displacement, m)")
      .def_property_readonly(
          "load_scale", [](const PyState& s) { return s.state.load_scale; },
          "factor on loads and gravity")
      .def_property_readonly(
          "p_W", [](const PyState& s) { return rows3(s.state.p_W); },
          "body centroids, world frame, m, shape (bodies, 3)")
      .def_property_readonly(
          "R_WB", [](const PyState& s) { return rotations(s.state.R_WB); },
          "body orientations (body to world), shape (bodies, 3, 3)")
      .def_property_readonly(
          "v_W", [](const PyState& s) { return rows3(s.state.v_W); },
          "centroid velocities, world frame, m/s, shape (bodies, 3)")
      .def_property_readonly(
          "w_W", [](const PyState& s) { return rows3(s.state.w_W); },
          "angular velocities, world frame, rad/s, shape (bodies, 3)")
      .def_property_readonly(
          "drive_s",
          [](const PyState& s) {
            return pyb::array_t<double>(static_cast<pyb::ssize_t>(s.state.drive_s.size()),
                                        s.state.drive_s.data());
          },
          "displacement of each drive, m")
      .def_property_readonly(
          "body_names",
          [](const PyState& s) {
            std::vector<std::string> names;
            for (const BodyDef& b : s.scene->model.bodies) names.push_back(b.name);
            return names;
          },
          "names of the bodies, in the rows' order")
      .def_property_readonly(
          "scene_hash", [](const PyState& s) { return s.scene_hash; },
          "fingerprint of the scene's inputs it was computed with (16 hex digits)")
      .def(
          "save",
          [](const PyState& s, const std::string& path) {
            write_state_file(path, s.scene->model, {s.state, s.scene_hash});
          },
          pyb::arg("path"), "write a state file (JSON, docs/state-file.md), atomically");

  pyb::class_<PyScene> scene(m, "Scene",
                             "A scene: model and run settings read from YAML (docs/scene.md), with "
                             "overrides. Immutable: with_set() gives a new one.");
  scene
      .def_property_readonly(
          "yaml", [](const PyScene& s) { return s.text; }, "the YAML text, before overrides")
      .def_property_readonly(
          "file", [](const PyScene& s) { return s.file; },
          "path it was read from, or <finseg.zigzag> etc.")
      .def_property_readonly(
          "overrides",
          [](const PyScene& s) {
            std::vector<std::string> out;
            for (const Override& o : s.overrides) out.push_back(o.path + "=" + o.value);
            return out;
          },
          "the overrides applied, as 'key.path=value'")
      .def_property_readonly(
          "title", [](const PyScene& s) { return s.scene->title; }, "the scene's title")
      .def_property_readonly(
          "solver", [](const PyScene& s) { return solver_name(s.scene->solver.kind); },
          "static, implicit or explicit")
      .def_property_readonly(
          "counts", [](const PyScene& s) { return json_to_python(model_counts(s.scene->model)); },
          "model counts: bodies, elements, creases, dofs, mass_kg, ...")
      .def(
          "with_set",
          [](const PyScene& s, const pyb::object& set) {
            std::vector<Override> all = s.overrides;
            for (Override& o : overrides_from(set)) all.push_back(std::move(o));
            return PyScene(s.text, s.file, all);
          },
          pyb::arg("set"),
          "a new Scene with more overrides (as finseg run --set): a dict {'key.path': value} or "
          "a list of 'key.path=value' strings");
  scene.def(
      "save",
      [](const PyScene& s, const std::string& path) { write_file_atomically(path, s.text); },
      pyb::arg("path"), "write the YAML text (without the overrides), atomically");
  scene.def(
      "initial_state", [](const PyScene& s) { return state_of(s, initial_state(s.scene->model)); },
      "the state at t = 0");
  scene.def(
      "read_state",
      [](const PyScene& s, const std::string& path) {
        StateSnapshot snap = read_state_file(path, s.scene->model);
        return PyState{s.scene, std::move(snap.state), snap.scene_hash};
      },
      pyb::arg("path"), "read a state file of this scene's model (raises InputError)");
  bind_run(m, scene);
  bind_patterns(m);

  m.def(
      "load",
      [](const std::string& path, const pyb::object& set) {
        read_text_file(path);  // an unreadable file is an InputError naming it
        return PyScene(read_whole_file(path), path, overrides_from(set));
      },
      pyb::arg("path"), pyb::arg("set") = pyb::none(),
      "read a scene file (YAML), with optional overrides");
  m.def(
      "parse",
      [](const std::string& yaml, const std::string& file, const pyb::object& set) {
        return PyScene(yaml, file, overrides_from(set));
      },
      pyb::arg("yaml"), pyb::arg("file") = "<string>", pyb::arg("set") = pyb::none(),
      "a scene from YAML text; `file` names it in messages and relative data files resolve "
      "from its folder");
  m.def(
      "cantilever",
      [](const pyb::kwargs& options) {
        return PyScene(cantilever_text(options), "<finseg.cantilever>", {});
      },
      "the cantilever generator (options of `finseg gen cantilever`, docs/python.md)");
  m.def(
      "zigzag",
      [](const pyb::kwargs& options) {
        return PyScene(zigzag_text(options), "<finseg.zigzag>", {});
      },
      "the zigzag strip generator (options of `finseg gen zigzag`, docs/python.md)");
}

}  // namespace finseg::py

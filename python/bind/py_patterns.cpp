// finseg.read_fold(): a FOLD crease pattern read and checked as `finseg pattern check` does
// (docs/fold.md), as numpy arrays. No model is built from it: the library cannot yet cut a
// pattern's faces into segments.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>

#include "core/error.hpp"
#include "patterns/fold_format.hpp"
#include "py_scene.hpp"

namespace finseg::py {

namespace pyb = pybind11;

namespace {

// `unit` of a unitless file: None, a FOLD unit name ("mm") or metres per unit (> 0).
std::optional<double> metres_per_unit(const pyb::object& unit) {
  if (unit.is_none()) return std::nullopt;
  if (pyb::isinstance<pyb::str>(unit)) {
    if (const auto m = metres_per_fold_unit(unit.cast<std::string>())) return m;
  } else if (!pyb::isinstance<pyb::bool_>(unit) &&
             (pyb::isinstance<pyb::float_>(unit) || pyb::isinstance<pyb::int_>(unit))) {
    const double m = unit.cast<double>();
    if (m > 0 && std::isfinite(m)) return m;
  }
  throw InputError("<python>", "unit",
                   "m, cm, mm, um, nm, in, pt or metres per unit (a number > 0)");
}

pyb::dict pattern_dict(const CreasePattern& p) {
  const auto n = static_cast<pyb::ssize_t>(p.vertices_flat_m.size());
  const auto e = static_cast<pyb::ssize_t>(p.edges.size());
  pyb::array_t<double> flat({n, pyb::ssize_t{2}});
  auto f = flat.mutable_unchecked<2>();
  for (pyb::ssize_t i = 0; i < n; ++i)
    f(i, 0) = p.vertices_flat_m[i].x(), f(i, 1) = p.vertices_flat_m[i].y();
  pyb::array_t<int> ev({e, pyb::ssize_t{2}});
  pyb::array_t<double> angle(e);
  auto v = ev.mutable_unchecked<2>();
  auto a = angle.mutable_unchecked<1>();
  std::string assignment;
  for (pyb::ssize_t i = 0; i < e; ++i) {
    v(i, 0) = p.edges[i].vertices[0];
    v(i, 1) = p.edges[i].vertices[1];
    a(i) = p.edges[i].fold_angle;
    assignment += static_cast<char>(p.edges[i].assignment);
  }
  pyb::dict d;
  d["vertices_flat_m"] = flat;
  d["vertices_folded_m"] = p.vertices_folded_m.empty() ? pyb::object(pyb::none())
                                                       : pyb::object(rows3(p.vertices_folded_m));
  d["faces_vertices"] = p.faces;
  d["edges_vertices"] = ev;
  d["edges_assignment"] = assignment;
  d["edges_fold_angle_rad"] = angle;
  d["has_fold_angles"] = p.has_fold_angles;
  d["title"] = p.meta.frame_title;
  return d;
}

}  // namespace

void bind_patterns(pyb::module_& m) {
  m.def(
      "read_fold",
      [](const std::string& path, const pyb::object& unit) {
        return pattern_dict(read_fold(path, metres_per_unit(unit)));
      },
      pyb::arg("path"), pyb::arg("unit") = pyb::none(),
      "read and check a FOLD crease pattern (docs/fold.md), as `finseg pattern check`: "
      "vertices_flat_m (n, 2), vertices_folded_m (n, 3) or None, faces_vertices, "
      "edges_vertices (e, 2), edges_assignment (one letter per edge), edges_fold_angle_rad "
      "(valley positive). unit: length of one unit of a unitless file");
}

}  // namespace finseg::py

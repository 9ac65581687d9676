#include "model/model.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace finseg {

void Model::finalize_dofs() {
  dof_of_body.assign(bodies.size(), -1);
  num_dofs = 0;
  for (size_t i = 0; i < bodies.size(); ++i) {
    if (!bodies[i].fixed) {
      dof_of_body[i] = num_dofs;
      num_dofs += 6;
    }
  }
}

int Model::body_index(const std::string& name) const {
  for (size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int panel_count(const Model& m) {
  int panels = 1;
  for (const BodyDef& b : m.bodies) panels = std::max(panels, b.panel + 1);
  return panels;
}

bool has_drive_path(const Model& m) {
  return !m.drives.empty() && m.drives[0].travel > 0 && m.drives[0].step > 0;
}

Vec2 set_prism(BodyDef& b, const Outline& outline_B, double thickness, double mass) {
  const Vec2 c = polygon_centroid(outline_B);
  b.outline_B = translated(outline_B, -c);
  b.thickness = thickness;
  b.mass = mass;
  b.J_B = prism_inertia(b.outline_B, thickness, mass);
  return c;
}

void set_box(BodyDef& b, const Vec3& size, double mass) {
  set_prism(b, rectangle_outline(size.x(), size.y()), size.z(), mass);
}

double segment_area(const BodyDef& b) {
  return polygon_area(b.outline_B);
}

Outline material_outline(const BodyDef& b) {
  return translated(b.outline_B, b.centroid_M.value());
}

namespace {

bool finite(const Eigen::MatrixXd& m) {
  return m.allFinite();
}

void check_body_ref(const Model& m, int body, const std::string& field) {
  if (body < 0 || body >= static_cast<int>(m.bodies.size())) {
    throw InputError(m.source, field,
                     fmt::format("body index {} out of range [0, {})", body, m.bodies.size()));
  }
}

}  // namespace

void validate(const Model& m) {
  if (m.bodies.empty()) throw InputError(m.source, "bodies", "the model has no body");
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const BodyDef& b = m.bodies[i];
    const std::string f = fmt::format("bodies[{}]", i);
    if (!(b.mass > 0) || !std::isfinite(b.mass)) {
      throw InputError(m.source, f + ".mass", fmt::format("{} kg; must be > 0", b.mass));
    }
    if (!(b.thickness > 0) || !std::isfinite(b.thickness)) {
      throw InputError(m.source, f + ".thickness", fmt::format("{} m; must be > 0", b.thickness));
    }
    if (b.outline_B.size() > kMaxOutlineVertices) {
      throw InputError(m.source, f + ".outline",
                       fmt::format("{} vertices; a segment has at most {}", b.outline_B.size(),
                                   kMaxOutlineVertices));
    }
    const double r = outline_radius(b.outline_B);
    const std::string shape = convexity_problem(b.outline_B, 1e-9 * r);
    if (!shape.empty()) throw InputError(m.source, f + ".outline", "the polygon " + shape);
    if (polygon_centroid(b.outline_B).norm() > 1e-9 * r) {
      throw InputError(m.source, f + ".outline", "the polygon's centroid must be B's origin");
    }
    if (!finite(b.J_B) || !(b.J_B.diagonal().minCoeff() > 0)) {
      throw InputError(m.source, f + ".inertia", "must be finite with positive diagonal");
    }
    if (!finite(b.p0_W) || !finite(b.R0_WB) ||
        (b.R0_WB.transpose() * b.R0_WB - Mat3::Identity()).norm() > 1e-9) {
      throw InputError(m.source, f + ".pose", "position must be finite, orientation a rotation");
    }
  }
  for (size_t k = 0; k < m.elements.size(); ++k) {
    const ElementDef& e = m.elements[k];
    const std::string f = fmt::format("elements[{}]", k);
    check_body_ref(m, e.inner, f + ".inner");
    check_body_ref(m, e.outer, f + ".outer");
    if (e.inner == e.outer) throw InputError(m.source, f, "joins a body to itself");
    if (!finite(e.K) || e.K.minCoeff() < 0) {
      throw InputError(m.source, f + ".stiffness", "must be finite and >= 0");
    }
    if (!finite(e.C) || e.C.minCoeff() < 0) {
      throw InputError(m.source, f + ".damping", "must be finite and >= 0");
    }
    if (e.crease >= static_cast<int>(m.creases.size()) ||
        (e.crease >= 0 && !m.creases[e.crease].law)) {
      throw InputError(m.source, f + ".crease", "refers to a missing crease law");
    }
  }
  for (size_t i = 0; i < m.loads.size(); ++i) {
    const LoadDef& l = m.loads[i];
    const std::string f = fmt::format("loads[{}]", i);
    check_body_ref(m, l.body, f + ".body");
    if (!finite(l.force) || !finite(l.moment) || !finite(l.point_B)) {
      throw InputError(m.source, f, "force, moment and point must be finite");
    }
  }
  for (size_t i = 0; i < m.drives.size(); ++i) {
    const DriveDef& d = m.drives[i];
    const std::string f = fmt::format("drives[{}]", i);
    check_body_ref(m, d.body, f + ".body");
    if (!(d.stiffness > 0) || !std::isfinite(d.stiffness)) {
      throw InputError(m.source, f + ".stiffness", "must be finite and > 0 N/m");
    }
    if (!(d.lateral_ratio >= 0) || !std::isfinite(d.lateral_ratio)) {
      throw InputError(m.source, f + ".lateral_stiffness", "must be finite and >= 0 N/m");
    }
    if (!(d.toe_force >= 0) || !std::isfinite(d.toe_force)) {
      throw InputError(m.source, f + ".toe_force", "must be finite and >= 0 N");
    }
    if (d.toe_force > 0 && !d.pull_only) {
      throw InputError(m.source, f + ".toe_force", "applies to pull_only: true drives only");
    }
    if (std::abs(d.direction_W.norm() - 1.0) > 1e-9) {
      throw InputError(m.source, f + ".direction", "must be a unit vector");
    }
    if (d.damping < 0 || d.travel < 0 || d.step < 0) {
      throw InputError(m.source, f, "damping, travel and step must be >= 0");
    }
  }
  if (!finite(m.gravity_W)) throw InputError(m.source, "gravity", "must be finite");
  validate_pressures(m.pressures, static_cast<int>(m.bodies.size()), m.source);
  validate_chambers(m.chambers, static_cast<int>(m.bodies.size()), m.source);
  if (static_cast<int>(m.dof_of_body.size()) != static_cast<int>(m.bodies.size())) {
    throw InputError(m.source, "bodies", "finalize_dofs() was not called after adding bodies");
  }
}

}  // namespace finseg

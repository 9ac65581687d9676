// Small hand-built models of rigid plates for the pressure and chamber tests.
#pragma once

#include <fmt/format.h>

#include <string>
#include <vector>

#include "contact_test_util.hpp"
#include "core/so3.hpp"
#include "elements/chamber_gas.hpp"
#include "elements/chamber_volume.hpp"

namespace finseg::test {

/// Appends a plate (mid-surface size.x x size.y, thickness size.z) at p_W turned by R_WB;
/// returns its body index.
inline int add_plate(Model& m, const std::string& name, const Vec3& size, const Vec3& p_W,
                     const Mat3& R_WB = Mat3::Identity(), double mass = 0.02, bool fixed = false) {
  m.bodies.push_back(plate(name, mass, size, p_W, R_WB, fixed));
  return static_cast<int>(m.bodies.size()) - 1;
}

constexpr double kPlateThickness = 1e-3;

// Rotations taking body z to world +x, +y (the face normals of an axis-aligned box).
inline const Mat3 kZtoX = so3_exp(Vec3(0, M_PI / 2, 0));   // x_B -> -z, z_B -> +x
inline const Mat3 kZtoY = so3_exp(Vec3(-M_PI / 2, 0, 0));  // y_B -> +z, z_B -> +y

/// Adds the six plates of the box [0, a] x [0, b] x [0, c] (fixed or free, `mass` each) and
/// returns them as chamber faces with outward normals.
inline std::vector<ChamberFace> add_box(Model& m, double a, double b, double c, bool fixed = false,
                                        double mass = 0.02) {
  std::vector<ChamberFace> faces;
  const auto face = [&](const Vec3& size, const Vec3& p, const Mat3& R, bool plus) {
    faces.push_back(
        {add_plate(m, fmt::format("f{}", faces.size()), size, p, R, mass, fixed), plus});
  };
  const double t = kPlateThickness;
  face({a, b, t}, {a / 2, b / 2, c}, Mat3::Identity(), true);
  face({a, b, t}, {a / 2, b / 2, 0}, Mat3::Identity(), false);
  face({c, b, t}, {a, b / 2, c / 2}, kZtoX, true);
  face({c, b, t}, {0, b / 2, c / 2}, kZtoX, false);
  face({a, c, t}, {a / 2, b, c / 2}, kZtoY, true);
  face({a, c, t}, {a / 2, 0, c / 2}, kZtoY, false);
  return faces;
}

/// Joins pairs of touching faces of a box along their common edge by a bushing (stiffness k
/// N/m, kr N m/rad) at each third of the edge.
inline void join_box_edges(Model& m, const std::vector<ChamberFace>& faces, double k, double kr) {
  const auto corners = [&](int b) {
    std::vector<Vec3> c;
    for (const Vec2& x : m.bodies[b].outline_B) {
      c.push_back(m.bodies[b].p0_W + m.bodies[b].R0_WB * Vec3(x.x(), x.y(), 0));
    }
    return c;
  };
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (std::size_t j = i + 1; j < faces.size(); ++j) {
      std::vector<Vec3> shared;
      for (const Vec3& a : corners(faces[i].body))
        for (const Vec3& b : corners(faces[j].body))
          if ((a - b).norm() < 1e-12) shared.push_back(a);
      if (shared.size() != 2) continue;
      for (const double w : {1.0 / 3, 2.0 / 3}) {
        const Vec3 P = (1 - w) * shared[0] + w * shared[1];
        const BodyDef& bi = m.bodies[faces[i].body];
        const BodyDef& bj = m.bodies[faces[j].body];
        ElementDef e;
        e.inner = faces[i].body;
        e.outer = faces[j].body;
        e.c_inner_B = bi.R0_WB.transpose() * (P - bi.p0_W);
        e.c_outer_B = bj.R0_WB.transpose() * (P - bj.p0_W);
        e.R_inner_E = bi.R0_WB.transpose();
        e.R_outer_F = bj.R0_WB.transpose();
        e.K << k, k, k, kr, kr, kr;
        m.elements.push_back(e);
      }
    }
  }
}

/// Adds chamber `c` to `m` and finishes the model as a scene would: length scale `length`
/// (m), DOFs, validation, the chamber's closed surface.
inline void add_chamber_and_finish(Model& m, const ChamberDef& c, double length) {
  m.chambers.push_back(c);
  m.sheet.length = length;
  m.finalize_dofs();
  validate(m);
  prepare_chambers(m);
}

/// A chamber of prescribed pressure (zero until set) bounded by every body of `m`, each
/// with its +z side outward: a closed pattern surface such as a sealed tube.
inline ChamberDef whole_model_chamber(const Model& m, const std::string& name) {
  ChamberDef c;
  c.name = name;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) c.faces.push_back({static_cast<int>(b), true});
  c.gas = GasModel::Prescribed;
  return c;
}

}  // namespace finseg::test

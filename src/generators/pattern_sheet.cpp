// Sheet from a crease pattern. Joint geometry: a cell side of length l whose cells' centroids
// lie d_L and d_R from its line stands for the strip of sheet between them, h = d_L + d_R;
// next to a clamped cell only the free side counts (the clamp is the side itself).
#include "generators/pattern_sheet.hpp"

#include <fmt/format.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/text.hpp"
#include "elements/crease_law.hpp"
#include "elements/crease_laws/scaled.hpp"
#include "generators/plate_cell_fit.hpp"
#include "patterns/pattern_checks.hpp"
#include "patterns/segment_mesh.hpp"

namespace finseg {
namespace {

constexpr double kShearCorrection = 5.0 / 6.0;

void validate_spec(const PatternSheetSpec& s, const CreasePattern& p, const std::string& src) {
  require_positive(s.thickness, src, "sheet.thickness", "m");
  require_positive(s.youngs_modulus, src, "material.youngs_modulus", "Pa");
  require_positive(s.density, src, "material.density", "kg/m^3");
  require_positive(s.crease_law_length, src, "creases.law_length", "m");
  if (!(s.poisson_ratio >= 0 && s.poisson_ratio < 0.5)) {
    throw InputError(src, "material.poisson_ratio",
                     fmt::format("{}; allowed range [0, 0.5)", s.poisson_ratio));
  }
  if (s.subdivisions < 1 || s.subdivisions > 64) {
    throw InputError(src, "discretisation.subdivisions",
                     fmt::format("{}; allowed range 1..64", s.subdivisions));
  }
  for (int f : s.fixed_faces) {
    if (f < 0 || f >= static_cast<int>(p.faces.size())) {
      throw InputError(src, "fixtures.fixed_faces",
                       fmt::format("face {} does not exist (1..{})", f + 1, p.faces.size()));
    }
  }
  if (!(s.damping_time >= 0)) throw InputError(src, "damping_time", "must be >= 0 s");
}

// Rigid motion (R, p) taking the flat points (x, y, 0) nearest to the folded ones (Kabsch).
void fit_pose(const std::vector<Vec2>& flat, const std::vector<Vec3>& folded, const Vec2& c_flat,
              Mat3& R, Vec3& p) {
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();
  for (std::size_t k = 0; k < flat.size(); ++k) {
    a += Vec3(flat[k].x(), flat[k].y(), 0);
    b += folded[k];
  }
  a /= static_cast<double>(flat.size());
  b /= static_cast<double>(flat.size());
  Mat3 H = Mat3::Zero();
  for (std::size_t k = 0; k < flat.size(); ++k) {
    H += (Vec3(flat[k].x(), flat[k].y(), 0) - a) * (folded[k] - b).transpose();
  }
  const Eigen::JacobiSVD<Mat3> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 D = Mat3::Identity();
  D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1 : 1;
  R = svd.matrixV() * D * svd.matrixU().transpose();
  p = b + R * (Vec3(c_flat.x(), c_flat.y(), 0) - a);
}

// The law of a crease side by its pattern edge, or null for a plate joint.
std::shared_ptr<const CreaseLaw> law_of(const PatternEdge& e, const PatternSheetSpec& s, int index,
                                        const std::string& src) {
  EdgeAssignment a = e.assignment;
  if ((a == EdgeAssignment::Flat || a == EdgeAssignment::Unassigned) && e.fold_angle != 0) {
    a = e.fold_angle > 0 ? EdgeAssignment::Valley : EdgeAssignment::Mountain;
  }
  if (a != EdgeAssignment::Mountain && a != EdgeAssignment::Valley) return nullptr;
  const bool mountain = a == EdgeAssignment::Mountain;
  const auto& law = mountain ? s.mountain_law : s.valley_law;
  if (!law) {
    throw InputError(
        src, fmt::format("edges_assignment[{}]", index),
        fmt::format("a {} crease needs a {} crease law", mountain ? "mountain" : "valley",
                    mountain ? "mountain" : "valley"));
  }
  return law;
}

// The sides of a plate joint as the two cells' curvature fits see them: the vector to the
// neighbour's centroid, or, next to a clamped cell, to the foot point on the side (the clamp
// holds the rotation there), whose joint is then the free cell's alone.
void add_cell_sides(const CellLink& l, const ElementDef& e, int element, const Model& m,
                    std::vector<std::vector<CellSideGeometry>>& cell_sides) {
  const Vec2 across(e.R_outer_F(0, 0), e.R_outer_F(1, 0));
  const Vec2 P(e.c_outer_B.x() + m.bodies[l.left].centroid_M->x(),
               e.c_outer_B.y() + m.bodies[l.left].centroid_M->y());
  for (const int side : {0, 1}) {
    const int c = side == 0 ? l.left : l.right, o = side == 0 ? l.right : l.left;
    const Vec2 c_M = *m.bodies[c].centroid_M;
    CellSideGeometry g;
    g.side = {element, e.R_outer_F, side == 0 ? 1.0 : -1.0};
    g.weight = e.K[3];  // twist; bending K[4] is the same on plate joints
    g.crease = e.crease >= 0;
    g.across_M = across;
    if (m.bodies[o].fixed) {
      g.d_M = across.dot(P - c_M) * across;
      g.share = 1;
    } else {
      g.d_M = *m.bodies[o].centroid_M - c_M;
    }
    cell_sides[c].push_back(g);
  }
}

}  // namespace

Vec6 plate_joint_stiffness(double E, double nu, double t, double l, double h) {
  const double G = E / (2 * (1 + nu)), D = E * t * t * t / (12 * (1 - nu * nu));
  Vec6 k;
  // Twist and bending both D: the joints then store D/2 kappa:kappa, Kirchhoff's energy less
  // the null Lagrangian D nu det(kappa) (docs/stiffness.md).
  k << E * t * l / h, G * t * l / h, kShearCorrection * G * t * l / h, D * l / h, D * l / h,
      E * t * l * l * l / (12 * h);
  return k;
}

Model build_pattern_model(const CreasePattern& p, const PatternSheetSpec& spec,
                          const std::string& source) {
  validate_spec(spec, p, source);
  const SegmentMesh mesh = subdivide_pattern(p, spec.subdivisions);
  const bool folded = spec.start_folded && !mesh.folded_m.empty();
  Model m;
  m.source = source;
  Vec2 lo = mesh.flat_m.front(), hi = lo;
  for (const Vec2& v : mesh.flat_m) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  m.sheet = {hi.x() - lo.x(),     hi.y() - lo.y(),    spec.thickness, lo,
             spec.youngs_modulus, spec.poisson_ratio, spec.density};

  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    BodyDef b;
    Outline flat;
    std::vector<Vec3> pts;
    for (int v : mesh.cells[c]) {
      flat.push_back(mesh.flat_m[v]);
      if (folded) pts.push_back(mesh.folded_m[v]);
    }
    const double mass = spec.density * polygon_area(flat) * spec.thickness;
    const Vec2 c_M = set_prism(b, flat, spec.thickness, mass);
    b.centroid_M = c_M;
    b.panel = mesh.cell_face[c];
    b.fixed = std::find(spec.fixed_faces.begin(), spec.fixed_faces.end(), b.panel) !=
              spec.fixed_faces.end();
    b.name = fmt::format("face{}_cell{}", b.panel + 1, c);
    if (folded) {
      fit_pose(flat, pts, c_M, b.R0_WB, b.p0_W);
      b.R0_WB = spec.R_W0 * b.R0_WB;
      b.p0_W = spec.origin_W + spec.R_W0 * b.p0_W;
    } else {
      b.R0_WB = spec.R_W0;
      b.p0_W = spec.origin_W + spec.R_W0 * Vec3(c_M.x(), c_M.y(), 0);
    }
    m.bodies.push_back(b);
  }

  std::vector<std::vector<CellSideGeometry>> cell_sides(mesh.cells.size());
  for (const CellLink& l : mesh.links) {
    const BodyDef &L = m.bodies[l.left], &R = m.bodies[l.right];
    const Vec2 a = mesh.flat_m[l.a], b = mesh.flat_m[l.b];
    const double len = (b - a).norm();
    const Vec2 along = (b - a) / len, across(along.y(), -along.x());  // from L into R
    const Vec2 P = 0.5 * (a + b);
    const double dL = across.dot(P - *L.centroid_M), dR = across.dot(*R.centroid_M - P);
    const double h = L.fixed ? dR : R.fixed ? dL : dL + dR;
    ElementDef e;
    e.outer = l.left;
    e.inner = l.right;
    const Vec2 cL = P - *L.centroid_M, cR = P - *R.centroid_M;
    e.c_outer_B = Vec3(cL.x(), cL.y(), 0);
    e.c_inner_B = Vec3(cR.x(), cR.y(), 0);
    Mat3 F;  // side frame in the cells' (material) axes: x across, y along, z normal
    F << across.x(), along.x(), 0, across.y(), along.y(), 0, 0, 0, 1;
    e.R_inner_E = e.R_outer_F = F;
    e.K = plate_joint_stiffness(spec.youngs_modulus, spec.poisson_ratio, spec.thickness, len, h);
    e.C = spec.damping_time * e.K;
    e.name = fmt::format("side_c{}_c{}", l.left, l.right);
    if (l.pattern_edge >= 0) {
      const PatternEdge& pe = p.edges[l.pattern_edge];
      if (auto law = law_of(pe, spec, l.pattern_edge, source)) {
        // The sheet's fold angle turns the right cell about the side's +y: FOLD's valley-
        // positive angle with the opposite sign (docs/fold.md).
        const double fold = folded ? -measured_fold_angle(p, l.pattern_edge) : 0.0;
        m.creases.push_back(
            {std::make_shared<ScaledCreaseLaw>(law, len / spec.crease_law_length), fold});
        e.crease = static_cast<int>(m.creases.size()) - 1;
        e.name = fmt::format("crease{}_c{}_c{}", l.pattern_edge + 1, l.left, l.right);
      }
    }
    add_cell_sides(l, e, static_cast<int>(m.elements.size()), m, cell_sides);
    m.elements.push_back(e);
  }
  const double D = spec.youngs_modulus * std::pow(spec.thickness, 3) /
                   (12 * (1 - spec.poisson_ratio * spec.poisson_ratio));
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    if (m.bodies[c].fixed || cell_sides[c].empty()) continue;
    m.plate_cells.push_back(plate_cell_correction(static_cast<int>(c), segment_area(m.bodies[c]),
                                                  cell_sides[c], D, spec.poisson_ratio));
  }
  m.finalize_dofs();
  return m;
}

}  // namespace finseg

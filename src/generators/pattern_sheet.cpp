// Sheet from a crease pattern. Joint geometry: a cell side of length l whose cells' centroids
// lie d_L and d_R from its line stands for the strip of sheet between them, h = d_L + d_R;
// next to a clamped cell only the free side counts (the clamp is the side itself).
#include "generators/pattern_sheet.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.hpp"
#include "core/rigid_fit.hpp"
#include "core/text.hpp"
#include "elements/crease_law.hpp"
#include "elements/crease_laws/scaled.hpp"
#include "elements/crease_laws/series.hpp"
#include "elements/crease_laws/shifted.hpp"
#include "generators/plate_cell_fit.hpp"
#include "generators/plate_hessian.hpp"
#include "generators/sheet.hpp"
#include "patterns/pattern_checks.hpp"
#include "patterns/segment_mesh.hpp"

namespace finseg {
namespace {

constexpr double kSeamFlat = 1e-9;  // rad: a seam kinked less than this is flat (round-off)

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
  if (!(s.segment_size >= 0 && std::isfinite(s.segment_size))) {
    throw InputError(src, "discretisation.segment_size",
                     fmt::format("{}; allowed: > 0 m, or 0 for subdivisions", s.segment_size));
  }
  if (!(s.crease_refinement >= 1 && s.crease_refinement <= 100)) {
    throw InputError(src, "discretisation.crease_refinement",
                     fmt::format("{}; allowed range [1, 100]", s.crease_refinement));
  }
  std::vector<bool> listed(p.edges.size(), false);
  for (std::size_t k = 0; k < s.edge_laws.size(); ++k) {
    const std::string field = fmt::format("crease_laws[{}]", k);
    if (!s.edge_laws[k].law) throw InputError(src, field + ".law", "missing");
    for (int e : s.edge_laws[k].edges) {
      if (e < 0 || e >= static_cast<int>(p.edges.size())) {
        throw InputError(src, field + ".edges",
                         fmt::format("edge {} does not exist (0..{})", e, p.edges.size() - 1));
      }
      if (!is_crease(p.edges[e].assignment)) {
        throw InputError(src, field + ".edges",
                         fmt::format("edge {} is '{}': allowed M, V, F, U (a crease)", e,
                                     static_cast<char>(p.edges[e].assignment)));
      }
      if (listed[e]) {
        throw InputError(src, field + ".edges", fmt::format("edge {} listed twice", e));
      }
      listed[e] = true;
    }
  }
  std::vector<bool> soft(p.seams.size(), false);
  for (std::size_t k = 0; k < s.soft_seams.size(); ++k) {
    const std::string field = fmt::format("soft_seams[{}]", k);
    if (!(s.soft_seams[k].scale > 0 && s.soft_seams[k].scale <= 1)) {
      throw InputError(src, field + ".scale",
                       fmt::format("{}; allowed (0, 1]", s.soft_seams[k].scale));
    }
    for (int q : s.soft_seams[k].seams) {
      if (q < 0 || q >= static_cast<int>(p.seams.size())) {
        throw InputError(
            src, field + ".seams",
            p.seams.empty() ? fmt::format("seam {}: the pattern has no seams", q)
                            : fmt::format("seam {} does not exist (0..{})", q, p.seams.size() - 1));
      }
      if (soft[q]) throw InputError(src, field + ".seams", fmt::format("seam {} listed twice", q));
      soft[q] = true;
    }
  }
  for (int f : s.fixed_faces) {
    if (f < 0 || f >= static_cast<int>(p.faces.size())) {
      throw InputError(src, "fixtures.fixed_faces",
                       fmt::format("face {} does not exist (1..{})", f + 1, p.faces.size()));
    }
  }
  if (!(s.damping_time >= 0)) throw InputError(src, "damping_time", "must be >= 0 s");
  if (s.bending_rigidity) require_positive(*s.bending_rigidity, src, "bending_rigidity", "N m");
  if (!p.seams.empty() && !(s.start_folded && !p.vertices_folded_m.empty())) {
    throw InputError(src, "finseg:seams",
                     "a seam joins edges that lie apart on the flat sheet: the pattern must "
                     "start from its folded coordinates (a foldedForm frame; start: folded)");
  }
}

// Pose of cell `c` of `mesh` placed on the mesh's folded positions: the rigid motion taking
// its flat corners (x, y, 0) nearest to the folded ones (Kabsch), applied to its flat centroid
// c_M, then the spec's placement of the sheet (R_W0, origin_W).
void cell_pose(const SegmentMesh& mesh, std::size_t c, const Vec2& c_M,
               const PatternSheetSpec& spec, Mat3& R_WB, Vec3& p_W) {
  std::vector<Vec3> flat3, folded;
  for (int v : mesh.cells[c]) {
    flat3.emplace_back(mesh.flat_m[v].x(), mesh.flat_m[v].y(), 0);
    folded.push_back(mesh.folded_m[v]);
  }
  const RigidFit fit = best_rigid_fit(flat3, folded);
  R_WB = spec.R_W0 * fit.R;
  p_W = spec.origin_W + spec.R_W0 * fit.apply(Vec3(c_M.x(), c_M.y(), 0));
}

// The law of a crease side by its pattern edge (index `index`, -1 for a seam), or null for a
// plate joint.
std::shared_ptr<const CreaseLaw> law_of(const PatternEdge& e, int index, const PatternSheetSpec& s,
                                        const std::string& field, const std::string& src) {
  for (const EdgeCreaseLaw& l : s.edge_laws) {
    if (std::find(l.edges.begin(), l.edges.end(), index) != l.edges.end()) return l.law;
  }
  EdgeAssignment a = e.assignment;
  if ((a == EdgeAssignment::Flat || a == EdgeAssignment::Unassigned) && e.fold_angle != 0) {
    a = e.fold_angle > 0 ? EdgeAssignment::Valley : EdgeAssignment::Mountain;
  }
  if (a != EdgeAssignment::Mountain && a != EdgeAssignment::Valley) return nullptr;
  const bool mountain = a == EdgeAssignment::Mountain;
  const auto& law = mountain ? s.mountain_law : s.valley_law;
  if (!law) {
    throw InputError(
        src, field,
        fmt::format("a {} crease needs a {} crease law", mountain ? "mountain" : "valley",
                    mountain ? "mountain" : "valley"));
  }
  return law;
}

// Fold angle a pattern gives edge `e` in the sheet's convention (the opposite sign of FOLD's):
// edges_foldAngle, else the folded coordinates, else 0.
double pattern_fold_angle(const CreasePattern& p, int e) {
  if (p.has_fold_angles) return -p.edges[e].fold_angle;
  return p.vertices_folded_m.empty() ? 0.0 : -measured_fold_angle(p, e);
}

// The crease on a side of pattern edge `pe` whose target fold angle is `target` (sheet
// convention): its share of the law, moved to rest at the target when asked; direction from
// the assignment (mountain: +1).
CreaseDef pattern_crease(const PatternEdge& pe, double target, std::shared_ptr<const CreaseLaw> law,
                         const PatternSheetSpec& spec, double len, double initial) {
  CreaseDef c;
  c.initial_fold_angle = initial;
  c.target_fold_angle = target;
  const EdgeAssignment a = pe.assignment;
  c.direction = a == EdgeAssignment::Mountain ? 1.0
                : a == EdgeAssignment::Valley ? -1.0
                                              : (c.target_fold_angle < 0 ? -1.0 : 1.0);
  c.law = law;  // law_direction reads the law's angle convention
  if (spec.laws_rest_at_pattern) {
    law = std::make_shared<ShiftedCreaseLaw>(law, law_direction(c) * c.target_fold_angle);
  }
  c.law = std::make_shared<ScaledCreaseLaw>(law, len / spec.crease_law_length);
  return c;
}

// A cell side in one cell's material coordinates: its midpoint, the unit vector along it
// (a -> b of the link) and across it (from the link's left cell into its right), and the
// side frame (x across, y along, z the normal) in the cell's axes.
struct SideInCell {
  Vec2 P, along, across;
  Mat3 frame() const {
    Mat3 F;
    F << across.x(), along.x(), 0, across.y(), along.y(), 0, 0, 0, 1;
    return F;
  }
};

SideInCell side_in_cell(const Vec2& a, const Vec2& b) {
  const Vec2 along = (b - a).normalized();
  return {0.5 * (a + b), along, Vec2(along.y(), -along.x())};
}

// The sides of a plate joint as the two cells' curvature fits see them: the vector to the
// neighbour's centroid, or, next to a clamped cell, to the foot point on the side (the clamp
// holds the rotation there), whose joint is then the free cell's alone. Across a seam the
// neighbour is unrolled next to the cell: its centroid's offset from the side, in the side's
// frame, is carried over to the cell's copy of the side.
void add_cell_sides(const CellLink& l, const std::array<SideInCell, 2>& sides, const ElementDef& e,
                    int element, const Model& m, bool crease_bends,
                    std::vector<std::vector<CellSideGeometry>>& cell_sides) {
  for (const int side : {0, 1}) {
    const int c = side == 0 ? l.left : l.right, o = side == 0 ? l.right : l.left;
    const SideInCell &mine = sides[side], &theirs = sides[1 - side];
    const Vec2 c_M = *m.bodies[c].centroid_M, o_M = *m.bodies[o].centroid_M;
    CellSideGeometry g;
    g.side = {element, side == 0 ? e.R_outer_F : e.R_inner_E, side == 0 ? 1.0 : -1.0};
    g.weight = e.K[3];  // twist; bending K[4] is the same on plate joints
    g.crease = e.crease >= 0;
    g.crease_bends = g.crease && crease_bends;
    g.across_M = mine.across;
    const double own = std::abs(mine.across.dot(mine.P - c_M)),
                 other = std::abs(theirs.across.dot(o_M - theirs.P));
    g.strip_share = own / (own + other);
    if (m.bodies[o].fixed) {
      g.d_M = mine.across.dot(mine.P - c_M) * mine.across;
      g.share = g.strip_share = 1;
    } else if (l.seam < 0) {
      g.d_M = o_M - c_M;
    } else {
      const Vec2 r = o_M - theirs.P;
      g.d_M = mine.P - c_M + r.dot(theirs.across) * mine.across + r.dot(theirs.along) * mine.along;
    }
    cell_sides[c].push_back(g);
  }
}

// A free cell's sides for the membrane correction: the curvature correction's geometry and
// the joints' T1 (across) and T2 (along) springs.
std::vector<MembraneSideGeometry> membrane_sides(const Model& m,
                                                 const std::vector<CellSideGeometry>& sides) {
  std::vector<MembraneSideGeometry> out;
  for (const CellSideGeometry& g : sides) {
    const ElementDef& e = m.elements[g.side.element];
    const Vec2 a = g.across_M, t(-a.y(), a.x());
    MembraneSideGeometry ms;
    ms.side = g.side;
    ms.d_M = g.d_M;
    ms.share = g.strip_share;
    ms.K_M = e.K[0] * a * a.transpose() + e.K[1] * t * t.transpose();
    out.push_back(ms);
  }
  return out;
}

bool has_membrane_correction(const Model& m, const std::vector<CellSideGeometry>& sides, int c) {
  return !m.bodies[c].fixed && !sides.empty();
}

// On skewed cells the joints see the strain along their sides too and can store more than
// plane stress in some strain: the in-plane springs of each joint are scaled down by the
// larger excess of its two cells, so that no correction has to be negative (convexity).
void limit_joints_to_plane_stress(Model& m,
                                  const std::vector<std::vector<CellSideGeometry>>& cell_sides,
                                  const PatternSheetSpec& spec) {
  std::vector<double> scale(m.elements.size(), 1.0);
  for (std::size_t c = 0; c < cell_sides.size(); ++c) {
    if (!has_membrane_correction(m, cell_sides[c], static_cast<int>(c))) continue;
    const double excess =
        membrane_joint_excess(segment_area(m.bodies[c]), membrane_sides(m, cell_sides[c]),
                              spec.youngs_modulus, spec.poisson_ratio, spec.thickness);
    if (excess <= 1 + 1e-9) continue;  // rectangles: 1 up to round-off
    for (const CellSideGeometry& g : cell_sides[c]) {
      scale[g.side.element] = std::min(scale[g.side.element], 1 / excess);
    }
  }
  for (std::size_t k = 0; k < m.elements.size(); ++k) {
    for (int i : {0, 1}) {
      m.elements[k].K[i] *= scale[k];
      m.elements[k].C[i] *= scale[k];
    }
  }
}

// The free cells' membrane corrections (docs/stiffness.md, "Cell membrane correction").
std::vector<MembraneCellDef> membrane_cells(
    const Model& m, const std::vector<std::vector<CellSideGeometry>>& cell_sides,
    const PatternSheetSpec& spec) {
  std::vector<MembraneCellDef> cells;
  for (std::size_t c = 0; c < cell_sides.size(); ++c) {
    if (!has_membrane_correction(m, cell_sides[c], static_cast<int>(c))) continue;
    cells.push_back(membrane_cell_correction(static_cast<int>(c), segment_area(m.bodies[c]),
                                             membrane_sides(m, cell_sides[c]), spec.youngs_modulus,
                                             spec.poisson_ratio, spec.thickness));
  }
  return cells;
}

// PatternSheetSpec::hessian_bending, unset: on where the joints and corrections do not converge
// (triangles), off on quadrilaterals (where they are more accurate).
bool uses_hessian_bending(const PatternSheetSpec& s, const SegmentMesh& mesh) {
  if (s.hessian_bending) return *s.hessian_bending;
  return std::any_of(mesh.cells.begin(), mesh.cells.end(),
                     [](const std::vector<int>& c) { return c.size() == 3; });
}

// Where the pattern's further folded forms put each body's centroid (ShapeDef): the faces
// cut as for the model's bodies, each cell placed on the shape's vertices by the same fit as
// its start pose.
std::vector<ShapeDef> pattern_shapes(const CreasePattern& p, const PatternSheetSpec& spec,
                                     const Model& m) {
  std::vector<ShapeDef> out;
  for (const PatternShape& shape : p.shapes) {
    CreasePattern placed = p;
    placed.vertices_folded_m = shape.vertices_m;
    placed.shapes.clear();
    const SegmentMesh cut = subdivide_pattern(placed, subdivision_of(spec));
    ShapeDef d{shape.title, std::vector<Vec3>(cut.cells.size()),
               std::vector<Mat3>(cut.cells.size())};
    for (std::size_t c = 0; c < cut.cells.size(); ++c) {
      cell_pose(cut, c, *m.bodies[c].centroid_M, spec, d.R_WB[c], d.p_W[c]);
    }
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace

Vec6 plate_joint_stiffness(double E, double nu, double t, double l, double h) {
  const double G = E / (2 * (1 + nu)), D = E * t * t * t / (12 * (1 - nu * nu));
  Vec6 k;
  // Twist and bending both D: the joints then store D/2 kappa:kappa, Kirchhoff's energy less
  // the null Lagrangian D nu det(kappa) (docs/stiffness.md). T1 = 2 G t l / h, the deviatoric
  // part of plane stress, so that what the cells' membrane corrections add (the volumetric
  // part) is never negative.
  k << 2 * G * t * l / h, G * t * l / h, kShearCorrection * G * t * l / h, D * l / h, D * l / h,
      E * t * l * l * l / (12 * h);
  return k;
}

Subdivision subdivision_of(const PatternSheetSpec& spec) {
  Subdivision cut;
  cut.n = spec.subdivisions;
  cut.segment_size = spec.segment_size;
  cut.crease_refinement = spec.crease_refinement;
  cut.triangles = spec.triangle_cells;
  return cut;
}

Model build_pattern_model(const CreasePattern& p, const PatternSheetSpec& spec,
                          const std::string& source) {
  validate_spec(spec, p, source);
  const SegmentMesh mesh = subdivide_pattern(p, subdivision_of(spec));
  const bool hessian = uses_hessian_bending(spec, mesh);
  // The cell Hessian carries the sheet's bending next to a crease itself: no series spring.
  const bool series = spec.crease_bending_in_series && !hessian;
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
    for (int v : mesh.cells[c]) flat.push_back(mesh.flat_m[v]);
    const double mass = spec.density * polygon_area(flat) * spec.thickness;
    const Vec2 c_M = set_prism(b, flat, spec.thickness, mass);
    b.centroid_M = c_M;
    b.panel = mesh.cell_face[c];
    b.fixed = std::find(spec.fixed_faces.begin(), spec.fixed_faces.end(), b.panel) !=
              spec.fixed_faces.end();
    b.name = fmt::format("face{}_cell{}", b.panel + 1, c);
    if (folded) {
      cell_pose(mesh, c, c_M, spec, b.R0_WB, b.p0_W);
    } else {
      b.R0_WB = spec.R_W0;
      b.p0_W = spec.origin_W + spec.R_W0 * Vec3(c_M.x(), c_M.y(), 0);
    }
    m.bodies.push_back(b);
  }
  m.shapes = pattern_shapes(p, spec, m);

  std::vector<std::vector<CellSideGeometry>> cell_sides(mesh.cells.size());
  std::vector<int> link_element;
  std::vector<double> seam_scale(p.seams.size(), 1.0);  // SoftSeams
  for (const SoftSeams& q : spec.soft_seams) {
    for (int k : q.seams) seam_scale[k] = q.scale;
  }
  for (const CellLink& l : mesh.links) {
    const BodyDef &L = m.bodies[l.left], &R = m.bodies[l.right];
    // Each cell's own copy of the side (two copies across a seam, else the same side).
    const std::array<SideInCell, 2> sides{
        side_in_cell(mesh.flat_m[l.a], mesh.flat_m[l.b]),
        side_in_cell(mesh.flat_m[l.a_right], mesh.flat_m[l.b_right])};
    const double len = (mesh.flat_m[l.b] - mesh.flat_m[l.a]).norm();
    const double dL = sides[0].across.dot(sides[0].P - *L.centroid_M),
                 dR = sides[1].across.dot(*R.centroid_M - sides[1].P);
    const double h = L.fixed ? dR : R.fixed ? dL : dL + dR;
    ElementDef e;
    e.outer = l.left;
    e.inner = l.right;
    const Vec2 cL = sides[0].P - *L.centroid_M, cR = sides[1].P - *R.centroid_M;
    e.c_outer_B = Vec3(cL.x(), cL.y(), 0);
    e.c_inner_B = Vec3(cR.x(), cR.y(), 0);
    e.R_outer_F = sides[0].frame();
    e.R_inner_E = sides[1].frame();
    e.K = plate_joint_stiffness(spec.youngs_modulus, spec.poisson_ratio, spec.thickness, len, h);
    if (spec.bending_rigidity) e.K[3] = e.K[4] = *spec.bending_rigidity * len / h;
    const bool soft = l.seam >= 0 && seam_scale[l.seam] < 1;
    if (soft) {
      for (int i : {0, 1, 5}) e.K[i] *= seam_scale[l.seam];
    }
    e.C = spec.damping_time * e.K;
    e.name = l.seam < 0 ? fmt::format("side_c{}_c{}", l.left, l.right)
                        : fmt::format("seam{}_c{}_c{}", l.seam + 1, l.left, l.right);
    // A seam is a crease when the folded sheet kinks across it (as an F edge with that fold
    // angle), else a plate joint.
    PatternEdge seam_edge;
    if (l.seam >= 0) {
      seam_edge.assignment = EdgeAssignment::Flat;
      seam_edge.fold_angle = folded ? measured_seam_fold_angle(p, l.seam) : 0.0;
      if (std::abs(seam_edge.fold_angle) < kSeamFlat) seam_edge.fold_angle = 0;
    }
    if (l.pattern_edge >= 0) {
      const PatternEdge& pe = l.seam >= 0 ? seam_edge : p.edges[l.pattern_edge];
      const std::string field = l.seam >= 0 ? fmt::format("finseg:seams[{}]", l.seam)
                                            : fmt::format("edges_assignment[{}]", l.pattern_edge);
      if (auto law = law_of(pe, l.seam >= 0 ? -1 : l.pattern_edge, spec, field, source)) {
        // The sheet's fold angle turns the right cell about the side's +y: FOLD's valley-
        // positive angle with the opposite sign (docs/fold.md).
        const double fold = !folded       ? 0.0
                            : l.seam >= 0 ? -seam_edge.fold_angle
                                          : -measured_fold_angle(p, l.pattern_edge);
        const double target =
            l.seam >= 0 ? -seam_edge.fold_angle : pattern_fold_angle(p, l.pattern_edge);
        m.creases.push_back(pattern_crease(pe, target, law, spec, len, fold));
        m.creases.back().line =
            l.seam >= 0 ? fmt::format("seam{}", l.seam) : fmt::format("edge{}", l.pattern_edge);
        e.crease = static_cast<int>(m.creases.size()) - 1;
        if (l.seam < 0) {
          e.name = fmt::format("crease{}_c{}_c{}", l.pattern_edge + 1, l.left, l.right);
        }
      }
    }
    if (e.crease >= 0 && series) {
      // The plate joint's bending spring (unused by the crease element) in series with the law.
      CreaseDef& c = m.creases[e.crease];
      c.law = std::make_shared<SeriesCreaseLaw>(c.law, e.K[4]);
    }
    if (!soft) {
      add_cell_sides(l, sides, e, static_cast<int>(m.elements.size()), m, series, cell_sides);
    }
    link_element.push_back(static_cast<int>(m.elements.size()));
    m.elements.push_back(e);
  }
  const double D =
      spec.bending_rigidity.value_or(spec.youngs_modulus * std::pow(spec.thickness, 3) /
                                     (12 * (1 - spec.poisson_ratio * spec.poisson_ratio)));
  limit_joints_to_plane_stress(m, cell_sides, spec);
  m.membrane_cells = membrane_cells(m, cell_sides, spec);
  if (hessian) {
    m.plate_cells = plate_hessian_cells(mesh, m, link_element, D, spec.poisson_ratio);
    for (ElementDef& e : m.elements) {
      // The cells' energy holds the plate's bending and twist, the slope along a supported
      // side included (a hinge to a fixed cell); a crease between free cells keeps its twist.
      const bool support = m.bodies[e.inner].fixed || m.bodies[e.outer].fixed;
      if (e.crease < 0 || support) e.K[3] = e.C[3] = 0;
      if (e.crease < 0) e.K[4] = e.C[4] = 0;
    }
    m.finalize_dofs();
    return m;
  }
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    if (m.bodies[c].fixed || cell_sides[c].empty()) continue;
    m.plate_cells.push_back(plate_cell_correction(static_cast<int>(c), segment_area(m.bodies[c]),
                                                  cell_sides[c], D, spec.poisson_ratio));
  }
  m.finalize_dofs();
  return m;
}

}  // namespace finseg

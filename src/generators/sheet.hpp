// Sheet generator: cuts a rectangular sheet (optionally folded along crease lines across
// its length) into rigid segments joined by force elements. docs/stiffness.md gives the
// stiffness formulas and the joint placement.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "model/model.hpp"

namespace finseg {

class CreaseLaw;

/// Timoshenko's shear correction of a rectangular section (5/6): the joints' transverse shear
/// springs (docs/stiffness.md).
inline constexpr double kShearCorrection = 5.0 / 6.0;

/// A fold line across the sheet at material coordinate s (m from the start).
struct FoldSpec {
  double s = 0;      ///< m
  double angle = 0;  ///< signed initial fold angle, rad: rotation of the next panel relative
                     ///< to the previous one about the sheet's +y axis
  std::shared_ptr<const CreaseLaw> law;  ///< moment about the crease line
};

/// Optional identified values that replace the material-derived ones (whole sheet width).
struct StiffnessOverride {
  std::optional<double> bending_rigidity;  ///< EI about y, N m^2
  std::optional<double> twist_rigidity;    ///< GJ about x, N m^2
  std::optional<double> inplane_rigidity;  ///< EI about z, N m^2
  std::optional<double> axial_rigidity;    ///< EA, N
  std::optional<double> shear_rigidity;    ///< kappa G A, N
};

/// Everything needed to generate a sheet model. Lengths in m, modulus in Pa, density kg/m^3.
struct SheetSpec {
  double length = 0.2, width = 0.04, thickness = 1e-4;
  double youngs_modulus = 3e9, poisson_ratio = 0.3, density = 800;
  int cells_along = 16;  ///< per panel when there are folds, else for the whole length
  int cells_across = 1;  ///< rows across; > 1 makes the sheet a plate (build_sheet_model)
  /// Optional relative cell lengths along s (one per cell, any positive scale); empty:
  /// uniform, or graded towards the creases by `crease_refinement`.
  std::vector<double> cell_weights;
  double crease_refinement = 1.0;  ///< ratio of the middle cell to the cell at a crease
  std::vector<FoldSpec> folds;     ///< sorted by s, strictly inside (0, length)
  std::vector<int> fixed_panels;   ///< panels whose bodies are clamped (0-based)
  bool clamp_start = false;        ///< clamp the sheet at s = 0 (cantilever root)
  double damping_time = 0;         ///< stiffness-proportional damping C = damping_time * K, s
  StiffnessOverride overrides;
  Vec3 origin_W = Vec3::Zero();  ///< world position of material point (0, 0)
  Mat3 R_W0 = Mat3::Identity();  ///< orientation of the first panel (x along s, y across)
};

/// Cell boundaries along s of the panel [a, b] (m, a and b included): uniform, by
/// `cell_weights`, or graded towards the panel's creases (crease_a, crease_b) by
/// `crease_refinement`. The bending joints sit at the cells' centres.
std::vector<double> panel_cell_bounds(const SheetSpec& spec, double a, double b, bool crease_a,
                                      bool crease_b);

/// Where each panel (the sheet between folds) starts along s, m: 0, the folds' s, and the
/// length last (panels + 1 entries).
std::vector<double> panel_starts(const SheetSpec& spec);

/// A panel's initial frame: the world position of its start (s at panel_starts, y = 0) and
/// its orientation (x along s, y across), the folds' rotations about y chained from R_W0.
struct PanelFrame {
  Vec3 o_W = Vec3::Zero();
  Mat3 R_W = Mat3::Identity();
};
std::vector<PanelFrame> panel_frames(const SheetSpec& spec);

/// Builds bodies, elements and initial poses. One row across: the strip of beam joints at
/// the cells' centres (the paper's model); more rows: a plate through the pattern path
/// (build_sheet_pattern_model), whose stiffness overrides are limited to the bending
/// rigidity. Throws InputError on impossible specs.
Model build_sheet_model(const SheetSpec& spec);

/// A square 0.2 m sheet of 80 g/m^2 paper (0.1 mm, 3 GPa, nu 0.3, 800 kg/m^3) cut into
/// n x n cells, clamped along its start edge and sagging under gravity: the sparse solvers'
/// scale case (tests/test_static_sheet.cpp, bench/bench_sheet_scale.cpp).
Model clamped_paper_sheet(int n);

/// Body containing material point (s, y) and that point's coordinates in the body frame.
struct MaterialPoint {
  int body = -1;
  Vec3 r_B = Vec3::Zero();
};
MaterialPoint locate_material_point(const Model& model, double s, double y);

}  // namespace finseg

// A sheet cut from a crease pattern (docs/stiffness.md, "Sheets from crease patterns"): every
// face divided into cells (patterns/segment_mesh.hpp), one polygonal segment per cell, one
// force element on every side two cells share, its frame aligned with that side. A side on
// a mountain or valley crease carries the crease law; every other side the plate's joint
// stiffness.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "model/model.hpp"
#include "patterns/crease_pattern.hpp"
#include "patterns/segment_mesh.hpp"

namespace finseg {

class CreaseLaw;

/// A crease law for a list of pattern edges (M, V, F or U; 0-based, as in the FOLD arrays).
struct EdgeCreaseLaw {
  std::vector<int> edges;
  std::shared_ptr<const CreaseLaw> law;
};

/// Seams (0-based indices into CreasePattern::seams) whose joints are made soft in the plane:
/// each cell side across them has its in-plane springs (stretch T1, shear T2, in-plane turn
/// theta3) scaled by `scale`, and is left out of its cells' membrane corrections, which would
/// add the stiffness back. For a compliant band (a pleated or elastic gusset) that lets a
/// rigid cap's edge slide against the tube end it closes (docs/fold.md, "The Miura tube").
struct SoftSeams {
  std::vector<int> seams;
  double scale = 1;  ///< (0, 1]
};

/// Material, discretisation and creases of a sheet cut from a pattern. SI units.
struct PatternSheetSpec {
  double thickness = 1e-4, youngs_modulus = 3e9, poisson_ratio = 0.3, density = 800;
  /// Plate bending rigidity D (N m) in place of E t^3 / (12 (1 - nu^2)), e.g. a laminate's:
  /// the joints' bending and twist springs and the cell corrections use it; stretching and
  /// shear keep E and t.
  std::optional<double> bending_rigidity;
  int subdivisions = 1;  ///< each face into n x n cells, 1..64 (when segment_size is 0)
  /// m; > 0: cells of at most this side along every pattern edge, in place of subdivisions
  /// (patterns/segment_mesh.hpp, Subdivision).
  double segment_size = 0;
  double crease_refinement = 1;  ///< >= 1: cells graded towards folded creases (Subdivision)
  /// True: quadrilateral cells cut into four triangles each (Subdivision::triangles), which
  /// then bend by the cell Hessian (hessian_bending)
  bool triangle_cells = false;
  /// Crease laws by assignment (M, V; F and U creases use them by the sign of their fold
  /// angle when given, else they are plate joints). Each law's moment is for a crease of
  /// `crease_law_length` (m); a cell side of length l carries the share l / that length.
  std::shared_ptr<const CreaseLaw> mountain_law, valley_law;
  /// Laws for chosen pattern edges (0-based), before the assignment's: e.g. a crease folded
  /// harder than the others, or an F edge made a crease. Each edge at most once.
  std::vector<EdgeCreaseLaw> edge_laws;
  std::vector<SoftSeams> soft_seams;  ///< seams with soft in-plane joints, each at most once
  double crease_law_length = 1.0;
  /// True: each crease's law is shifted so that it rests at the crease's own fold angle in
  /// the pattern (edges_foldAngle, else the folded coordinates); false: the law's own rest.
  bool laws_rest_at_pattern = false;
  /// True: each crease side carries its law in series with the plate's bending spring across
  /// the side (`D l / h`, as a plate joint's), and the cells next to it count that side's
  /// bending in their correction: the crease cells' bending next to the fold, which rigid
  /// cells miss, converges at second order (docs/stiffness.md, "Creases on cell sides").
  /// False: the law alone (first order at creases; kept for comparisons).
  bool crease_bending_in_series = true;
  /// Bending by the consistent cell Hessian (generators/plate_hessian.hpp) in place of the
  /// plate joints' bending and twist springs and the cell corrections: it converges on
  /// triangulated segmentations, where the corrections do not (docs/stiffness.md, "Triangular
  /// cells"). Unset: on when some cell is a triangle, else off.
  std::optional<bool> hessian_bending;
  std::vector<int> fixed_faces;  ///< pattern faces (0-based) clamped in place
  bool start_folded = true;      ///< start from the pattern's folded coordinates if any
  double damping_time = 0;       ///< stiffness-proportional damping C = damping_time K, s
  Vec3 origin_W = Vec3::Zero();  ///< world position of the pattern's origin, m
  Mat3 R_W0 = Mat3::Identity();  ///< orientation of the flat pattern's axes
};

/// How `spec` cuts the pattern's faces (subdivisions or segment size, grading, triangles).
Subdivision subdivision_of(const PatternSheetSpec& spec);

/// Builds bodies, elements and initial poses from a validated pattern (validate_pattern).
/// Throws InputError (naming `source`) on an impossible spec or a crease without a law.
Model build_pattern_model(const CreasePattern& pattern, const PatternSheetSpec& spec,
                          const std::string& source = "<api>");

/// Stiffness of a plate joint (docs/stiffness.md): a side of length l (m) between cells
/// whose centroids lie h (m) apart across it: T1..T3 (N/m), theta1..3 (N m/rad) in the
/// side's frame (x across the side, y along it, z the normal).
Vec6 plate_joint_stiffness(double E, double nu, double t, double l, double h);

}  // namespace finseg

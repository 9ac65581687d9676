// The paper's typical model (section 4): a strip folded in a zigzag into equal panels, two
// panels clamped, one crease pulled open through a force gauge. DESIGN.md section 1 states
// our reading of the geometry; every choice of that reading is a parameter here.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "generators/sheet.hpp"
#include "model/model.hpp"

namespace finseg {

class CreaseLaw;

/// Contact settings of the paper strip (docs/zigzag.md, "Contact"): IMPACT normal law
/// (docs/contact.md's 80 g/m^2 paper values) and elastic-anchor friction for the static pull.
ContactDef zigzag_contact_defaults();

/// Contact groups of the paper's model (section 2.3): each panel with its neighbours,
/// panels (1)-(2), (2)-(3), ... (0-based indices).
std::vector<std::vector<int>> adjacent_panel_groups(int panels);

/// Parameters of the zigzag strip and its pull test. SI units; angles in rad.
struct ZigzagSpec {
  double length = 0.480, width = 0.040, thickness = 1.0e-4;  ///< m (paper: 480 x 40 mm)
  double youngs_modulus = 4.0e9, poisson_ratio = 0.3;        ///< Pa, -
  double density = 800;                                      ///< kg/m^3 (80 g/m^2 at 0.1 mm)
  int panels = 6;
  double fold_angle = 80 * kDegToRad;  ///< angle between a panel and the horizontal
  /// 'P' (peak) or 'V' (valley) for each crease, first to last; empty: alternate so that
  /// the first crease is a peak.
  std::string pattern;
  int segments_per_panel = 8;
  int segments_across = 1;
  double crease_refinement = 2.0;       ///< middle cell / cell next to a crease
  std::vector<int> fixed_panels{1, 6};  ///< 1-based
  int pulled_crease = 3;                ///< 1-based (between panels 3 and 4)
  Vec3 pull_direction_W = Vec3::UnitZ();
  double pull_step = 2e-3;       ///< m per equilibrium (one turn of the slide)
  double pull_travel = 0;        ///< m; 0: 90 % of the travel that straightens the panels
  double gauge_stiffness = 1e4;  ///< N/m of the push-pull gauge
  /// Crease law of each crease (size panels-1) or one for all (size 1).
  std::vector<std::shared_ptr<const CreaseLaw>> crease_laws;
  StiffnessOverride overrides;  ///< e.g. the taped (stiffened) panels' bending rigidity
  bool gravity = true;
  bool contact = true;  ///< contact between panels on/off
  /// Used when `contact`; empty `groups` means adjacent_panel_groups(panels).
  ContactDef contact_settings = zigzag_contact_defaults();
  double damping_time = 0;
};

/// Checks the spec; throws InputError naming the field and the allowed range.
void validate(const ZigzagSpec& spec, const std::string& source = "<api>");

/// The sheet (panels, creases, fixtures) of the zigzag in its folded initial state: panel 1
/// rises from the origin at fold_angle, peaks and valleys alternate per the pattern.
SheetSpec zigzag_sheet(const ZigzagSpec& spec);

/// Signed fold angle of crease k (0-based) in the initial state, rad.
double zigzag_fold_angle(const ZigzagSpec& spec, int k);

/// Lift of the pulled crease (along the pull) at which the panels between it and the nearest
/// fixed panel form a straight line: `links a sin(fold_angle)` (links panels of length a);
/// the strip is fully deployed there (the deployment peak's window ends there), m.
double zigzag_deployed_travel(const ZigzagSpec& spec);

/// Default pull travel: 90 % of the vertical travel of the pulled crease that would bring
/// the panels between it and the nearest fixed panels into a straight line.
double zigzag_default_travel(const ZigzagSpec& spec);

/// The whole model: sheet, gravity, the gauge drive at the pulled crease, probes `gauge`,
/// `reaction` and `energy`, and contact between panels.
Model build_zigzag_model(const ZigzagSpec& spec);

/// The test rig of build_zigzag_model on a strip model `m` of `spec` (material coordinates
/// s along, y across from the strip's corner; panels numbered as the spec's): gravity,
/// contact, the gauge drive at the pulled crease and the probes. Validates `m`.
void add_zigzag_rig(Model& m, const ZigzagSpec& spec);

}  // namespace finseg

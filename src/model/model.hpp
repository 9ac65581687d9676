// Model: what the structure is (bodies, force elements, fixtures, loads, drives, probes).
// Immutable once built, plain arrays like MuJoCo's mjModel. Where it is now lives in State.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/chamber_def.hpp"
#include "model/contact_def.hpp"
#include "model/crease_def.hpp"
#include "model/plate_cell_def.hpp"
#include "model/pressure_def.hpp"
#include "model/segment_shape.hpp"

namespace finseg {

/// A rigid segment: a convex polygon of the sheet with the sheet's thickness (a prism).
/// Body frame B: origin at the centroid, z along the normal; x and y are the sheet's
/// material axes when the body was cut from a sheet (along the length and across for a strip).
struct BodyDef {
  std::string name;
  double mass = 0;                ///< kg
  Mat3 J_B = Mat3::Zero();        ///< inertia about the centroid in frame B, kg m^2
  Outline outline_B;              ///< mid-surface polygon in B (z = 0), convex, counter-clockwise
                                  ///< about +z_B, centroid at the origin, m
  double thickness = 0;           ///< m
  Vec3 p0_W = Vec3::Zero();       ///< initial centroid position, m
  Mat3 R0_WB = Mat3::Identity();  ///< initial orientation
  bool fixed = false;             ///< clamped by a fixture: never moves
  /// Centroid on the flat (unfolded) sheet, material coordinates in m, when the body was cut
  /// from a sheet: its outline there is centroid_M + outline_B (contact rules, probes).
  std::optional<Vec2> centroid_M;
  int panel = 0;  ///< fold panel (part of the sheet between two creases), 0-based
};

/// Six-DOF spring-damper force element E_k between inner body e+(k) and outer body e-(k)
/// (paper eqs. 5-7). Its frame E is fixed to the inner body and F to the outer body; they
/// coincide in the rest (flat-sheet) configuration. Translations and rotations are
/// measured in F: z_F = R_WF^T (P+ - P-) - z0_F, theta = log(R_FE).
struct ElementDef {
  int inner = -1;                     ///< e+(k): body carrying P+
  int outer = -1;                     ///< e-(k): body carrying P-
  Vec3 c_inner_B = Vec3::Zero();      ///< lever vector c_{e+(k)k}: centroid -> P+, inner frame
  Vec3 c_outer_B = Vec3::Zero();      ///< lever vector c_{e-(k)k}: centroid -> P-, outer frame
  Mat3 R_inner_E = Mat3::Identity();  ///< element frame E in the inner body's frame
  Mat3 R_outer_F = Mat3::Identity();  ///< element frame F in the outer body's frame
  Vec6 K = Vec6::Zero();              ///< diagonal stiffness: T1..T3 in N/m, theta1..3 in N m/rad
  Vec6 C = Vec6::Zero();              ///< diagonal damping: N s/m and N m s/rad
  Vec3 z0_F = Vec3::Zero();           ///< rest offset of P+ from P- in F, m
  int crease = -1;  ///< index into Model::creases (rotation about F's y from a crease law)
  std::string name;
};

/// A dead or follower point load on one body (scaled by State::load_scale).
struct LoadDef {
  int body = -1;
  Vec3 point_B = Vec3::Zero();  ///< application point in the body frame, m
  Vec3 force = Vec3::Zero();    ///< N, world frame (dead) or body frame (follower)
  Vec3 moment = Vec3::Zero();   ///< N m, same frame rule as force
  bool follower = false;
};

/// Displacement drive with a force gauge: the point `point_B` of `body` is pulled towards
/// the target start_W + s * direction_W through a spring of stiffness `stiffness` (the
/// push-pull gauge). s is the drive displacement, held in State::drive_s.
struct DriveDef {
  std::string name;
  int body = -1;
  Vec3 point_B = Vec3::Zero();
  Vec3 start_W = Vec3::Zero();       ///< target at s = 0 (the point's initial position), m
  Vec3 direction_W = Vec3::UnitZ();  ///< unit pull direction
  double stiffness = 1e3;            ///< gauge stiffness along direction_W, N/m
  double damping = 0;                ///< gauge damping along direction_W, N s/m
  /// Stiffness and damping across direction_W over those along it: 1 an isotropic gauge, 0 a
  /// long string that pulls along direction_W and lets the point move sideways.
  double lateral_ratio = 1;
  /// A string: the gauge pulls along direction_W but never holds the point back; where its
  /// force along direction_W would, it is slack there (the lateral part stays).
  bool pull_only = false;
  /// Pull-only: the band of the two-way pull u (N) over which the tension eases in, (u + b)^2 /
  /// (4 b) for |u| < b, so that Newton meets no kink; 0: max(0, u).
  double toe_force = 0;
  double speed = 0;   ///< dynamic solvers: ds/dt, m/s
  double travel = 0;  ///< total drive displacement, m
  double step = 0;    ///< quasi-static solver: displacement increment, m
  /// Drive displacement at which the structure is fully deployed (end of the window of the
  /// deployment peak, probes/deployment_peak.hpp), m; 0: not known, the whole travel.
  double deployed_at = 0;
};

/// Kinds of recorded tables. Chamber tables are made by the recorder, one per chamber (not
/// a scene probe type).
enum class ProbeKind {
  Point,
  Drive,
  Reaction,
  Energy,
  Contact,
  Crease,
  Element,
  Pose,
  Chamber,
  Shape,
  Unfolding
};

/// Something a user wants recorded over the run (one CSV per probe).
struct ProbeDef {
  std::string name;
  ProbeKind kind = ProbeKind::Point;
  int body = -1;                ///< Point: body carrying the point; Pose: the body
  Vec3 point_B = Vec3::Zero();  ///< Point: position in the body frame
  /// Drive: the drives whose gauges it records; several (moving alike) are summed.
  std::vector<int> drives;
  bool pairs = false;  ///< Contact: also record each touching pair's forces
  int crease = -1;     ///< Crease: index into Model::creases
  int element = -1;    ///< Element: index into Model::elements
  int shape = -1;      ///< Shape, Unfolding: index into Model::shapes (Unfolding: -1 = flat)
};

/// A named placement of the whole structure (a pattern's further folded frame, e.g. its
/// deployed form): where it puts every body's centroid, m. A shape probe measures how far
/// the run's bodies are from it after the best rigid fit.
struct ShapeDef {
  std::string name;
  std::vector<Vec3> p_W;   ///< one per body, the bodies' order
  std::vector<Mat3> R_WB;  ///< one per body: its orientation there (the creases' angles)
};

/// Description of the flat sheet a model was cut from (used by writers and probes).
struct SheetInfo {
  double length = 0, width = 0, thickness = 0;  ///< m
  /// Lower-left corner of the flat sheet's bounding box in material coordinates, m: the
  /// sheet spans [origin, origin + (length, width)] ((0, 0) for the generators' strips).
  Vec2 origin_M = Vec2::Zero();
  double youngs_modulus = 0;  ///< Pa
  double poisson_ratio = 0;
  double density = 0;  ///< kg/m^3
};

/// The whole structure. Built by generators or the scene reader; never mutated by solvers.
struct Model {
  std::string source = "<api>";  ///< file it came from, for messages
  SheetInfo sheet;
  std::vector<BodyDef> bodies;
  std::vector<ElementDef> elements;
  /// Curvature corrections of plate cells (sheets cut from patterns; docs/stiffness.md).
  std::vector<PlateCellDef> plate_cells;
  std::vector<MembraneCellDef> membrane_cells;  ///< in-plane corrections (Poisson, shear)
  std::vector<CreaseDef> creases;
  std::vector<LoadDef> loads;
  std::vector<DriveDef> drives;
  std::vector<ProbeDef> probes;
  std::vector<ShapeDef> shapes;        ///< target placements a shape probe can name
  std::vector<PressureDef> pressures;  ///< pressure loads on segment faces
  std::vector<ChamberDef> chambers;    ///< closed volumes of gas (docs/gas.md)
  ContactDef contact;
  Vec3 gravity_W = Vec3::Zero();  ///< m/s^2
  /// N: a force that the static solver's tolerances scale with besides loads, gravity and
  /// drives (the creases' pull when folding by simulation); 0: none.
  double actuation_force = 0;

  /// Index of the 6-DOF block of each body in solver vectors, -1 for fixed bodies.
  std::vector<int> dof_of_body;
  int num_dofs = 0;

  /// Fills dof_of_body / num_dofs; call after the body list is final.
  void finalize_dofs();
  int body_index(const std::string& name) const;  ///< -1 if absent
};

/// Number of panels (largest BodyDef::panel + 1, at least 1).
int panel_count(const Model& m);

/// True when drive 0 has a travel and a step: the static solver then follows a quasi-static
/// pull (one equilibrium per step) after its load stepping.
bool has_drive_path(const Model& m);

/// Gives `b` the prism of cross-section `outline_B` (any position: it is moved so that its
/// centroid is B's origin) and `thickness` (m), with mass `mass` (kg) and its exact inertia.
/// Returns the centroid of the given outline, m (where B's origin lies in its coordinates).
Vec2 set_prism(BodyDef& b, const Outline& outline_B, double thickness, double mass);

/// set_prism for a box: rectangle size.x() by size.y(), thickness size.z() (m).
void set_box(BodyDef& b, const Vec3& size, double mass);

/// Area of a segment's mid-surface polygon, m^2.
double segment_area(const BodyDef& b);

/// A segment's polygon on the flat sheet (material coordinates, m); requires centroid_M.
Outline material_outline(const BodyDef& b);

/// Checks sizes, indices and finiteness; throws InputError naming model.source.
void validate(const Model& model);

}  // namespace finseg

// Contact settings of a model (paper eqs. 18-19) and the contact history carried in State.
// docs/contact.md explains every parameter and how to choose it.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/types.hpp"

namespace finseg {

/// Damping part of the normal force.
enum class ContactDamping {
  Impact,              ///< Adams IMPACT: STEP(delta, 0, 0, d, c_max) * delta_dot
  HuntCrossley,        ///< K delta^e * 3(1-cr)/2 * delta_dot / v0
  LankaraniNikravesh,  ///< K delta^e * 3(1-cr^2)/4 * delta_dot / v0
  Flores,              ///< K delta^e * 8(1-cr)/(5 cr) * delta_dot / v0
};

/// Tangential (friction) law.
enum class FrictionModel {
  None,        ///< frictionless
  Continuous,  ///< Adams mu(v): 0 at rest, mu_s at v_s, mu_d beyond v_d (creeps when loaded)
  Anchor,      ///< elastic anchor (bristle): holds static friction without creep
};

/// What the contact does with plates that overlap where a run starts.
enum class InitialOverlap {
  Push,    ///< push them apart like any penetration
  Ignore,  ///< no force against the overlap found at the start; it shrinks as they part
};

/// Contact between segments: off unless enabled. All values SI. K and the damping describe
/// the contact of a whole face lying flat on another: the force is shared by the plate's
/// sample points (weights summing to 1, see docs/contact.md).
struct ContactDef {
  bool enabled = false;

  // Normal force (eq. 18): F = K delta^e + damping, never attractive.
  double stiffness = 0;   ///< K, N/m^e, > 0
  double exponent = 1.5;  ///< e >= 1
  ContactDamping damping_law = ContactDamping::Impact;
  double damping = 0;              ///< Impact: c_max, N s/m, >= 0
  double damping_depth = 1e-5;     ///< Impact: d, penetration of full damping, m, > 0
  double restitution = 1.0;        ///< HC / LN / Flores: coefficient of restitution, (0, 1]
  double min_impact_speed = 1e-3;  ///< HC / LN / Flores: floor of v0, m/s, > 0

  // Friction (eq. 19): f = -F_n mu(v) along the slip direction.
  FrictionModel friction = FrictionModel::None;
  double mu_static = 0;             ///< mu_s >= 0
  double mu_dynamic = 0;            ///< mu_d in [0, mu_s]
  double stiction_speed = 1e-4;     ///< v_s, m/s, > 0
  double friction_speed = 1e-3;     ///< v_d, m/s, > v_s
  double tangential_stiffness = 0;  ///< Anchor: k_t of a whole face, N/m, > 0
  double tangential_damping = 0;    ///< Anchor: c_t of a whole face, N s/m, >= 0

  // Which pairs may touch.
  /// Same-panel pairs at most this many force elements apart are skipped (>= 0).
  int panel_exclusion = 2;
  /// Lists of panels that may touch each other; empty: every panel with every panel.
  std::vector<std::vector<int>> groups;
  /// Pairs closer than this on the flat sheet (material distance, m, >= 0) never touch: the
  /// material a real fold bends through (docs/contact.md). Unset: twice the thicker plate's
  /// thickness.
  std::optional<double> crease_zone;
  double margin = 0;  ///< extra broad-phase box growth, m, >= 0
  /// Sample points per plate side of the narrow phase (n x n on a rectangle), 2..16.
  int samples_per_edge = 3;
  /// Overlaps at the start of a run: pushed apart, or ignored (layers of a stowed pattern
  /// that coincide; docs/contact.md, "Layers that start overlapping").
  InitialOverlap initial_overlap = InitialOverlap::Push;
};

/// History of one contact point (a sample point of one plate against the other plate of a
/// pair), kept from one accepted step to the next.
struct ContactAnchor {
  std::uint64_t key = 0;        ///< pair and sample identity (collision/contact_forces.cpp)
  Vec3 r_src_B = Vec3::Zero();  ///< anchor on the sampled (source) body, its body frame, m
  Vec3 r_tgt_B = Vec3::Zero();  ///< anchor on the target body, its body frame, m
  double impact_speed = 0;      ///< penetration rate when the contact began, m/s
  /// Which face of the target plate the point is on; 0: none yet (a point that started
  /// overlapping: no force until the plates are a quarter of their thickness apart).
  int side = 1;
  bool sliding = false;  ///< Anchor friction: currently slipping
  /// Slip speed at the last accepted step, m/s (-1: not known); the continuous law takes its
  /// falling branch there (docs/contact.md, "Friction").
  double slip_speed = -1;
  /// Penetration the normal force does not push against, m (>= 0): what the point had at the
  /// start of a run with `initial_overlap: ignore`, never growing, shrinking as the plates part.
  double overlap = 0;
};

struct ContactCandidates;  // collision/candidate_cache.hpp

/// Contact history in State (sorted by key); written only by commit_contact_history().
struct ContactState {
  std::vector<ContactAnchor> anchors;
  /// Body poses at the last commit: a point that enters the contact takes the side of the
  /// target it was on then, so a step that carries two plates through each other meets the
  /// full force instead of a contact seen from the far side.
  std::vector<Vec3> p_W;
  std::vector<Mat3> R_WB;
  /// Candidate pairs found at the last commit with grown boxes, reused by the detections
  /// while they cover the poses (derived data: not saved; null: search afresh).
  std::shared_ptr<const ContactCandidates> candidates;
};

}  // namespace finseg

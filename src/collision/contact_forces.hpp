// Contact between segments: entry points used by the force assembly and the probes.
#pragma once

#include <vector>

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

class Assembler;

/// Adds the normal and friction forces of every active contact (nothing when disabled).
void add_contact_forces(const Model& model, const State& state, Assembler& assembler);

/// Updates contact history (friction anchors, overlaps) after an accepted step; `start`: the
/// state a run starts from (new points then keep their overlap under `initial_overlap: ignore`).
void commit_contact_history(const Model& model, State& state, bool start = false);

/// Contact of one pair of bodies.
struct ContactPairForce {
  int a = -1, b = -1;          ///< body indices, a < b
  int points = 0;              ///< active sample points
  double normal_force = 0;     ///< N (sum over the points)
  double friction_force = 0;   ///< N (sum of magnitudes)
  double max_penetration = 0;  ///< m
  Vec3 f_b_W = Vec3::Zero();   ///< resultant force on body b (normal + friction), N
};

/// What the contact probes record; a joint's stop (collision/joint_stops.hpp) counts as one
/// point of its two bodies' pair.
struct ContactSummary {
  int active = 0;                         ///< number of contact points with positive penetration
  double total_normal_force = 0;          ///< N
  double total_friction_force = 0;        ///< N (sum of magnitudes)
  double max_penetration = 0;             ///< m
  std::vector<Vec3> points_W;             ///< active contact points, m
  std::vector<double> point_normal;       ///< per point: normal force, N
  std::vector<double> point_penetration;  ///< per point: penetration, m
  std::vector<double> point_friction;     ///< per point: friction force magnitude, N
  std::vector<ContactPairForce> pairs;    ///< touching pairs, in body order
};
ContactSummary contact_summary(const Model& model, const State& state);

}  // namespace finseg

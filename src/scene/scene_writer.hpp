// Scene files written by `finseg gen`: the cantilever and the zigzag strip as YAML that
// read_scene() turns back into the model the generators build (docs/scene.md).
#pragma once

#include <optional>
#include <string>

#include "generators/cantilever.hpp"
#include "generators/zigzag.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/solver.hpp"

namespace finseg {

/// Cantilever of the paper's bending test as a general-sheet scene: clamp at s = 0, the tip
/// load shared by the rows' free-edge segments, probe `tip` at the mid-point of the free edge.
std::string cantilever_scene(const CantileverSpec& spec, const SolverSettings& solver);

/// What `finseg gen zigzag` knows beyond ZigzagSpec (whose crease_laws it ignores).
struct ZigzagSceneOptions {
  ZigzagSpec spec;                      ///< fold_angle is taken from fold_angle_deg below
  double fold_angle_deg = 80;           ///< deg, written as given
  std::string crease_law_file;          ///< measured crease data for every crease (empty: default)
  std::optional<double> pressing_time;  ///< s: which measured pressing time (interpolated)
  std::optional<double> crease_stiffness;  ///< N m/rad: linear crease resting at the fold
  std::optional<double> pull_speed;        ///< m/s of the dynamic solvers' pull (zigzag.pull_speed)
};

/// The zigzag strip scene: every ZigzagSpec field written out explicitly.
std::string zigzag_scene(const ZigzagSceneOptions& options, const SolverSettings& solver);

/// The `chambers:` section of `model` (docs/scene.md) as YAML that read_scene() reads back
/// to the same chambers; faces name their bodies. Empty without chambers.
std::string chambers_section(const Model& model);

/// Shortest decimal text of x that reads back to the same double.
std::string yaml_number(double x);

/// `[x, y, z]` with yaml_number components.
std::string yaml_vector(const Vec3& v);

/// Quotes a string for YAML (single quotes, '' inside).
std::string yaml_quote(const std::string& s);

}  // namespace finseg

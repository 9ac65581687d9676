// What `finseg gen cantilever|zigzag` and Python's finseg.cantilever()/finseg.zigzag() share:
// the checks of the generator options and the scene text they give (docs/scene.md,
// docs/python.md). Each front end only maps its own option syntax onto these structs.
#pragma once

#include <optional>
#include <string>

#include "scene/scene_writer.hpp"

namespace finseg {

/// How a front end names its options in messages: the source ("<cli>", "<python>") and the
/// spelling of a key, e.g. "pull_speed" -> "--pull-speed" (prefix "--", separator '-').
struct OptionNaming {
  std::string source = "<api>";
  std::string prefix;
  char separator = '_';
  /// The option `key` (words joined by '_') as the front end spells it.
  std::string operator()(const std::string& key) const;
};

/// The command line's spelling: --words-with-dashes, errors naming "<cli>".
inline const OptionNaming kCliNames{"<cli>", "--", '-'};

/// Solver kind of a name: static, implicit or explicit; nullopt for any other word.
std::optional<SolverKind> solver_kind_from_name(const std::string& name);

/// `finseg gen zigzag`'s options: the scene options, the solver and whether t_end was given
/// (without it a pull speed sets t_end = travel / speed).
struct ZigzagGenOptions {
  ZigzagSceneOptions z;
  SolverSettings solver;
  bool t_end_given = false;
};

/// Checks the options (crease law xor crease stiffness, pressing time only with a crease
/// law, the spec's ranges, pull speed > 0) and returns the scene text. A crease-law file
/// must exist; it is written relative to `scene_out`'s folder when that is given (the scene
/// reader resolves it from there), else as given. Throws InputError(names.source,
/// names(key), ...).
std::string zigzag_gen_scene(ZigzagGenOptions o, const OptionNaming& names,
                             const std::string& scene_out = "");

/// Checks the cantilever spec and returns its scene text (cantilever_scene).
std::string cantilever_gen_scene(const CantileverSpec& spec, const SolverSettings& solver,
                                 const OptionNaming& names);

}  // namespace finseg

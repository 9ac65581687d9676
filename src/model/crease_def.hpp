// Crease description: which law drives the rotation about the crease line (F's y axis).
#pragma once

#include <memory>
#include <string>

namespace finseg {

class CreaseLaw;  // elements/crease_law.hpp

/// One crease. The fold angle is the exact signed rotation of E relative to F about F's y
/// axis, measured from the flat sheet; `law` gives the moment about that axis.
struct CreaseDef {
  std::shared_ptr<const CreaseLaw> law;
  double initial_fold_angle = 0;  ///< rad, fold angle in the initial configuration
  /// Fold direction +1 / -1 where known apart from the initial angle (a pattern's M or V on
  /// a sheet that starts flat); 0: the sign of initial_fold_angle.
  double direction = 0;
  /// rad, signed like the fold angle: where folding by simulation takes the crease
  /// (docs/folding.md); 0: the crease is not folded.
  double target_fold_angle = 0;
  /// The crease line it is a piece of, e.g. "edge17" or "seam2" (0-based FOLD edge or
  /// `finseg:seams` index) on a pattern cut into segments; empty: a line of its own.
  std::string line{};
};

}  // namespace finseg

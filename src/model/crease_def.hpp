// Crease description: which law drives the rotation about the crease line (F's y axis).
#pragma once

#include <memory>

namespace finseg {

class CreaseLaw;  // elements/crease_law.hpp

/// One crease. The fold angle is the exact signed rotation of E relative to F about F's y
/// axis, measured from the flat sheet; `law` gives the moment about that axis.
struct CreaseDef {
  std::shared_ptr<const CreaseLaw> law;
  double initial_fold_angle = 0;  ///< rad, fold angle in the initial configuration
};

}  // namespace finseg

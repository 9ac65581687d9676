// The four working conditions of the paper's pull-open test (Table 1): fold angle 80 or 83
// deg, plain paper or paper stiffened with adhesive tape on its non-crease areas.
// docs/zigzag.md states the material data, their sources and the crease law.
#pragma once

#include <vector>

#include "generators/zigzag.hpp"

namespace finseg {

/// One layer of a laminated strip, bottom to top. SI units.
struct Layer {
  double thickness = 0;  ///< m
  double modulus = 0;    ///< Young's modulus, Pa (0: carries no stress, e.g. a soft adhesive)
  double density = 0;    ///< kg/m^3
};

/// Bending rigidity E I of a perfectly bonded laminate of width `width` about its own
/// neutral axis (parallel-axis theorem), N m^2. Throws InputError on an empty or bad stack.
double laminate_bending_rigidity(const std::vector<Layer>& layers, double width);

/// Mass per area of a laminate, kg/m^2.
double laminate_areal_mass(const std::vector<Layer>& layers);

/// The plain paper of the experiment: 80 g/m^2, 0.1 mm, E = 4 GPa.
Layer paper_layer();

/// The paper with office tape on one face: paper, 0.02 mm acrylic adhesive (no stiffness),
/// 0.05 mm BOPP backing at E = 2 GPa.
std::vector<Layer> taped_paper_layers();

/// Table 1 condition n (1..4): 1 = 80 deg plain, 2 = 80 deg taped, 3 = 83 deg plain,
/// 4 = 83 deg taped; everything else the ZigzagSpec defaults (contact on, linear creases).
/// Throws InputError for other n.
ZigzagSpec paper_condition(int n);

/// Short label of condition n, e.g. "80 deg, taped".
const char* paper_condition_label(int n);

}  // namespace finseg

#include "probes/deployment_phases.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/so3.hpp"

namespace finseg {

double panel_bend_angle(const Model& model, const State& state, int panel) {
  double total = 0;
  for (const ElementDef& e : model.elements) {
    if (e.crease >= 0 || model.bodies[e.inner].panel != panel ||
        model.bodies[e.outer].panel != panel || !e.R_inner_E.isIdentity()) {
      continue;  // only the along-length bending joints inside the panel
    }
    const Mat3 R_FE =
        (state.R_WB[e.outer] * e.R_outer_F).transpose() * state.R_WB[e.inner] * e.R_inner_E;
    total += std::abs(so3_log<double>(R_FE).y());
  }
  return total;
}

DeploymentPhases detect_phases(const std::vector<PhaseSample>& samples, double bend_threshold) {
  const double none = std::numeric_limits<double>::quiet_NaN();
  DeploymentPhases p{samples.empty() ? none : samples.front().displacement, none, none};
  for (const PhaseSample& s : samples) {
    if (std::isnan(p.contact) && s.active_contacts > 0) p.contact = s.displacement;
    if (std::isnan(p.bending) && s.bend > bend_threshold &&
        (std::isnan(p.contact) ? false : s.displacement >= p.contact)) {
      p.bending = s.displacement;
    }
  }
  // Without contact the panels may still bend: report it after the initial phase.
  if (std::isnan(p.contact)) {
    for (const PhaseSample& s : samples) {
      if (s.bend > bend_threshold) {
        p.bending = s.displacement;
        break;
      }
    }
  }
  return p;
}

double watched_bend(const Model& model, const State& state, const std::vector<int>& panels) {
  double bend = 0;
  for (int p : panels) bend = std::max(bend, panel_bend_angle(model, state, p));
  return bend;
}

}  // namespace finseg

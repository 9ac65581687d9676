#include "probes/segment_fields.hpp"

#include <algorithm>
#include <cmath>

#include "elements/element_load.hpp"

namespace finseg {

SegmentFields segment_fields(const Model& model, const State& state, const BodyForces& forces,
                             const ContactSummary& contact) {
  const std::size_t n = model.bodies.size();
  SegmentFields s;
  s.force_W = forces.f_W;
  s.moment_W = forces.tau_W;
  s.element_force.assign(n, 0.0);
  s.element_moment.assign(n, 0.0);
  s.crease_opening.assign(n, NAN);
  s.crease_moment.assign(n, NAN);
  s.contact_normal.assign(n, 0.0);
  s.contact_friction.assign(n, 0.0);
  for (std::size_t k = 0; k < model.elements.size(); ++k) {
    const ElementDef& e = model.elements[k];
    const ElementLoad l = element_load(model, state, static_cast<int>(k));
    for (int b : {e.inner, e.outer}) {
      s.element_force[b] = std::max(s.element_force[b], l.force_F.norm());
      s.element_moment[b] = std::max(s.element_moment[b], l.moment_F.norm());
      if (l.crease && std::isnan(s.crease_opening[b])) {
        s.crease_opening[b] = l.opening_angle;
        s.crease_moment[b] = l.crease_moment;
      }
    }
  }
  for (const ContactPairForce& p : contact.pairs) {
    for (int b : {p.a, p.b}) {
      s.contact_normal[b] += p.normal_force;
      s.contact_friction[b] += p.friction_force;
    }
  }
  return s;
}

}  // namespace finseg

// Placeholder until the contact module lands: no contact forces.
#include "collision/contact_forces.hpp"

namespace finseg {

void add_contact_forces(const Model&, const State&, Assembler&) {}

void commit_contact_history(const Model&, State&) {}

ContactSummary contact_summary(const Model&, const State&) {
  return {};
}

}  // namespace finseg

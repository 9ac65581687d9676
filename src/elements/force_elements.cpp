#include "elements/force_elements.hpp"

#include "elements/bushing.hpp"
#include "elements/element_jacobian.hpp"

namespace finseg {
namespace {

// Below this many elements a parallel region costs more than it saves (a few us per
// region against ~0.2 us per element and evaluation).
constexpr int kParallelElements = 512;

struct ElementResult {
  double energy = 0;
  Wrench<double> on_inner, on_outer;
};

// The automatic-differentiation oracle, element by element (ForceJacobian::autodiff).
void add_elements_autodiff(const Model& model, const State& state, Assembler& as) {
  for (size_t k = 0; k < model.elements.size(); ++k) {
    const ElementDef& e = model.elements[k];
    const CreaseDef* crease = e.crease >= 0 ? &model.creases[e.crease] : nullptr;
    const ElementHistory& h = state.history[k];
    as.pair(e.inner, e.outer, [&](const auto& A, const auto& B, auto& wa, auto& wb) {
      return element_kernel(e, crease, h, state.t, A, B, wa, wb);
    });
  }
}

bool damped(const ElementDef& e) {
  return e.C.any();
}

}  // namespace

void add_force_elements(const Model& model, const State& state, Assembler& as) {
  if (as.want_jacobian() && as.autodiff_elements()) {
    add_elements_autodiff(model, state, as);
    return;
  }
  const int n = static_cast<int>(model.elements.size());
  // Scratch reused between calls on this thread; the parallel loop's workers reach it
  // through these references (by name they would see their own, empty, copies).
  thread_local std::vector<ElementResult> results_scratch;
  thread_local std::vector<PairSlots> slots_scratch;
  std::vector<ElementResult>& results = results_scratch;
  std::vector<PairSlots>& slots = slots_scratch;
  results.resize(n);
  const bool jacobian = as.want_jacobian();
  if (jacobian) {
    slots.resize(n);
    for (int k = 0; k < n; ++k) {
      const ElementDef& e = model.elements[k];
      slots[k] = as.reserve_pair(e.inner, e.outer, as.want_velocity_jacobian() && damped(e));
    }
  }
#pragma omp parallel for schedule(static) if (n >= kParallelElements)
  for (int k = 0; k < n; ++k) {
    const ElementDef& e = model.elements[k];
    const CreaseDef* crease = e.crease >= 0 ? &model.creases[e.crease] : nullptr;
    const ElementHistory& h = state.history[k];
    const BodyKin<double> A = as.kin(e.inner), B = as.kin(e.outer);
    ElementResult& r = results[k];
    r.on_inner = r.on_outer = Wrench<double>();
    r.energy = element_kernel(e, crease, h, state.t, A, B, r.on_inner, r.on_outer);
    if (jacobian && slots[k].any()) {
      ElementJacobian J;
      element_jacobian(e, crease, h, state.t, A, B, slots[k].with_velocity, J);
      as.fill_pair(slots[k], J.dq, J.dv);
    }
  }
  for (int k = 0; k < n; ++k) {
    as.add_energy(results[k].energy);
    as.add(model.elements[k].inner, results[k].on_inner);
    as.add(model.elements[k].outer, results[k].on_outer);
  }
}

}  // namespace finseg

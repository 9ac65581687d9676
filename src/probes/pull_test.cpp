#include "probes/pull_test.hpp"

#include <algorithm>
#include <cmath>

#include "collision/contact_forces.hpp"
#include "core/error.hpp"
#include "elements/drive_gauge.hpp"

namespace finseg {
namespace {

bool finite_state(const State& s, const BodyForces& f) {
  for (size_t i = 0; i < s.p_W.size(); ++i) {
    if (!s.p_W[i].allFinite() || !s.R_WB[i].allFinite() || !f.f_W[i].allFinite() ||
        !f.tau_W[i].allFinite()) {
      return false;
    }
  }
  return true;
}

PullSample sample(const Model& m, const State& s, const BodyForces& f,
                  const std::vector<int>& watched) {
  PullSample p;
  p.displacement = s.drive_s[0];
  p.force = drive_force(m, s, 0).dot(m.drives[0].direction_W);
  const ContactSummary c = contact_summary(m, s);
  p.active_contacts = c.active;
  p.max_penetration = c.max_penetration;
  p.bend = watched_bend(m, s, watched);
  p.finite = finite_state(s, f) && std::isfinite(p.force);
  return p;
}

}  // namespace

PullResult run_pull_test(const Model& model, const std::vector<int>& watched_panels,
                         double bend_threshold, const SolverSettings& settings) {
  if (model.drives.empty()) throw InputError(model.source, "drives", "a pull test needs a drive");
  PullResult r;
  State st = initial_state(model);
  r.stats = run_solver(model, st, settings, [&](const State& s, const BodyForces& f) {
    r.samples.push_back(sample(model, s, f, watched_panels));
  });
  std::vector<PhaseSample> phase_samples;
  for (const PullSample& p : r.samples) {
    phase_samples.push_back({p.displacement, p.active_contacts, p.bend});
    r.all_finite = r.all_finite && p.finite;
    r.max_penetration = std::max(r.max_penetration, p.max_penetration);
    if (p.force > r.peak_force) r.peak_force = p.force, r.peak_displacement = p.displacement;
  }
  r.phases = detect_phases(phase_samples, bend_threshold);
  std::vector<double> x, force;
  for (const PullSample& p : r.samples) x.push_back(p.displacement), force.push_back(p.force);
  const double deployed_at = model.drives[0].deployed_at;
  r.deployment_peak =
      find_deployment_peak(x, force, -INFINITY, deployed_at > 0 ? deployed_at : INFINITY);
  return r;
}

}  // namespace finseg

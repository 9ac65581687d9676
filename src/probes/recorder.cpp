#include "probes/recorder.hpp"

#include <cmath>

#include "collision/contact_forces.hpp"
#include "solvers/dofs.hpp"

namespace finseg {

std::string abscissa_column(const Model& model, const SolverSettings& settings) {
  if (settings.kind != SolverKind::Static) return "t_s";
  const bool path = !model.drives.empty() && model.drives[0].travel > 0 && model.drives[0].step > 0;
  return path ? "pull_displacement_m" : "load_scale";
}

std::string probe_kind_name(ProbeKind kind) {
  switch (kind) {
    case ProbeKind::Point:
      return "point";
    case ProbeKind::Drive:
      return "drive";
    case ProbeKind::Reaction:
      return "reaction";
    case ProbeKind::Energy:
      return "energy";
    case ProbeKind::Contact:
      break;
  }
  return "contact";
}

namespace {

std::vector<std::string> columns_of(ProbeKind kind, const std::string& x) {
  switch (kind) {
    case ProbeKind::Point:
      return {x, "x_m", "y_m", "z_m"};
    case ProbeKind::Drive: {
      std::vector<std::string> c{"pull_displacement_m", "force_N",   "force_x_N", "force_y_N",
                                 "force_z_N",           "point_x_m", "point_y_m", "point_z_m"};
      if (x != "pull_displacement_m") c.push_back(x);
      return c;
    }
    case ProbeKind::Reaction:
      return {
          x, "force_x_N", "force_y_N", "force_z_N", "moment_x_Nm", "moment_y_Nm", "moment_z_Nm"};
    case ProbeKind::Energy:
      return {x, "potential_J", "kinetic_J", "total_J"};
    case ProbeKind::Contact:
      break;
  }
  return {x, "active_points", "normal_force_N", "friction_force_N", "max_penetration_m"};
}

}  // namespace

RunRecorder::RunRecorder(const Model& model, const SolverSettings& settings,
                         RecorderOptions options)
    : model_(model),
      options_(std::move(options)),
      abscissa_(abscissa_column(model, settings)),
      dynamic_(settings.kind != SolverKind::Static),
      last_x_(NAN) {
  for (const ProbeDef& p : model.probes) {
    const bool pairs = p.pairs && p.kind == ProbeKind::Contact;
    tables_.push_back({p.name, p.kind, columns_of(p.kind, abscissa_), {}, pairs, {}});
  }
}

std::vector<double> RunRecorder::row(const ProbeDef& p, const State& s, const BodyForces& f,
                                     const ContactSummary* contact) const {
  const double x = last_x_;
  switch (p.kind) {
    case ProbeKind::Point: {
      const Vec3 r = s.p_W[p.body] + s.R_WB[p.body] * p.point_B;
      return {x, r.x(), r.y(), r.z()};
    }
    case ProbeKind::Drive: {
      const DriveDef& d = model_.drives[p.drive];
      const Vec3 F = drive_force(model_, s, p.drive);
      const Vec3 r = s.p_W[d.body] + s.R_WB[d.body] * d.point_B;
      std::vector<double> v{
          s.drive_s[p.drive], F.dot(d.direction_W), F.x(), F.y(), F.z(), r.x(), r.y(), r.z()};
      if (abscissa_ != "pull_displacement_m") v.push_back(x);
      return v;
    }
    case ProbeKind::Reaction: {
      Vec3 F = Vec3::Zero(), M = Vec3::Zero();
      for (std::size_t i = 0; i < model_.bodies.size(); ++i) {
        if (!model_.bodies[i].fixed) continue;
        F -= f.f_W[i];
        M -= f.tau_W[i] + s.p_W[i].cross(f.f_W[i]);
      }
      return {x, F.x(), F.y(), F.z(), M.x(), M.y(), M.z()};
    }
    case ProbeKind::Energy: {
      const double kinetic = dynamic_ ? kinetic_energy(model_, s) : 0.0;
      return {x, f.potential_energy, kinetic, f.potential_energy + kinetic};
    }
    case ProbeKind::Contact:
      break;
  }
  return {x, static_cast<double>(contact->active), contact->total_normal_force,
          contact->total_friction_force, contact->max_penetration};
}

void RunRecorder::record(const State& state, const BodyForces& forces) {
  last_x_ = abscissa_ == "load_scale" ? state.load_scale : state.t;
  ++outputs_;
  ContactSummary contact;
  if (model_.contact.enabled) contact = contact_summary(model_, state);
  for (std::size_t k = 0; k < tables_.size(); ++k) {
    tables_[k].rows.push_back(row(model_.probes[k], state, forces, &contact));
    if (!tables_[k].pairs) continue;
    for (const ContactPairForce& p : contact.pairs) tables_[k].pair_rows.push_back({last_x_, p});
  }
  if (options_.frames) frames_.push_back({state.t, state.p_W, state.R_WB, contact.points_W});
  if (options_.phases && !model_.drives.empty()) {
    samples_.push_back(
        {state.drive_s[0], contact.active, watched_bend(model_, state, options_.watched_panels)});
  }
}

void RunRecorder::restore(std::vector<ProbeTable> tables, std::vector<Frame> frames,
                          std::vector<PhaseSample> samples, double last_x, std::size_t outputs) {
  tables_ = std::move(tables);
  frames_ = std::move(frames);
  samples_ = std::move(samples);
  last_x_ = last_x;
  outputs_ = outputs;
}

}  // namespace finseg

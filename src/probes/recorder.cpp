#include "probes/recorder.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "collision/contact_forces.hpp"
#include "core/allocator.hpp"
#include "core/rigid_fit.hpp"
#include "core/so3.hpp"
#include "elements/drive_gauge.hpp"
#include "elements/element_load.hpp"
#include "probes/segment_fields.hpp"
#include "solvers/dofs.hpp"

namespace finseg {

std::string abscissa_column(const Model& model, const SolverSettings& settings) {
  if (settings.kind != SolverKind::Static) return "t_s";
  return has_drive_path(model) ? "pull_displacement_m" : "load_scale";
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
    case ProbeKind::Crease:
      return "crease";
    case ProbeKind::Element:
      return "element";
    case ProbeKind::Pose:
      return "pose";
    case ProbeKind::Chamber:
      return "chamber";
    case ProbeKind::Shape:
      return "shape";
    case ProbeKind::Unfolding:
      return "unfolding";
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
      return {x, "potential_J", "kinetic_J", "total_J", "gas_work_J"};
    case ProbeKind::Crease:
      return {x, "fold_angle_deg", "opening_angle_deg", "moment_Nm"};
    case ProbeKind::Element:
      return {
          x, "force_x_N", "force_y_N", "force_z_N", "moment_x_Nm", "moment_y_Nm", "moment_z_Nm"};
    case ProbeKind::Pose:
      return {x, "x_m", "y_m", "z_m", "qw", "qx", "qy", "qz", "rx_rad", "ry_rad", "rz_rad"};
    case ProbeKind::Chamber:
      return {x,        "pressure_Pa", "volume_m3", "mass_kg", "temperature_K",
              "work_J", "injected_kg", "vented_kg"};
    case ProbeKind::Shape:
      return {x, "rms_distance_m", "largest_distance_m"};
    case ProbeKind::Unfolding:  // its columns depend on the model: unfolding_columns
    case ProbeKind::Contact:
      break;
  }
  return {x,
          "active_points",
          "normal_force_N",
          "friction_force_N",
          "max_penetration_m",
          "touching_pairs"};
}

// Crease probe: mean fold and opening angle over the crease's elements (they differ only
// when the crease line twists), total moment about the crease line.
std::vector<double> crease_row(double x, const Model& model, const State& s,
                               const std::vector<int>& elements) {
  double fold = 0, opening = 0, moment = 0;
  for (int k : elements) {
    const ElementLoad l = element_load(model, s, k);
    fold += l.fold_angle;
    opening += l.opening_angle;
    moment += l.crease_moment;
  }
  const double n = static_cast<double>(elements.size());
  return {x, fold / n / kDegToRad, opening / n / kDegToRad, moment};
}

// Pose probe: centroid, unit quaternion (w >= 0) and rotation vector of R_WB.
std::vector<double> pose_row(double x, const Vec3& p_W, const Mat3& R_WB) {
  Eigen::Quaterniond q(R_WB);
  q.normalize();
  if (q.w() < 0) q.coeffs() *= -1;
  const Vec3 r = so3_log<double>(R_WB);
  return {x, p_W.x(), p_W.y(), p_W.z(), q.w(), q.x(), q.y(), q.z(), r.x(), r.y(), r.z()};
}

// Shape probe: RMS and largest distance of the bodies' centroids from the shape's after the
// rigid motion that brings them nearest (so a structure that has moved as a whole is at 0).
std::vector<double> shape_row(double x, const State& s, const ShapeDef& shape) {
  const RigidFit fit = best_rigid_fit(s.p_W, shape.p_W);
  double sum = 0, largest = 0;
  for (std::size_t i = 0; i < s.p_W.size(); ++i) {
    const double d = (fit.apply(s.p_W[i]) - shape.p_W[i]).norm();
    sum += d * d;
    largest = std::max(largest, d);
  }
  return {x, std::sqrt(sum / static_cast<double>(s.p_W.size())), largest};
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
    const bool unfolding = p.kind == ProbeKind::Unfolding;
    lines_.push_back(unfolding ? unfolding_lines(model, p.shape) : std::vector<UnfoldingLine>{});
    tables_.push_back(
        {p.name,
         p.kind,
         unfolding ? unfolding_columns(abscissa_, lines_.back()) : columns_of(p.kind, abscissa_),
         {},
         pairs,
         {}});
    crease_elements_.push_back(p.kind == ProbeKind::Crease ? crease_elements(model, p.crease)
                                                           : std::vector<int>{});
  }
  for (const ChamberDef& c : model.chambers) {
    tables_.push_back({chamber_table_name(c),
                       ProbeKind::Chamber,
                       columns_of(ProbeKind::Chamber, abscissa_),
                       {},
                       false,
                       {}});
  }
}

const std::vector<UnfoldingLine>& RunRecorder::unfolding_lines_of(std::size_t k) const {
  static const std::vector<UnfoldingLine> none;
  return k < lines_.size() ? lines_[k] : none;
}

std::string chamber_table_name(const ChamberDef& chamber) {
  return "chamber_" + chamber.name;
}

std::vector<double> RunRecorder::row(std::size_t probe, const State& s, const BodyForces& f,
                                     const ContactSummary* contact) const {
  const double x = last_x_;
  if (probe >= model_.probes.size()) {  // the chambers' tables follow the probes
    const ChamberGas& g = s.chambers[probe - model_.probes.size()];
    return {x, g.pressure, g.volume, g.mass, g.temperature, g.work, g.injected, g.vented};
  }
  const ProbeDef& p = model_.probes[probe];
  switch (p.kind) {
    case ProbeKind::Point: {
      const Vec3 r = s.p_W[p.body] + s.R_WB[p.body] * p.point_B;
      return {x, r.x(), r.y(), r.z()};
    }
    case ProbeKind::Drive: {
      // Several gauges (moving alike): their forces summed, their points' mean.
      Vec3 F = Vec3::Zero(), r = Vec3::Zero();
      double along = 0;
      for (const int k : p.drives) {
        const DriveDef& d = model_.drives[k];
        const Vec3 F_k = drive_force(model_, s, k);
        F += F_k;
        along += F_k.dot(d.direction_W);
        r += s.p_W[d.body] + s.R_WB[d.body] * d.point_B;
      }
      r /= static_cast<double>(p.drives.size());
      std::vector<double> v{
          s.drive_s[p.drives[0]], along, F.x(), F.y(), F.z(), r.x(), r.y(), r.z()};
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
      double gas_work = 0;  // p dV done on the structure by every chamber's gas
      for (const ChamberGas& g : s.chambers) gas_work += g.work;
      return {x, f.potential_energy, kinetic, f.potential_energy + kinetic, gas_work};
    }
    case ProbeKind::Crease:
      return crease_row(x, model_, s, crease_elements_[probe]);
    case ProbeKind::Element: {
      const ElementLoad l = element_load(model_, s, p.element);
      return {x,
              l.force_F.x(),
              l.force_F.y(),
              l.force_F.z(),
              l.moment_F.x(),
              l.moment_F.y(),
              l.moment_F.z()};
    }
    case ProbeKind::Pose:
      return pose_row(x, s.p_W[p.body], s.R_WB[p.body]);
    case ProbeKind::Shape:
      return shape_row(x, s, model_.shapes[p.shape]);
    case ProbeKind::Unfolding: {
      // Openings count from the table's first row: the state the run started from.
      const auto& rows = tables_[probe].rows;
      const std::vector<double> start =
          rows.empty() ? std::vector<double>{}
                       : std::vector<double>(rows[0].begin() + kFirstLineColumn, rows[0].end());
      return unfolding_row(x, line_fold_angles(model_, s, lines_[probe]), start, lines_[probe]);
    }
    case ProbeKind::Chamber:  // handled above
    case ProbeKind::Contact:
      break;
  }
  const auto touching = std::count_if(contact->pairs.begin(), contact->pairs.end(),
                                      [](const ContactPairForce& p) { return p.points > 0; });
  return {x,
          static_cast<double>(contact->active),
          contact->total_normal_force,
          contact->total_friction_force,
          contact->max_penetration,
          static_cast<double>(touching)};
}

void RunRecorder::record(const State& state, const BodyForces& forces) {
  last_x_ = abscissa_ == "load_scale" ? state.load_scale : state.t;
  ++outputs_;
  ContactSummary contact;
  if (model_.contact.enabled) contact = contact_summary(model_, state);
  for (std::size_t k = 0; k < tables_.size(); ++k) {
    tables_[k].rows.push_back(row(k, state, forces, &contact));
    if (!tables_[k].pairs) continue;
    for (const ContactPairForce& p : contact.pairs) tables_[k].pair_rows.push_back({last_x_, p});
  }
  if (options_.frames) {
    const SegmentFields fields = segment_fields(model_, state, forces, contact);
    const MappedAllocations kept_apart;  // the frame's copies only
    frames_.push_back({state.t, state.p_W, state.R_WB, contact.points_W, state.v_W, state.w_W,
                       fields, contact.point_normal, contact.point_penetration,
                       contact.point_friction});
  }
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

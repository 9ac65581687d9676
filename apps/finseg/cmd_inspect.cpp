// finseg inspect SCENE [--incidence FILE.csv] [--levers FILE.csv] [--check-forces [--state F]]:
// counts of the model, the incidence matrix S^c and lever vectors c_ik of the paper's eqs. 1-4,
// and the force Jacobian checked against central differences (solvers/force_check.hpp).
#include <fmt/format.h>

#include <memory>
#include <string>

#include "apps/finseg/commands.hpp"
#include "elements/assemble.hpp"
#include "probes/unfolding.hpp"
#include "scene/scene_reader.hpp"
#include "scene/state_file.hpp"
#include "solvers/force_check.hpp"
#include "writers/atomic_write.hpp"
#include "writers/run_outputs.hpp"

namespace finseg::cli {

namespace {

struct InspectOptions {
  std::string scene, incidence, levers, state;
  bool check_forces = false;
  double step = 1e-7;
};

// S_ik = +1 if body i is the inner body e+(k) of element k, -1 if the outer e-(k), else 0.
// What a probe watches, in words.
std::string probe_target(const Model& m, const ProbeDef& p) {
  switch (p.kind) {
    case ProbeKind::Point:
      return "point on " + m.bodies[p.body].name;
    case ProbeKind::Drive: {
      std::string names;
      for (const int d : p.drives) names += (names.empty() ? "" : " + ") + m.drives[d].name;
      return (p.drives.size() > 1 ? "drives " : "drive ") + names;
    }
    case ProbeKind::Crease:
      return fmt::format("crease {}", p.crease + 1);
    case ProbeKind::Element:
      return "element " + m.elements[p.element].name;
    case ProbeKind::Pose:
      return "pose of " + m.bodies[p.body].name;
    case ProbeKind::Shape:
      return "distance from shape " + m.shapes[p.shape].name;
    case ProbeKind::Unfolding:
      return fmt::format("{} crease lines opening towards {}", unfolding_lines(m, -1).size(),
                         p.shape < 0 ? std::string("flat") : "shape " + m.shapes[p.shape].name);
    default:
      return "whole model";
  }
}

std::string incidence_csv(const Model& m) {
  std::string out = "body";
  for (const ElementDef& e : m.elements) out += "," + e.name;
  out += "\n";
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    out += m.bodies[i].name;
    for (const ElementDef& e : m.elements) {
      const int b = static_cast<int>(i);
      out += e.inner == b ? ",1" : e.outer == b ? ",-1" : ",0";
    }
    out += "\n";
  }
  return out;
}

// c_ik: from the centroid of body i to the element's attachment point, body frame (m).
std::string levers_csv(const Model& m) {
  std::string out = "element,element_name,body,body_name,S,c_x_m,c_y_m,c_z_m\n";
  for (std::size_t k = 0; k < m.elements.size(); ++k) {
    const ElementDef& e = m.elements[k];
    const auto row = [&](int body, int sign, const Vec3& c) {
      out += fmt::format("{},{},{},{},{},{:.17g},{:.17g},{:.17g}\n", k, e.name, body,
                         m.bodies[body].name, sign, c.x(), c.y(), c.z());
    };
    row(e.inner, 1, e.c_inner_B);
    row(e.outer, -1, e.c_outer_B);
  }
  return out;
}

// The force Jacobian against central differences at the scene's start or a state file.
void check_forces(const Scene& scene, const InspectOptions& o) {
  const Model& m = scene.model;
  State state = o.state.empty() ? initial_state(m) : read_state_file(o.state, m).state;
  commit_history(m, state, o.state.empty());  // as a solver holds it after a step
  fmt::print(
      "force Jacobian against central differences at t = {:.6g} s, steps {:g} and {:g} "
      "(m, rad, m/s, rad/s; {} force evaluations):\n",
      state.t, o.step, 0.1 * o.step, 8 * m.num_dofs);
  const std::vector<ForceMismatch> found = check_force_jacobian(m, state, o.step);
  if (found.empty()) {
    fmt::print("  every entry agrees (within 1e-3 of its size)\n");
    return;
  }
  static const char* force[] = {"f_x", "f_y", "f_z", "m_x", "m_y", "m_z"};
  static const char* pose[] = {"x", "y", "z", "rot_x", "rot_y", "rot_z"};
  static const char* rate[] = {"v_x", "v_y", "v_z", "w_x", "w_y", "w_z"};
  fmt::print("  {:<9} {:<28} {:<28} {:>13} {:>13} {:>13}\n", "kind", "force", "moved", "jacobian",
             "difference", "step / 10");
  const std::size_t shown = std::min<std::size_t>(found.size(), 20);
  for (std::size_t i = 0; i < shown; ++i) {
    const ForceMismatch& x = found[i];
    fmt::print("  {:<9} {:<28} {:<28} {:>13.5g} {:>13.5g} {:>13.5g}\n", to_string(x.kind),
               m.bodies[x.body].name + " " + force[x.dof],
               m.bodies[x.perturbed].name + " " + (x.velocity ? rate : pose)[x.perturbed_dof],
               x.jacobian, x.coarse, x.fine);
  }
  if (found.size() > shown) fmt::print("  ... {} more pairs\n", found.size() - shown);
  fmt::print(
      "  jump: the difference grows as the step shrinks (a force that jumps; Newton cannot "
      "cross it); inexact: it stays; curvature: it shrinks\n");
}

void inspect(const InspectOptions& o) {
  const Scene scene = read_scene(o.scene);
  const Model& m = scene.model;
  const nlohmann::json c = model_counts(m);
  fmt::print("scene {}{}\n", o.scene, scene.zigzag ? " (zigzag generator)" : "");
  fmt::print("  bodies {} ({} fixed), elements {}, creases {}, DOFs {}\n", c["bodies"].get<int>(),
             c["fixed_bodies"].get<int>(), c["elements"].get<int>(), c["creases"].get<int>(),
             c["dofs"].get<int>());
  fmt::print("  mass {:.6g} kg, loads {}, drives {}, probes {}, contact {}\n",
             c["mass_kg"].get<double>(), c["loads"].get<int>(), c["drives"].get<int>(),
             c["probes"].get<int>(), m.contact.enabled ? "on" : "off");
  fmt::print("  gravity [{:g}, {:g}, {:g}] m/s^2, solver {}\n", m.gravity_W.x(), m.gravity_W.y(),
             m.gravity_W.z(), solver_name(scene.solver.kind));
  for (const DriveDef& d : m.drives) {
    fmt::print("  drive {}: body {}, travel {:.6g} m, step {:.6g} m, stiffness {:.6g} N/m\n",
               d.name, m.bodies[d.body].name, d.travel, d.step, d.stiffness);
  }
  for (const ShapeDef& shape : m.shapes) {
    fmt::print("  shape {} (a further folded frame of the pattern; probes of type shape name it)\n",
               shape.name);
  }
  for (const ProbeDef& p : m.probes) fmt::print("  probe {} ({})\n", p.name, probe_target(m, p));
  if (!o.incidence.empty()) {
    write_file_atomically(o.incidence, incidence_csv(m));
    fmt::print("wrote {} (incidence S^c: {} bodies x {} elements)\n", o.incidence, m.bodies.size(),
               m.elements.size());
  }
  if (!o.levers.empty()) {
    write_file_atomically(o.levers, levers_csv(m));
    fmt::print("wrote {} (lever vectors c_ik, body frames, m)\n", o.levers);
  }
  if (o.check_forces) check_forces(scene, o);
}

}  // namespace

void register_inspect(CLI::App& app) {
  auto o = std::make_shared<InspectOptions>();
  CLI::App* cmd = app.add_subcommand("inspect", "counts, incidence matrix and lever vectors");
  cmd->add_option("SCENE", o->scene, "scene file")->required();
  cmd->add_option("--incidence", o->incidence, "write S^c (bodies x elements) as CSV");
  cmd->add_option("--levers", o->levers, "write the lever vectors c_ik as CSV");
  cmd->add_flag("--check-forces", o->check_forces,
                "check the force Jacobian against central differences of the forces (finds "
                "forces that jump, where the implicit solver's steps crawl)");
  cmd->add_option("--state", o->state, "with --check-forces: at this state file (checkpoint.json)");
  cmd->add_option("--step", o->step, "with --check-forces: the difference step, m and rad")
      ->check(CLI::PositiveNumber);
  cmd->callback([o] { inspect(*o); });
}

}  // namespace finseg::cli

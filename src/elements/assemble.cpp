#include "elements/assemble.hpp"

#include "collision/contact_forces.hpp"
#include "collision/joint_stops.hpp"
#include "elements/assembler.hpp"
#include "elements/chamber_gas.hpp"
#include "elements/crease_history.hpp"
#include "elements/drive_gauge.hpp"
#include "elements/force_elements.hpp"
#include "elements/joint_rotation_history.hpp"
#include "elements/membrane_cells.hpp"
#include "elements/plate_cells.hpp"
#include "elements/pressure.hpp"

namespace finseg {
namespace {

void add_loads_and_gravity(const Model& model, const State& state, Assembler& as) {
  const double lambda = state.load_scale;
  for (const LoadDef& l : model.loads) {
    if (!l.follower) {
      // A dead load: its moment arm still turns with the body.
      as.single(l.body, [&](const auto& A, auto& w) {
        using T = typename std::decay_t<decltype(A.p_W)>::Scalar;
        const Vec3T<T> f = (lambda * l.force).cast<T>();
        w.add_force_at(f, A.point_W(l.point_B), A.p_W);
        w.tau_W += (lambda * l.moment).cast<T>();
        return T(-f.dot(A.point_W(l.point_B)));
      });
    } else {
      as.single(l.body, [&](const auto& A, auto& w) {
        using T = typename std::decay_t<decltype(A.p_W)>::Scalar;
        const Vec3T<T> f = A.R_WB * (lambda * l.force).cast<T>();
        w.add_force_at(f, A.point_W(l.point_B), A.p_W);
        w.tau_W += A.R_WB * (lambda * l.moment).cast<T>();
        return T(0);  // follower loads have no potential
      });
    }
  }
  if (model.gravity_W.squaredNorm() > 0) {
    for (size_t i = 0; i < model.bodies.size(); ++i) {
      const Vec3 f = lambda * model.bodies[i].mass * model.gravity_W;
      Wrench<double> w;
      w.f_W = f;
      as.add(static_cast<int>(i), w);
      as.add_energy(-f.dot(state.p_W[i]));
    }
  }
}

}  // namespace

void compute_forces(const Model& model, const State& state, BodyForces& out, ForceJacobian* jac) {
  const size_t n = model.bodies.size();
  out.f_W.assign(n, Vec3::Zero());
  out.tau_W.assign(n, Vec3::Zero());
  out.potential_energy = 0;
  Assembler as(model, state, out, jac);
  add_force_elements(model, state, as);
  add_plate_cells(model, state, as);
  add_membrane_cells(model, state, as);
  add_loads_and_gravity(model, state, as);
  add_pressure_loads(model, state, as);
  add_chamber_pressures(model, state, as);
  add_drive_gauges(model, state, as);
  add_contact_forces(model, state, as);
  add_joint_stops(model, state, as);
  if (jac) {
    jac->dq_blocks.to_sparse(model.num_dofs, jac->dq);
    jac->dv_blocks.to_sparse(model.num_dofs, jac->dv);
  }
}

bool conservative_stiffness(const Model& model) {
  for (const LoadDef& l : model.loads) {
    if (l.follower || l.moment.squaredNorm() > 0) return false;  // a dead moment: no potential
  }
  return model.pressures.empty() && model.chambers.empty() && !model.contact.enabled;
}

bool has_velocity_forces(const Model& model) {
  for (const ElementDef& e : model.elements) {
    if (e.C.squaredNorm() > 0) return true;
  }
  for (const DriveDef& d : model.drives) {
    if (d.damping > 0) return true;
  }
  return model.contact.enabled;
}

Eigen::VectorXd generalized_forces(const Model& model, const BodyForces& forces) {
  Eigen::VectorXd g(model.num_dofs);
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    g.segment<3>(d) = forces.f_W[i];
    g.segment<3>(d + 3) = forces.tau_W[i];
  }
  return g;
}

void commit_history(const Model& model, State& state, bool start) {
  commit_crease_history(model, state);
  commit_joint_rotations(model, state);
  commit_contact_history(model, state, start);
  commit_chamber_gas(model, state);
}

}  // namespace finseg

#include "solvers/volume_stiffness.hpp"

#include <Eigen/Dense>

#include "elements/chamber_gas.hpp"
#include "elements/chamber_surface.hpp"
#include "solvers/linear_solve.hpp"

namespace finseg {

VolumeStiffness volume_stiffness(const Model& model, const State& state) {
  VolumeStiffness out;
  for (std::size_t c = 0; c < model.chambers.size(); ++c) {
    const ChamberDef& def = model.chambers[c];
    if (def.gas == GasModel::Prescribed) continue;
    std::vector<Vec3> g;
    const double V = surface_volume(state, def, &g);
    const double slope = gas_pressure_slope(def, state.chambers[c], state.t, V, state.load_scale,
                                            state.quasi_static);
    if (slope == 0) continue;
    Eigen::VectorXd a = Eigen::VectorXd::Zero(model.num_dofs);
    for (std::size_t i = 0; i < def.vertices.size(); ++i) {
      const SurfaceVertex& v = def.vertices[i];
      const int d = v.body < 0 ? -1 : model.dof_of_body[v.body];
      if (d < 0) continue;
      a.segment<3>(d) += g[i];
      a.segment<3>(d + 3) += (state.R_WB[v.body] * v.x).cross(g[i]);
    }
    out.a.push_back(std::move(a));
    out.k.push_back(-slope);
  }
  return out;
}

bool solve_with_volume_stiffness(const Eigen::SparseMatrix<double>& A, double s,
                                 const VolumeStiffness& terms, const Eigen::VectorXd& b,
                                 Eigen::VectorXd& x) {
  if (!sparse_solve(A, b, x)) return false;
  const int n = static_cast<int>(terms.a.size());
  if (n == 0) return true;
  // (A + U C U^T)^-1 b = y - Z (C^-1 + U^T Z)^-1 U^T y with y = A^-1 b, Z = A^-1 U.
  Eigen::MatrixXd Z(b.size(), n), cap = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd z;
    if (!sparse_solve(A, terms.a[j], z)) return false;
    Z.col(j) = z;
  }
  Eigen::VectorXd Uty(n);
  for (int i = 0; i < n; ++i) {
    Uty[i] = terms.a[i].dot(x);
    for (int j = 0; j < n; ++j) cap(i, j) = terms.a[i].dot(Z.col(j));
    cap(i, i) += 1 / (s * terms.k[i]);
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(cap);
  if (!lu.isInvertible()) return false;
  x -= Z * lu.solve(Uty);
  return x.allFinite();
}

}  // namespace finseg

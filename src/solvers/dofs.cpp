#include "solvers/dofs.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "core/so3.hpp"

namespace finseg {

void apply_pose_increment(const Model& model, State& state, const Eigen::VectorXd& dq) {
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    state.p_W[i] += dq.segment<3>(d);
    state.R_WB[i] = so3_exp<double>(dq.segment<3>(d + 3)) * state.R_WB[i];
  }
}

RotationBlocks pose_increment_jacobians(const Model& model, const Eigen::VectorXd& dq) {
  RotationBlocks T(model.bodies.size(), Mat3::Identity());
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d >= 0) T[i] = so3_left_jacobian<double>(dq.segment<3>(d + 3));
  }
  return T;
}

RotationBlocks mass_pose_jacobians(const Model& model, const State& state,
                                   const Eigen::VectorXd& y) {
  RotationBlocks B(model.bodies.size(), Mat3::Zero());
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    const Mat3 J_W = inertia_W(model, state, i);
    const Vec3 w = y.segment<3>(d + 3);
    B[i] = J_W * hat<double>(w) - hat<double>(J_W * w);
  }
  return B;
}

namespace {

// Block-diagonal sparse matrix of the rotation blocks (the fallbacks below).
Eigen::SparseMatrix<double> rotation_block_matrix(const Model& model, const RotationBlocks& B,
                                                  double rest) {
  std::vector<Eigen::Triplet<double>> t;
  std::vector<bool> rotation(model.num_dofs, false);
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    for (int r = 0; r < 3; ++r) {
      rotation[d + 3 + r] = true;
      for (int c = 0; c < 3; ++c) t.emplace_back(d + 3 + r, d + 3 + c, B[i](r, c));
    }
  }
  for (int k = 0; rest != 0 && k < model.num_dofs; ++k) {
    if (!rotation[k]) t.emplace_back(k, k, rest);
  }
  Eigen::SparseMatrix<double> m(model.num_dofs, model.num_dofs);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

// Index of entry (row, col) in compressed A, or -1.
int entry_index(const Eigen::SparseMatrix<double>& A, int row, int col) {
  const int* inner = A.innerIndexPtr();
  const int begin = A.outerIndexPtr()[col], end = A.outerIndexPtr()[col + 1];
  const int* at = std::lower_bound(inner + begin, inner + end, row);
  return at != inner + end && *at == row ? static_cast<int>(at - inner) : -1;
}

bool shares_rows(const Eigen::SparseMatrix<double>& A, int c0, int c1) {
  const int* outer = A.outerIndexPtr();
  const int n = outer[c0 + 1] - outer[c0];
  return outer[c1 + 1] - outer[c1] == n &&
         std::equal(A.innerIndexPtr() + outer[c0], A.innerIndexPtr() + outer[c0] + n,
                    A.innerIndexPtr() + outer[c1]);
}

}  // namespace

void add_rotation_blocks(const Model& model, const RotationBlocks& B, double scale,
                         Eigen::SparseMatrix<double>& A) {
  if (!A.isCompressed()) A.makeCompressed();
  std::vector<int> at;  // entry of each rotation-block element, found before writing any
  at.reserve(9 * model.bodies.size());
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) at.push_back(entry_index(A, d + 3 + r, d + 3 + c));
    }
  }
  if (std::find(at.begin(), at.end(), -1) != at.end()) {
    A += scale * rotation_block_matrix(model, B, 0);
    return;
  }
  double* value = A.valuePtr();
  size_t k = 0;
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    if (model.dof_of_body[i] < 0) continue;
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) value[at[k++]] += scale * B[i](r, c);
    }
  }
}

void right_multiply_rotation_columns(const Model& model, const RotationBlocks& T,
                                     Eigen::SparseMatrix<double>& A) {
  if (!A.isCompressed()) A.makeCompressed();
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d >= 0 && !(shares_rows(A, d + 3, d + 4) && shares_rows(A, d + 3, d + 5))) {
      A = A * rotation_block_matrix(model, T, 1);
      return;
    }
  }
  const int* outer = A.outerIndexPtr();
  double* value = A.valuePtr();
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    const int n = outer[d + 4] - outer[d + 3];
    double* c0 = value + outer[d + 3];
    double* c1 = value + outer[d + 4];
    double* c2 = value + outer[d + 5];
    for (int k = 0; k < n; ++k) {
      const Eigen::RowVector3d row = Eigen::RowVector3d(c0[k], c1[k], c2[k]) * T[i];
      c0[k] = row[0];
      c1[k] = row[1];
      c2[k] = row[2];
    }
  }
}

bool add_on_pattern(const Eigen::SparseMatrix<double>& B, Eigen::SparseMatrix<double>& A) {
  if (!A.isCompressed() || B.rows() != A.rows() || B.cols() != A.cols()) return false;
  std::vector<int> at;  // A's entry of each of B's, all found before any is written
  at.reserve(static_cast<std::size_t>(B.nonZeros()));
  for (int c = 0; c < B.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(B, c); it; ++it) {
      at.push_back(entry_index(A, static_cast<int>(it.row()), c));
      if (at.back() < 0) return false;
    }
  }
  double* value = A.valuePtr();
  std::size_t k = 0;
  for (int c = 0; c < B.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(B, c); it; ++it) {
      value[at[k]] = it.value() + value[at[k]];
      ++k;
    }
  }
  return true;
}

Eigen::VectorXd displacement_weights(const Model& model) {
  Eigen::VectorXd w(model.num_dofs);
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    const BodyDef& b = model.bodies[i];
    w.segment<3>(d).setOnes();
    w.segment<3>(d + 3).setConstant(std::hypot(outline_radius(b.outline_B), 0.5 * b.thickness));
  }
  return w;
}

Eigen::VectorXd velocity_vector(const Model& model, const State& state) {
  Eigen::VectorXd v(model.num_dofs);
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    v.segment<3>(d) = state.v_W[i];
    v.segment<3>(d + 3) = state.w_W[i];
  }
  return v;
}

void set_velocity(const Model& model, State& state, const Eigen::VectorXd& v) {
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    state.v_W[i] = v.segment<3>(d);
    state.w_W[i] = v.segment<3>(d + 3);
  }
}

Eigen::SparseMatrix<double> mass_matrix(const Model& model, const State& state) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(12 * model.bodies.size());
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    const BodyDef& b = model.bodies[i];
    const Mat3 J_W = inertia_W(model, state, i);
    for (int r = 0; r < 3; ++r) {
      t.emplace_back(d + r, d + r, b.mass);
      for (int c = 0; c < 3; ++c) t.emplace_back(d + 3 + r, d + 3 + c, J_W(r, c));
    }
  }
  Eigen::SparseMatrix<double> M(model.num_dofs, model.num_dofs);
  M.setFromTriplets(t.begin(), t.end());
  return M;
}

Eigen::VectorXd mass_times(const Model& model, const State& state, const Eigen::VectorXd& x) {
  Eigen::VectorXd y(model.num_dofs);
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const int d = model.dof_of_body[i];
    if (d < 0) continue;
    y.segment<3>(d) = model.bodies[i].mass * x.segment<3>(d);
    y.segment<3>(d + 3) = inertia_W(model, state, i) * x.segment<3>(d + 3);
  }
  return y;
}

Eigen::VectorXd momentum(const Model& model, const State& state) {
  return mass_times(model, state, velocity_vector(model, state));
}

double kinetic_energy(const Model& model, const State& state) {
  double e = 0;
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const BodyDef& b = model.bodies[i];
    const Vec3 w_B = state.R_WB[i].transpose() * state.w_W[i];
    e += 0.5 * b.mass * state.v_W[i].squaredNorm() + 0.5 * w_B.dot(b.J_B * w_B);
  }
  return e;
}

void set_drives_at_time(const Model& model, State& state, double t) {
  for (size_t i = 0; i < model.drives.size(); ++i) {
    const DriveDef& d = model.drives[i];
    double s = d.speed * t;
    if (d.travel > 0) s = std::min(s, d.travel);
    state.drive_s[i] = s;
  }
}

std::string most_strained_element(const Model& model, const State& state) {
  double worst = -1;
  std::string text = "no force element";
  for (size_t k = 0; k < model.elements.size(); ++k) {
    const ElementDef& e = model.elements[k];
    const Mat3 R_WF = state.R_WB[e.outer] * e.R_outer_F;
    const Vec3 Pp = state.p_W[e.inner] + state.R_WB[e.inner] * e.c_inner_B;
    const Vec3 Pm = state.p_W[e.outer] + state.R_WB[e.outer] * e.c_outer_B;
    const Vec3 z = R_WF.transpose() * (Pp - Pm) - e.z0_F;
    const double scale = 2 * outline_radius(model.bodies[e.inner].outline_B);
    const double strain = z.norm() / scale;
    if (!(strain <= worst)) {
      worst = strain;
      text = fmt::format(
          "element {} ('{}', bodies {} and {}): separation {:.3g} m ({:.3g} of the "
          "segment diameter)",
          k, e.name, e.inner, e.outer, z.norm(), strain);
      if (!std::isfinite(strain)) break;
    }
  }
  return text;
}

void check_finite(const Model& model, const State& state, const BodyForces& forces,
                  const char* where) {
  bool ok = true;
  for (size_t i = 0; i < model.bodies.size() && ok; ++i) {
    ok = forces.f_W[i].allFinite() && forces.tau_W[i].allFinite() && state.p_W[i].allFinite() &&
         state.v_W[i].allFinite() && state.w_W[i].allFinite() &&
         state.p_W[i].norm() < 1e6 * std::max(1.0, model.sheet.length);
  }
  if (!ok) {
    throw DivergenceError(
        fmt::format("{} diverged at t = {:.6g}: non-finite or runaway state; "
                    "most strained {}",
                    where, state.t, most_strained_element(model, state)));
  }
}

}  // namespace finseg

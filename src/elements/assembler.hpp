// Accumulates element wrenches into per-body resultants and, on request, the exact
// Jacobian blocks of each element by forward-mode automatic differentiation.
//
// A kernel is a generic callable  T kernel(const BodyKin<T>& A, const BodyKin<T>& B,
// Wrench<T>& on_A, Wrench<T>& on_B)  (or the one-body form for `single`) that returns the
// element's potential energy. It is evaluated with T = double for forces, and with an
// autodiff scalar seeded with the bodies' pose perturbations (dp, dphi) and velocities when
// the Jacobian is wanted.
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "elements/assemble.hpp"
#include "elements/kinematics.hpp"

namespace finseg {

/// Where a two-body element's Jacobian blocks go (Assembler::reserve_pair): the block slots
/// of its (row body, column body) pairs, -1 where a body is fixed.
struct PairSlots {
  int row0[2] = {-1, -1};  ///< first dof of the inner and outer body (-1: fixed)
  int first_dq = -1;       ///< first dq slot (count: free bodies squared)
  int first_dv = -1;       ///< first dv slot, or -1 when the element has no velocity terms
  bool with_velocity = false;
  bool any() const { return row0[0] >= 0 || row0[1] >= 0; }
};

class Assembler {
 public:
  /// jac: where the Jacobian goes (its block scratch is filled); null for forces only.
  Assembler(const Model& model, const State& state, BodyForces& out, ForceJacobian* jac)
      : model_(model),
        state_(state),
        out_(out),
        jac_(jac),
        want_jacobian_(jac != nullptr),
        want_velocity_(jac != nullptr && jac->with_velocity),
        autodiff_elements_(jac != nullptr && jac->autodiff) {
    if (jac_) {
      jac_->dq_blocks.clear();
      jac_->dv_blocks.clear();
      jac_->secant_differs = false;
    }
  }

  bool want_jacobian() const { return want_jacobian_; }
  bool want_velocity_jacobian() const { return want_velocity_; }
  bool autodiff_elements() const { return autodiff_elements_; }
  /// Whether friction's blocks take their secant (ForceJacobian::friction_secant).
  bool friction_secant() const { return jac_ != nullptr && jac_->friction_secant; }
  /// Records that a secant differed from its tangent; sequential.
  void mark_secant_differs() { jac_->secant_differs = true; }
  /// Plain kinematics of body i from the state.
  BodyKin<double> kin(int i) const {
    return {state_.p_W[i], state_.R_WB[i], state_.v_W[i], state_.w_W[i]};
  }

  /// Adds a two-body element.
  template <class Kernel>
  void pair(int a, int b, Kernel&& kernel) {
    if (!want_jacobian_ || (model_.dof_of_body[a] < 0 && model_.dof_of_body[b] < 0)) {
      Wrench<double> wa, wb;
      out_.potential_energy += kernel(kin(a), kin(b), wa, wb);
      add(a, wa);
      add(b, wb);
      return;
    }
    if (want_velocity_) {
      pair_jacobian<24>(a, b, kernel);
    } else {
      pair_jacobian<12>(a, b, kernel);
    }
  }

  /// Reserves the Jacobian block slots of a two-body element between bodies a (inner) and
  /// b (outer), in order; sequential. The slots are filled later by fill_pair, in parallel.
  PairSlots reserve_pair(int a, int b, bool with_velocity) {
    PairSlots s;
    s.row0[0] = model_.dof_of_body[a];
    s.row0[1] = model_.dof_of_body[b];
    const int free = (s.row0[0] >= 0) + (s.row0[1] >= 0);
    s.first_dq = jac_->dq_blocks.append(free * free);
    s.with_velocity = with_velocity && free > 0;
    if (s.with_velocity) s.first_dv = jac_->dv_blocks.append(free * free);
    return s;
  }

  /// Writes an element's blocks (rows and columns as in ElementJacobian) into its slots;
  /// dv is read only when the slots have velocity terms. Safe in parallel across elements.
  void fill_pair(const PairSlots& s, const Mat12& dq, const Mat12& dv) {
    int q = s.first_dq, v = s.first_dv;
    for (int ra = 0; ra < 2; ++ra) {
      if (s.row0[ra] < 0) continue;
      for (int cb = 0; cb < 2; ++cb) {
        if (s.row0[cb] < 0) continue;
        jac_->dq_blocks.set(q++, s.row0[ra], s.row0[cb], dq.block<6, 6>(6 * ra, 6 * cb));
        if (s.with_velocity) {
          jac_->dv_blocks.set(v++, s.row0[ra], s.row0[cb], dv.block<6, 6>(6 * ra, 6 * cb));
        }
      }
    }
  }

  /// Adds a one-body load.
  template <class Kernel>
  void single(int a, Kernel&& kernel) {
    if (!want_jacobian_ || model_.dof_of_body[a] < 0) {
      Wrench<double> wa;
      out_.potential_energy += kernel(kin(a), wa);
      add(a, wa);
      return;
    }
    if (want_velocity_) {
      single_jacobian<12>(a, kernel);
    } else {
      single_jacobian<6>(a, kernel);
    }
  }

  /// Adds a plain wrench with no Jacobian contribution (constant loads).
  void add(int i, const Wrench<double>& w) {
    out_.f_W[i] += w.f_W;
    out_.tau_W[i] += w.tau_W;
  }

  /// Adds d(couple on body a)/d(rotation of body b), world frame, to the Jacobian (no-op
  /// when either body is fixed or no Jacobian is wanted).
  void add_rotation_block(int a, int b, const Mat3& dtau_dphi) {
    const int ra = model_.dof_of_body[a], cb = model_.dof_of_body[b];
    if (!jac_ || ra < 0 || cb < 0) return;
    jac_->dq_blocks.add_corner(ra, cb, dtau_dphi);
  }

  /// Adds d(wrench on body a)/d(pose of body b) (forces and couples by translations and
  /// world-frame rotations, as the Jacobian's blocks) to the Jacobian (no-op when either body
  /// is fixed or no Jacobian is wanted).
  void add_pose_block(int a, int b, const Mat6& block) {
    const int ra = model_.dof_of_body[a], cb = model_.dof_of_body[b];
    if (!jac_ || ra < 0 || cb < 0) return;
    jac_->dq_blocks.add(ra, cb, block);
  }

  /// Adds d(wrench on body a)/d(velocity and angular velocity of body b), world frame, when
  /// the velocity Jacobian is wanted (no-op otherwise or when either body is fixed).
  void add_velocity_block(int a, int b, const Mat6& block) {
    const int ra = model_.dof_of_body[a], cb = model_.dof_of_body[b];
    if (!want_velocity_ || ra < 0 || cb < 0) return;
    jac_->dv_blocks.add(ra, cb, block);
  }

  /// Adds potential energy that has no force of its own (bookkeeping).
  void add_energy(double e) { out_.potential_energy += e; }

 private:
  // N derivatives: poses of both bodies (12), plus their velocities when N = 24.
  template <int N, class Kernel>
  void pair_jacobian(int a, int b, Kernel& kernel) {
    using AD = AutoDiff<N>;
    const BodyKin<AD> A = seeded<N>(a, 0, 2), B = seeded<N>(b, 1, 2);
    Wrench<AD> wa, wb;
    out_.potential_energy += value_of(kernel(A, B, wa, wb));
    const int bodies[2] = {a, b};
    scatter<N>(a, wa, bodies, 2);
    scatter<N>(b, wb, bodies, 2);
  }

  template <int N, class Kernel>
  void single_jacobian(int a, Kernel& kernel) {
    using AD = AutoDiff<N>;
    const BodyKin<AD> A = seeded<N>(a, 0, 1);
    Wrench<AD> wa;
    out_.potential_energy += value_of(kernel(A, wa));
    const int bodies[1] = {a};
    scatter<N>(a, wa, bodies, 1);
  }

  // Slot s of n bodies: pose variables at 6s..6s+5, velocities (when N = 12 n) at
  // 6n+6s..6n+6s+5; with N = 6 n the velocities are plain constants.
  template <int N>
  BodyKin<AutoDiff<N>> seeded(int i, int slot, int n) const {
    using AD = AutoDiff<N>;
    using D = typename AD::DerType;
    BodyKin<AD> k;
    const bool free = model_.dof_of_body[i] >= 0;
    for (int r = 0; r < 3; ++r) {
      const int ip = 6 * slot + r;
      const int iv = 6 * n + 6 * slot + r, iw = 6 * n + 6 * slot + 3 + r;
      k.p_W[r] = free ? AD(state_.p_W[i][r], N, ip) : AD(state_.p_W[i][r], D::Zero());
      const bool seed_v = free && N == 12 * n;
      k.v_W[r] = seed_v ? AD(state_.v_W[i][r], N, iv) : AD(state_.v_W[i][r], D::Zero());
      k.w_W[r] = seed_v ? AD(state_.w_W[i][r], N, iw) : AD(state_.w_W[i][r], D::Zero());
    }
    // First order in dphi is all a Jacobian needs: R = (I + [dphi]x) R0, so column j of R
    // moves by dphi x R0.col(j): d R(:, j) / d dphi_r = e_r x R0.col(j). Written out instead
    // of multiplied in autodiff (a tenth of the Jacobian's cost).
    const Mat3& R0 = state_.R_WB[i];
    for (int j = 0; j < 3; ++j) {
      D d[3] = {D::Zero(), D::Zero(), D::Zero()};  // rows of column j
      for (int r = 0; free && r < 3; ++r) {
        const Vec3 dcol = Vec3::Unit(r).cross(R0.col(j));
        for (int row = 0; row < 3; ++row) d[row][6 * slot + 3 + r] = dcol[row];
      }
      for (int row = 0; row < 3; ++row) k.R_WB(row, j) = AD(R0(row, j), d[row]);
    }
    return k;
  }

  template <int N>
  void scatter(int i, const Wrench<AutoDiff<N>>& w, const int* bodies, int n) {
    Wrench<double> plain;
    for (int r = 0; r < 3; ++r) {
      plain.f_W[r] = w.f_W[r].value();
      plain.tau_W[r] = w.tau_W[r].value();
    }
    add(i, plain);
    const int row0 = model_.dof_of_body[i];
    if (row0 < 0) return;
    for (int s = 0; s < n; ++s) {
      const int col0 = model_.dof_of_body[bodies[s]];
      if (col0 < 0) continue;
      Mat6 bq;
      for (int r = 0; r < 6; ++r) {
        const auto& d = r < 3 ? w.f_W[r].derivatives() : w.tau_W[r - 3].derivatives();
        for (int c = 0; c < 6; ++c) bq(r, c) = d[6 * s + c];
      }
      jac_->dq_blocks.add(row0, col0, bq);
      if constexpr (N == 12 * 2 || N == 12) {
        if (N != 12 * n) continue;  // N = 12 with two bodies: no velocity derivatives
        Mat6 bv;
        for (int r = 0; r < 6; ++r) {
          const auto& d = r < 3 ? w.f_W[r].derivatives() : w.tau_W[r - 3].derivatives();
          for (int c = 0; c < 6; ++c) bv(r, c) = d[6 * n + 6 * s + c];
        }
        jac_->dv_blocks.add(row0, col0, bv);
      }
    }
  }

  const Model& model_;
  const State& state_;
  BodyForces& out_;
  ForceJacobian* jac_;
  bool want_jacobian_;
  bool want_velocity_;
  bool autodiff_elements_;
};

}  // namespace finseg

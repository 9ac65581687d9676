// The implicit solvers' iteration matrix is the derivative of their residual: checked against
// central differences of the residual at end-of-step rotations of tenths of a radian, where
// the exponential map's chain rule and the turning inertia matter (docs/solvers.md, "The
// iteration matrix"). And the SO(3) left Jacobian it rests on, against differences of the
// exponential map.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/so3.hpp"
#include "solvers/dofs.hpp"
#include "solvers/implicit_newton.hpp"
#include "validation_cantilever.hpp"

namespace finseg {
namespace newton_matrix_test {

Eigen::VectorXd random_vector(int n, double scale, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

// exp([phi + d]x) = exp([J_l d]x) exp([phi]x) to first order: J_l d is the derivative of
// log(exp([phi + e d]x) exp([phi]x)^T) at e = 0.
TEST(NewtonMatrix, LeftJacobianIsTheDerivativeOfTheExponentialMap) {
  std::mt19937 rng(7);
  for (const Vec3& phi :
       {Vec3(1e-6, 2e-6, -1e-6), Vec3(1e-3, 0, 2e-3), Vec3(0.3, -0.2, 0.4), Vec3(1.5, 2.0, -0.5)}) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 d = random_vector(3, 1, rng);
      const double e = 1e-6;
      const Mat3 R = so3_exp<double>(phi);
      const Vec3 fd = (so3_log<double>(so3_exp<double>(phi + e * d) * R.transpose()) -
                       so3_log<double>(so3_exp<double>(phi - e * d) * R.transpose())) /
                      (2 * e);
      const Vec3 Jd = so3_left_jacobian<double>(phi) * d;
      EXPECT_LT((Jd - fd).norm(), 1e-8 * d.norm()) << phi.transpose();
    }
  }
  EXPECT_TRUE(so3_left_jacobian<double>(Vec3::Zero()).isIdentity(0));
}

// A clamped, damped strip (bushings: forces turn with the segments) in flight: each segment
// turning at up to 8 rad/s, so that a step of 0.05 s turns it by up to 0.4 rad. Stiff (E 4 GPa),
// the forces' Jacobian and its chain rule through the exponential map rule the matrix; soft
// (E 1 mPa), the inertia turning with the segments does.
struct Flight {
  Model model;
  State start;
};

Flight strip_in_flight(double youngs_modulus, std::mt19937& rng) {
  CantileverSpec s = validation::slender_strip(6);
  s.thickness = 1e-3;
  s.youngs_modulus = youngs_modulus;
  s.tip_force = Vec3(0, 0, -0.05);
  s.damping_time = 1e-3;
  Flight f{build_cantilever_model(s), {}};
  f.start = initial_state(f.model);
  for (size_t i = 0; i < f.model.bodies.size(); ++i) {
    f.start.v_W[i] = random_vector(3, 0.5, rng);
    f.start.w_W[i] = random_vector(3, 8, rng);
  }
  return f;
}

// The rows of one kind (translation: 0, rotation: 3) of each free body.
Eigen::VectorXd rows(const Model& model, const Eigen::VectorXd& v, int kind) {
  Eigen::VectorXd out(3 * model.bodies.size());
  int n = 0;
  for (int d : model.dof_of_body) {
    if (d >= 0) out.segment<3>(3 * n++) = v.segment<3>(d + kind);
  }
  return out.head(3 * n);
}

// |A d - (r(x + e d) - r(x - e d)) / 2e| against |A d| along random directions d, the
// translation and the rotation rows apart (their scales differ by the segments' size squared).
double worst_mismatch(const Flight& f, double h, const AffineStep& map, const NewtonResidual& res,
                      const Eigen::VectorXd& x, std::mt19937& rng) {
  State state;
  Eigen::VectorXd r, rp, rm;
  Eigen::SparseMatrix<double> A, unused;
  newton_linearisation(f.model, f.start, h, map, res, x, state, r, A);
  double worst = 0;
  for (int k = 0; k < 4; ++k) {
    const Eigen::VectorXd d = random_vector(f.model.num_dofs, 1, rng);
    const double e = 1e-7 / (map.cq * d.lpNorm<Eigen::Infinity>());  // 1e-7 m and rad
    newton_linearisation(f.model, f.start, h, map, res, x + e * d, state, rp, unused);
    newton_linearisation(f.model, f.start, h, map, res, x - e * d, state, rm, unused);
    const Eigen::VectorXd Ad = A * d, fd = (rp - rm) / (2 * e);
    for (int kind : {0, 3}) {
      const Eigen::VectorXd a = rows(f.model, Ad, kind), b = rows(f.model, fd, kind);
      worst = std::max(worst, (a - b).norm() / a.norm());
    }
  }
  return worst;
}

TEST(NewtonMatrix, BackwardEulersMatrixIsTheResidualsDerivativeAtLargeRotations) {
  std::mt19937 rng(11);
  for (double youngs_modulus : {4e9, 1e-3}) {
    const Flight f = strip_in_flight(youngs_modulus, rng);
    const double h = 0.05;
    AffineStep map;  // backward Euler (src/solvers/implicit_euler.cpp): x = v_n+1
    map.dq0 = Eigen::VectorXd::Zero(f.model.num_dofs);
    map.v0 = Eigen::VectorXd::Zero(f.model.num_dofs);
    map.cq = h;
    map.cv = 1;
    NewtonResidual res;
    res.b = momentum(f.model, f.start);
    res.s = h;
    const Eigen::VectorXd x = velocity_vector(f.model, f.start);
    EXPECT_GT(map.cq * x.lpNorm<Eigen::Infinity>(), 0.3);  // rad: the case this test is for
    EXPECT_LT(worst_mismatch(f, h, map, res, x, rng), 1e-6) << youngs_modulus;
  }
}

// The generalized-alpha form: an offset pose increment, and the gyroscopic term of the
// acceleration form, whose inertia turns with the pose too.
TEST(NewtonMatrix, AccelerationFormsMatrixIsTheResidualsDerivativeAtLargeRotations) {
  std::mt19937 rng(13);
  for (double youngs_modulus : {4e9, 1e-3}) {
    const Flight f = strip_in_flight(youngs_modulus, rng);
    const double h = 0.05;
    AffineStep map;
    map.dq0 = h * velocity_vector(f.model, f.start);
    map.v0 = velocity_vector(f.model, f.start);
    map.cq = 0.3 * h * h;
    map.cv = 0.6 * h;
    NewtonResidual res;
    res.b = random_vector(f.model.num_dofs, 1e-3, rng);
    res.s = 1;
    res.with_gyro = true;
    const Eigen::VectorXd x = random_vector(f.model.num_dofs, 200, rng);  // rad/s^2, m/s^2
    EXPECT_LT(worst_mismatch(f, h, map, res, x, rng), 1e-6) << youngs_modulus;
  }
}

// The in-place block operations against dense arithmetic, on a matrix with every entry (the
// in-place path) and on one with holes (the sparse fallbacks); body 1 has no DOFs.
TEST(NewtonMatrix, RotationBlockOperationsMatchDenseArithmetic) {
  Model m;
  m.bodies.resize(3);
  m.dof_of_body = {0, -1, 6};
  m.num_dofs = 12;
  RotationBlocks B(3), T(3);
  for (int i = 0; i < 3; ++i) {
    B[i] = Mat3::Random();
    T[i] = Mat3::Random();
  }
  Eigen::MatrixXd blocks = Eigen::MatrixXd::Zero(12, 12), right = Eigen::MatrixXd::Identity(12, 12);
  for (int i : {0, 2}) {
    const int d = m.dof_of_body[i];
    blocks.block<3, 3>(d + 3, d + 3) = B[i];
    right.block<3, 3>(d + 3, d + 3) = T[i];
  }
  for (bool holes : {false, true}) {
    Eigen::MatrixXd dense = Eigen::MatrixXd::Random(12, 12);
    if (holes) {
      for (int k = 0; k < 12; ++k) dense(k, (5 * k + 3) % 12) = 0;
    }
    const Eigen::SparseMatrix<double> A = dense.sparseView();
    ASSERT_EQ(A.nonZeros(), holes ? 132 : 144);
    Eigen::SparseMatrix<double> added = A, turned = A;
    add_rotation_blocks(m, B, -0.7, added);
    right_multiply_rotation_columns(m, T, turned);
    EXPECT_LT((Eigen::MatrixXd(added) - (dense - 0.7 * blocks)).norm(), 1e-14) << holes;
    EXPECT_LT((Eigen::MatrixXd(turned) - dense * right).norm(), 1e-14) << holes;
  }
}

// A sum in place on A's pattern: the bits of Eigen's sparse sum B + A where B's entries fall on
// A's pattern; refused, A unchanged, where one does not.
TEST(NewtonMatrix, SumOnThePatternIsEigensSum) {
  Eigen::MatrixXd dense = Eigen::MatrixXd::Random(8, 8);
  for (int k = 0; k < 8; ++k) dense(k, (3 * k + 1) % 8) = 0;  // holes in A's pattern
  const Eigen::SparseMatrix<double> A = dense.sparseView();
  Eigen::MatrixXd inside = Eigen::MatrixXd::Zero(8, 8);
  for (int k = 0; k < 8; ++k) inside(k, k) = 0.1 + k;  // the diagonal: on the pattern
  inside(2, 5) = -3.0;
  Eigen::SparseMatrix<double> on = A;
  ASSERT_TRUE(add_on_pattern(inside.sparseView(), on));
  const Eigen::SparseMatrix<double> eigen_sum =
      Eigen::SparseMatrix<double>(inside.sparseView()) + A;
  ASSERT_EQ(on.nonZeros(), A.nonZeros());
  EXPECT_EQ(Eigen::MatrixXd(on), Eigen::MatrixXd(eigen_sum));
  Eigen::MatrixXd outside = inside;
  outside(0, 1) = 1.0;  // a hole of A
  Eigen::SparseMatrix<double> off = A;
  EXPECT_FALSE(add_on_pattern(outside.sparseView(), off));
  EXPECT_EQ(Eigen::MatrixXd(off), dense);
}

}  // namespace newton_matrix_test
}  // namespace finseg

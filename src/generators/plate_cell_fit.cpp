#include "generators/plate_cell_fit.hpp"

#include <Eigen/Eigenvalues>

namespace finseg {
namespace {

using Mat23 = Eigen::Matrix<double, 2, 3>;

// In-plane rotation across d for the uniform curvature kappa = (k_xx, k_yy, k_xy) of
// w = 1/2 k_xx x^2 + k_xy x y + 1/2 k_yy y^2: rotation vector (w_y, -w_x).
Mat23 rotation_of_curvature(const Vec2& d) {
  Mat23 B;
  B << 0, d.y(), d.x(), -d.x(), 0, -d.y();
  return B;
}

}  // namespace

Mat23 midpoint_tilt(const std::vector<Vec2>& outline_B) {
  // The cell's plane through its side midpoints has the mean gradient of that plane over the
  // cell, (1/A) sum_i l_i n_i w(m_i) (divergence theorem, exact for a linear w).
  Eigen::Matrix<double, 2, 3> grad = Eigen::Matrix<double, 2, 3>::Zero();
  double area2 = 0;
  const std::size_t n = outline_B.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &p = outline_B[i], &q = outline_B[(i + 1) % n];
    const Vec2 m = 0.5 * (p + q), ln(q.y() - p.y(), p.x() - q.x());
    area2 += p.x() * q.y() - q.x() * p.y();
    grad += ln * Eigen::RowVector3d(0.5 * m.x() * m.x(), 0.5 * m.y() * m.y(), m.x() * m.y());
  }
  grad /= 0.5 * area2;
  Mat23 rot;
  rot.row(0) = grad.row(1);
  rot.row(1) = -grad.row(0);
  return rot;
}

PlateCellDef plate_cell_correction(int body, double area,
                                   const std::vector<CellSideGeometry>& sides, double D, double nu,
                                   bool tilt_free) {
  PlateCellDef cell;
  cell.body = body;
  // Fit parameters z: the curvature (3), and with a free tilt the cell's own rotation
  // offset c (2): Theta_k = B_k kappa + c.
  const int nz = tilt_free ? 5 : 3;
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(nz, nz), M = G;
  std::vector<Eigen::MatrixXd> Wk;  // w_k A_k^T, A_k = [B_k, I]
  for (const CellSideGeometry& side : sides) {
    Eigen::MatrixXd A(2, nz);
    A.leftCols<3>() = rotation_of_curvature(side.d_M) + side.tilt;
    if (tilt_free) A.rightCols<2>().setIdentity();
    if (side.crease) {
      const Eigen::RowVectorXd b = side.across_M.transpose() * A;  // twist about the normal
      M += side.share * side.weight * b.transpose() * b;
      continue;
    }
    G += side.weight * A.transpose() * A;
    M += side.share * side.weight * A.transpose() * A;
    Wk.push_back(side.weight * A.transpose());
    cell.sides.push_back(side.side);
  }
  Eigen::MatrixXd W(nz, 2 * Wk.size());
  for (std::size_t k = 0; k < Wk.size(); ++k) W.middleCols(2 * k, 2) = Wk[k];
  Mat3 C;
  C << 1, nu, 0, nu, 1, 0, 0, 0, 2 * (1 - nu);
  // What the joints miss per uniform curvature; the tilt offset keeps the joints' own energy
  // and is uncoupled from the curvature.
  Eigen::MatrixXd S = -M;
  S.topLeftCorner<3, 3>() += area * D * C;
  if (tilt_free) S.bottomRightCorner<2, 2>().setZero();
  // Fit z = G^+ W Theta; the null space of G is condensed out of S.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(G);
  const double tol = 1e-10 * eig.eigenvalues().cwiseAbs().maxCoeff();
  Eigen::MatrixXd G_pinv = Eigen::MatrixXd::Zero(nz, nz);
  Eigen::MatrixXd N(nz, 0);
  for (int i = 0; i < nz; ++i) {
    const Eigen::VectorXd v = eig.eigenvectors().col(i);
    if (eig.eigenvalues()[i] > tol) {
      G_pinv += v * v.transpose() / eig.eigenvalues()[i];
    } else {
      N.conservativeResize(nz, N.cols() + 1);
      N.col(N.cols() - 1) = v;
    }
  }
  Eigen::MatrixXd S_eff = S;
  if (N.cols() > 0) {
    const Eigen::MatrixXd SN = S * N;
    S_eff -= SN * (N.transpose() * SN).inverse() * SN.transpose();
  }
  const Eigen::MatrixXd P = G_pinv * W;
  cell.Q = P.transpose() * S_eff * P;
  return cell;
}

}  // namespace finseg

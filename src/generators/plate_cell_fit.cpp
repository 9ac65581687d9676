#include "generators/plate_cell_fit.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

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

// Q of a correction: the cell's uniform field (3 components) fitted to its sides'
// measurements by weighted least squares, field = G^+ W measurements, and S (what the joints
// miss per uniform field) with the components no side sees condensed out (minimised: free).
Eigen::MatrixXd fitted_correction(const Mat3& S, const Mat3& G, const Eigen::MatrixXd& W) {
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(G);
  const double tol = 1e-10 * eig.eigenvalues().cwiseAbs().maxCoeff();
  Mat3 G_pinv = Mat3::Zero();
  Eigen::MatrixXd N(3, 0);
  for (int i = 0; i < 3; ++i) {
    const Vec3 v = eig.eigenvectors().col(i);
    if (eig.eigenvalues()[i] > tol) {
      G_pinv += v * v.transpose() / eig.eigenvalues()[i];
    } else {
      N.conservativeResize(3, N.cols() + 1);
      N.col(N.cols() - 1) = v;
    }
  }
  Mat3 S_eff = S;
  if (N.cols() > 0) {
    // Pseudo-inverse: where the joints already store all of the target energy in a component
    // no side sees (N^T S N = 0 there, e.g. crease sides counted whole), nothing is condensed.
    const Eigen::MatrixXd SN = S * N;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> en(N.transpose() * SN);
    const double s_tol = 1e-10 * std::max(S.cwiseAbs().maxCoeff(), 1e-300);
    Eigen::MatrixXd inv = Eigen::MatrixXd::Zero(N.cols(), N.cols());
    for (int i = 0; i < N.cols(); ++i) {
      const double l = en.eigenvalues()[i];
      if (std::abs(l) > s_tol)
        inv += en.eigenvectors().col(i) * en.eigenvectors().col(i).transpose() / l;
    }
    S_eff -= SN * inv * SN.transpose();
  }
  const Eigen::MatrixXd P = G_pinv * W;
  return P.transpose() * S_eff * P;
}

// Relative in-plane displacement across d for the uniform strain (e_xx, e_yy, g_xy),
// g_xy the engineering shear: (e_xx d_x + g_xy d_y / 2, g_xy d_x / 2 + e_yy d_y).
Mat23 displacement_of_strain(const Vec2& d) {
  Mat23 B;
  B << d.x(), 0, 0.5 * d.y(), 0, d.y(), 0.5 * d.x();
  return B;
}

}  // namespace

PlateCellDef plate_cell_correction(int body, double area,
                                   const std::vector<CellSideGeometry>& sides, double D,
                                   double nu) {
  PlateCellDef cell;
  cell.body = body;
  Mat3 G = Mat3::Zero(), M = Mat3::Zero();
  std::vector<Eigen::Matrix<double, 3, 2>> Wk;  // sum_k s_k w_k B_k^T Theta_k
  for (const CellSideGeometry& side : sides) {
    const Mat23 B = rotation_of_curvature(side.d_M);
    if (side.crease && side.crease_bends) {
      M += side.share * side.weight * B.transpose() * B;
      continue;
    }
    if (side.crease) {
      const Eigen::RowVector3d b = side.across_M.transpose() * B;  // twist about the normal
      M += side.share * side.weight * b.transpose() * b;
      continue;
    }
    // The fit weighs each side by the cell's share of its joint, as the energy does, so that
    // a uniform curvature is an equilibrium too (docs/stiffness.md, "Shares in the fit").
    const Eigen::Matrix<double, 3, 2> sw_Bt = side.strip_share * side.weight * B.transpose();
    const Mat3 sw_BtB = sw_Bt * B;
    G += sw_BtB;
    M += sw_BtB;
    Wk.push_back(sw_Bt);
    cell.sides.push_back(side.side);
  }
  Eigen::MatrixXd W(3, 2 * Wk.size());
  for (std::size_t k = 0; k < Wk.size(); ++k) W.middleCols<2>(2 * k) = Wk[k];
  Mat3 C;
  C << 1, nu, 0, nu, 1, 0, 0, 0, 2 * (1 - nu);
  cell.Q = fitted_correction(area * D * C - M, G, W);
  return cell;
}

namespace {

// The joints' energy per uniform strain, 1/2 e^T M e, and plane stress's A C.
Mat3 membrane_joint_energy(const std::vector<MembraneSideGeometry>& sides) {
  Mat3 M = Mat3::Zero();
  for (const MembraneSideGeometry& s : sides) {
    const Mat23 B = displacement_of_strain(s.d_M);
    M += s.share * B.transpose() * s.K_M * B;
  }
  return M;
}

Mat3 plane_stress(double area, double E, double nu, double t) {
  Mat3 C;  // engineering shear
  C << 1, nu, 0, nu, 1, 0, 0, 0, 0.5 * (1 - nu);
  return area * E * t / (1 - nu * nu) * C;
}

}  // namespace

double membrane_joint_excess(double area, const std::vector<MembraneSideGeometry>& sides, double E,
                             double nu, double t) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Mat3> ges(membrane_joint_energy(sides),
                                                           plane_stress(area, E, nu, t));
  return ges.eigenvalues().maxCoeff();
}

MembraneCellDef membrane_cell_correction(int body, double area,
                                         const std::vector<MembraneSideGeometry>& sides, double E,
                                         double nu, double t) {
  MembraneCellDef cell;
  cell.body = body;
  Mat3 G = Mat3::Zero();
  Eigen::MatrixXd W(3, 2 * sides.size());
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const Mat23 B = displacement_of_strain(sides[k].d_M);
    G += B.transpose() * sides[k].K_M * B;
    W.middleCols<2>(2 * k) = B.transpose() * sides[k].K_M;
    cell.sides.push_back(sides[k].side);
  }
  cell.Q = fitted_correction(plane_stress(area, E, nu, t) - membrane_joint_energy(sides), G, W);
  return cell;
}

}  // namespace finseg

// Consistent cell Hessian bending (docs/stiffness.md, "Triangular cells"). All in the flat
// sheet's material coordinates and in slopes g = grad w; an element's relative rotation
// Theta (inner relative to outer, rotation vector (w_y, -w_x)) is the slope jump
// J = (-Theta_y, Theta_x) from its outer cell into its inner one. Each cell's energy is built
// in its own material coordinates: a neighbour across a seam (whose copy of the side lies
// elsewhere on the flat sheet) is unrolled next to it first.
#include "generators/plate_hessian.hpp"

#include <Eigen/Eigenvalues>
#include <map>
#include <utility>

namespace finseg {
namespace {

using Mat23 = Eigen::Matrix<double, 2, 3>;
using Mat = Eigen::MatrixXd;
using Mat2 = Eigen::Matrix2d;

// A rigid motion of the flat sheet taking one cell's material coordinates into another's: the
// identity except across a seam.
struct Unroll {
  Mat2 Q = Mat2::Identity();
  Vec2 b = Vec2::Zero();
  Vec2 point(const Vec2& p) const { return Q * p + b; }
  // This map, then `next`.
  Unroll then(const Unroll& next) const { return {next.Q * Q, next.Q * b + next.b}; }
};

// The map that takes the segment p0 -> p1 onto q0 -> q1 (of the same length).
Unroll unroll_onto(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const Vec2 u = (p1 - p0).normalized(), v = (q1 - q0).normalized();
  Unroll r;
  r.Q << u.x() * v.x() + u.y() * v.y(), u.y() * v.x() - u.x() * v.y(),
      u.x() * v.y() - u.y() * v.x(), u.x() * v.x() + u.y() * v.y();
  r.b = q0 - r.Q * p0;
  return r;
}

// The slope change K d over d for the curvature K = (k_xx, k_yy, k_xy).
Mat23 hess_times(const Vec2& d) {
  Mat23 M;
  M << d.x(), 0, d.y(), 0, d.y(), d.x();
  return M;
}

// Interior: a free plate cell; Clamp: a plate joint to a fixed cell (zero slope on the side);
// Support: a crease (hinge) to a fixed cell (zero slope along the side); Free: no neighbour or
// a crease to a free cell (the crease law carries the moment).
enum class SideKind { Interior, Clamp, Support, Free };

struct Side {
  Vec2 m, n, t;  // midpoint, outward normal, unit vector along (counter-clockwise)
  double l = 0;
  SideKind kind = SideKind::Free;
  int element = -1, neighbour = -1;
  double sign = 1;    // slope jump into the neighbour = sign * J of the element
  double weight = 0;  // the side's plate-joint rotational stiffness, N m
  Unroll from_nb;     // the neighbour's material coordinates into this cell's
};

struct Cell {
  Vec2 c = Vec2::Zero();
  double area = 0;
  bool fixed = false;
  // Slope of the plane through the side midpoints less the slope at the centroid, per
  // curvature: delta = Delta K (the Crouzeix-Raviart tilt; zero on centrally symmetric cells).
  Mat23 Delta = Mat23::Zero();
  std::vector<Side> sides;
};

// Delta: the Crouzeix-Raviart tilt per curvature, from the sides' midpoints and normals.
Mat23 tilt_of(const Cell& cell) {
  Mat23 Delta = Mat23::Zero();
  for (const Side& s : cell.sides) {
    const Vec2 r = s.m - cell.c;
    Delta += s.l / cell.area * 0.5 * s.n *
             Eigen::RowVector3d(r.x() * r.x(), r.y() * r.y(), 2 * r.x() * r.y());
  }
  return Delta;
}

// Cell X as seen in other material coordinates (u: X's into those).
Cell unrolled(const Cell& X, const Unroll& u) {
  Cell Y = X;
  Y.c = u.point(X.c);
  for (Side& s : Y.sides) {
    s.m = u.point(s.m);
    s.n = u.Q * s.n;
    s.t = u.Q * s.t;
    s.from_nb = s.from_nb.then(u);
  }
  Y.Delta = tilt_of(Y);
  return Y;
}

std::vector<Cell> cells_of(const SegmentMesh& mesh, const Model& model,
                           const std::vector<int>& link_element) {
  std::map<std::pair<int, int>, int> link_at;  // (cell, first vertex of its side) -> link
  for (std::size_t k = 0; k < mesh.links.size(); ++k) {
    const CellLink& l = mesh.links[k];
    link_at[{l.left, l.a}] = static_cast<int>(k);
    link_at[{l.right, l.b_right}] = static_cast<int>(k);  // it runs b -> a on its copy
  }
  std::vector<Cell> cells(mesh.cells.size());
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    Cell& cell = cells[c];
    const BodyDef& body = model.bodies[c];
    cell.c = *body.centroid_M;
    cell.area = segment_area(body);
    cell.fixed = body.fixed;
    const std::vector<int>& loop = mesh.cells[c];
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Vec2 a = mesh.flat_m[loop[i]], b = mesh.flat_m[loop[(i + 1) % loop.size()]];
      Side s;
      s.l = (b - a).norm();
      s.t = (b - a) / s.l;
      s.n = Vec2(s.t.y(), -s.t.x());
      s.m = 0.5 * (a + b);
      const auto it = link_at.find({static_cast<int>(c), loop[i]});
      if (it != link_at.end()) {
        const CellLink& l = mesh.links[it->second];
        const ElementDef& e = model.elements[link_element[it->second]];
        s.element = link_element[it->second];
        s.neighbour = l.left == static_cast<int>(c) ? l.right : l.left;
        s.sign = l.left == static_cast<int>(c) ? 1.0 : -1.0;
        s.weight = e.K[4];
        if (l.seam >= 0) {
          const Vec2 &la = mesh.flat_m[l.a], &lb = mesh.flat_m[l.b];
          const Vec2 &ra = mesh.flat_m[l.a_right], &rb = mesh.flat_m[l.b_right];
          s.from_nb = s.sign > 0 ? unroll_onto(ra, rb, la, lb) : unroll_onto(la, lb, ra, rb);
        }
        const bool crease = e.crease >= 0, nb_fixed = model.bodies[s.neighbour].fixed;
        s.kind = nb_fixed ? (crease ? SideKind::Support : SideKind::Clamp)
                          : (crease ? SideKind::Free : SideKind::Interior);
      }
      cell.sides.push_back(s);
    }
    cell.Delta = tilt_of(cell);
  }
  return cells;
}

// The cells around `t` (its neighbours and theirs: what its fit and its neighbours' fits
// read) in t's material coordinates, with the maps that took them there.
struct Stencil {
  std::map<int, Cell> cell;
  std::map<int, Unroll> to_t;
};

Stencil stencil_of(const std::vector<Cell>& cells, int t) {
  Stencil st;
  st.cell[t] = cells[t];
  st.to_t[t] = Unroll{};
  std::vector<int> frontier{t};
  for (int depth = 0; depth < 2; ++depth) {
    std::vector<int> next;
    for (int x : frontier) {
      for (const Side& s : st.cell.at(x).sides) {
        if (s.neighbour < 0 || st.cell.count(s.neighbour)) continue;
        st.to_t[s.neighbour] = s.from_nb;  // already composed into t's coordinates
        st.cell[s.neighbour] = unrolled(cells[s.neighbour], s.from_nb);
        next.push_back(s.neighbour);
      }
    }
    frontier = std::move(next);
  }
  return st;
}

// A cell's least-squares curvature K = F J and its weighted residuals R J, J the stacked slope
// jumps of the stencil's elements (columns `col`). Each side predicts its jump from a uniform
// curvature exactly, the cells' tilts Delta included, so both are exact for quadratic w.
struct Fit {
  Mat F, R;
};

Fit fit_of(const std::map<int, Cell>& cells, int x, const std::map<int, int>& col, int ncol) {
  const Cell& X = cells.at(x);
  std::vector<Eigen::Matrix<double, Eigen::Dynamic, 3>> As;
  std::vector<Mat> Ps;
  std::vector<double> ws;
  for (const Side& s : X.sides) {
    if (s.kind == SideKind::Free) continue;
    Mat P = Mat::Zero(2, ncol);
    P.block<2, 2>(0, 2 * col.at(s.element)) = s.sign * Eigen::Matrix2d::Identity();
    Mat23 A;
    if (s.kind == SideKind::Interior) {
      const Cell& N = cells.at(s.neighbour);
      A = hess_times(N.c - X.c) + N.Delta - X.Delta;
    } else {
      A = hess_times(s.m - X.c) - X.Delta;  // the slope at the side's midpoint is zero
    }
    if (s.kind == SideKind::Support) {  // only the slope along the side is held
      As.push_back(s.t.transpose() * A);
      Ps.push_back(s.t.transpose() * P);
    } else {
      As.push_back(A);
      Ps.push_back(P);
    }
    ws.push_back(s.weight);
  }
  int rows = 0;
  for (const Mat& P : Ps) rows += static_cast<int>(P.rows());
  Mat A(rows, 3), P(rows, ncol);
  Eigen::VectorXd w(rows);
  for (std::size_t k = 0, r = 0; k < Ps.size(); r += Ps[k].rows(), ++k) {
    A.middleRows(r, As[k].rows()) = As[k];
    P.middleRows(r, Ps[k].rows()) = Ps[k];
    w.segment(r, Ps[k].rows()).setConstant(ws[k]);
  }
  const Mat3 G = A.transpose() * w.asDiagonal() * A;
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(G);
  const double tol = 1e-10 * eig.eigenvalues().cwiseAbs().maxCoeff();
  Mat3 G_pinv = Mat3::Zero();
  for (int i = 0; i < 3; ++i) {
    const Vec3 v = eig.eigenvectors().col(i);
    if (eig.eigenvalues()[i] > tol) G_pinv += v * v.transpose() / eig.eigenvalues()[i];
  }
  Fit f;
  f.F = G_pinv * A.transpose() * w.asDiagonal() * P;
  f.R = w.cwiseSqrt().asDiagonal() * (P - A * f.F);
  return f;
}

}  // namespace

std::vector<PlateCellDef> plate_hessian_cells(const SegmentMesh& mesh, const Model& model,
                                              const std::vector<int>& link_element, double D,
                                              double nu, double stabilisation) {
  const std::vector<Cell> cells = cells_of(mesh, model, link_element);
  Mat3 C;
  C << 1, nu, 0, nu, 1, 0, 0, 0, 2 * (1 - nu);
  C *= D;
  std::vector<PlateCellDef> out;
  for (std::size_t t = 0; t < cells.size(); ++t) {
    if (cells[t].fixed) continue;
    const Stencil st = stencil_of(cells, static_cast<int>(t));
    const Cell& T = st.cell.at(static_cast<int>(t));
    // Stencil: the elements on the cell's sides and on its free neighbours' sides.
    std::map<int, int> col;
    std::vector<int> order;
    auto add = [&](const Cell& X) {
      for (const Side& s : X.sides) {
        if (s.kind == SideKind::Free || col.count(s.element)) continue;
        col[s.element] = static_cast<int>(order.size());
        order.push_back(s.element);
      }
    };
    add(T);
    for (const Side& s : T.sides) {
      if (s.kind == SideKind::Interior) add(st.cell.at(s.neighbour));
    }
    if (order.empty()) continue;
    const int ncol = 2 * static_cast<int>(order.size());
    const Fit fT = fit_of(st.cell, static_cast<int>(t), col, ncol);
    // Slope at a point from cell X's plane and fit, less X's slope.
    auto extrapolate = [&](const Cell& X, const Fit& f, const Vec2& p) -> Mat {
      return (hess_times(p - X.c) - X.Delta) * f.F;
    };
    // Green's formula: A kappa = sum_sides l sym(g_side (x) n), g_side the slope at the side's
    // midpoint, one value per side (the mean of both cells' extrapolations), so the sum over
    // cells telescopes to the boundary. g_T drops out (sum l n = 0).
    Mat L = Mat::Zero(3, ncol);
    for (const Side& s : T.sides) {
      Mat v = Mat::Zero(2, ncol);
      Mat jump = Mat::Zero(2, ncol);
      if (s.kind != SideKind::Free) {
        jump.block<2, 2>(0, 2 * col.at(s.element)) = s.sign * Eigen::Matrix2d::Identity();
      }
      switch (s.kind) {
        case SideKind::Interior: {
          const Cell& N = st.cell.at(s.neighbour);
          const Fit fN = fit_of(st.cell, s.neighbour, col, ncol);
          v = 0.5 * extrapolate(T, fT, s.m) + 0.5 * (jump + extrapolate(N, fN, s.m));
          break;
        }
        case SideKind::Clamp:
          v = jump;
          break;
        case SideKind::Support:
          v = s.t * (s.t.transpose() * jump) + s.n * (s.n.transpose() * extrapolate(T, fT, s.m));
          break;
        case SideKind::Free:
          v = extrapolate(T, fT, s.m);
          break;
      }
      const double f = s.l / T.area;
      L.row(0) += f * s.n.x() * v.row(0);
      L.row(1) += f * s.n.y() * v.row(1);
      L.row(2) += f * 0.5 * (s.n.y() * v.row(0) + s.n.x() * v.row(1));
    }
    // Slope jumps from rotations: J = (-Theta_y, Theta_x).
    Mat to_J = Mat::Zero(ncol, ncol);
    for (int k = 0; k < ncol; k += 2) {
      to_J(k, k + 1) = -1;
      to_J(k + 1, k) = 1;
    }
    const Mat Lt = L * to_J, Rt = fT.R * to_J;
    PlateCellDef cell;
    cell.body = static_cast<int>(t);
    cell.correction = false;
    // Each element's rotation read in its outer cell's frame, turned into t's.
    for (int e : order) {
      Mat3 R_TO = Mat3::Identity();
      R_TO.topLeftCorner<2, 2>() = st.to_t.at(model.elements[e].outer).Q;
      cell.sides.push_back({e, R_TO * model.elements[e].R_outer_F, 1.0});
    }
    cell.Q = T.area * Lt.transpose() * C * Lt + stabilisation * Rt.transpose() * Rt;
    out.push_back(std::move(cell));
  }
  return out;
}

}  // namespace finseg

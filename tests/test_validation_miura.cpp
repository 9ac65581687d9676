// Folding by simulation against rigid-origami kinematics. Miura sheets of rigid panels (one
// segment per face) joined by soft linear creases, no contact, folded from flat by carrying
// the creases' rest angles to a share of their target angles (generators/folding.hpp):
//  - a single degree-4 vertex (2 x 2 Miura): its fold angles obey Huffman's relation for
//    flat-foldable degree-4 vertices, tan(rho_b / 2) = tan(rho_a / 2) / cos(gamma) (the
//    straight creases b, the zigzag creases a; Huffman 1976, Hull, "Origametry" ch. 5);
//  - a 4 x 4 sheet: outer dimensions against Schenk and Guest's closed form (PNAS 2013)
//    over the whole fold range.
// Shares below one give targets that no rigid folding meets (the four angles' ratios change
// along the fold), so the sheet settles where the mechanism allows: the relations must hold
// there too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "elements/crease_law.hpp"
#include "generators/folding.hpp"
#include "generators/pattern_sheet.hpp"
#include "patterns/miura_pattern.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace validation_miura_test {

MiuraSpec miura(int rows, int columns, double theta) {
  MiuraSpec s;
  s.rows = rows;
  s.columns = columns;
  s.side_a = 0.02;
  s.side_b = 0.026;
  s.sector_angle = 55 * kDegToRad;
  s.fold_angle = theta;
  return s;
}

// Rigid panels (stiff sheet, one segment per face), soft linear creases resting flat, face 0
// clamped; folded statically to `share` of the pattern's fold angles.
struct Folded {
  Model model;
  State state;
  CreasePattern pattern;
};

Folded flat_sheet(const MiuraSpec& s) {
  Folded f;
  f.pattern = miura_crease_pattern(s);
  PatternSheetSpec spec;
  spec.thickness = 2e-4;
  spec.youngs_modulus = 5e9;
  spec.subdivisions = 1;
  spec.start_folded = false;
  spec.fixed_faces = {0};
  spec.mountain_law = spec.valley_law = std::make_shared<LinearCreaseLaw>(1e-5, 0.0);
  spec.laws_rest_at_pattern = true;
  f.model = build_pattern_model(f.pattern, spec);
  // Rigid folding starts at 1 deg, not at the flat sheet, where every vertex could fold either
  // way to first order: the poses of the same sheet folded rigidly to 1 deg.
  MiuraSpec start = s;
  start.fold_angle = 1 * kDegToRad;
  spec.start_folded = true;
  const Model started = build_pattern_model(miura_crease_pattern(start), spec);
  for (std::size_t b = 0; b < f.model.bodies.size(); ++b) {
    f.model.bodies[b].p0_W = started.bodies[b].p0_W;
    f.model.bodies[b].R0_WB = started.bodies[b].R0_WB;
  }
  for (std::size_t c = 0; c < f.model.creases.size(); ++c) {
    f.model.creases[c].initial_fold_angle = started.creases[c].initial_fold_angle;
  }
  f.state = initial_state(f.model);
  return f;
}

// Folds on from where the sheet is to `share` of the pattern's fold angles (static).
void fold_to(Folded& f, double share) {
  const Model folding = folding_model(f.model, f.state, share, 1.0);
  SolverSettings set;
  set.kind = SolverKind::Static;
  set.load_steps = 10;
  const SolverStats st = run_solver(folding, f.state, set, nullptr);
  EXPECT_EQ(st.status, "ok") << st.message;
}

Folded fold(const MiuraSpec& s, double share) {
  Folded f = flat_sheet(s);
  fold_to(f, share);
  return f;
}

// World position of pattern vertex v: the corner of a face's segment at v.
Vec3 vertex_W(const Folded& f, int v) {
  const Vec2 x = f.pattern.vertices_flat_m[v];
  for (std::size_t b = 0; b < f.model.bodies.size(); ++b) {
    const BodyDef& body = f.model.bodies[b];
    for (const Vec2& c : body.outline_B) {
      if ((*body.centroid_M + c - x).norm() < 1e-12) {
        return f.state.p_W[b] + f.state.R_WB[b] * Vec3(c.x(), c.y(), 0);
      }
    }
  }
  ADD_FAILURE() << "vertex " << v << " on no segment";
  return Vec3::Zero();
}

// Fold angle (rad, magnitude) of the crease on pattern edge u-v.
double crease_angle(const Folded& f, int u, int v) {
  for (std::size_t e = 0; e < f.pattern.edges.size(); ++e) {
    const auto& ev = f.pattern.edges[e].vertices;
    if (!((ev[0] == u && ev[1] == v) || (ev[0] == v && ev[1] == u))) continue;
    const std::string prefix = "crease" + std::to_string(e + 1) + "_";
    for (std::size_t k = 0; k < f.model.elements.size(); ++k) {
      if (f.model.elements[k].name.rfind(prefix, 0) == 0) {
        return std::abs(f.state.history[k].fold_angle);
      }
    }
  }
  ADD_FAILURE() << "no crease on " << u << "-" << v;
  return 0;
}

TEST(MiuraValidation, SingleDegreeFourVertexFollowsHuffmansRelation) {
  for (const double theta_deg : {30.0, 60.0, 80.0}) {
    for (const double share : {0.5, 1.0}) {
      const MiuraSpec s = miura(2, 2, theta_deg * kDegToRad);
      const Folded f = fold(s, share);
      auto id = [](int i, int j) { return i * 3 + j; };
      const double rho_a1 = crease_angle(f, id(0, 1), id(1, 1));
      const double rho_a2 = crease_angle(f, id(1, 1), id(2, 1));
      const double rho_b1 = crease_angle(f, id(1, 0), id(1, 1));
      const double rho_b2 = crease_angle(f, id(1, 1), id(1, 2));
      EXPECT_GT(rho_b1, 0.3 * share * 2 * theta_deg * kDegToRad) << "barely folded";
      EXPECT_NEAR(rho_a1, rho_a2, 1e-5);
      EXPECT_NEAR(rho_b1, rho_b2, 1e-5);
      const double predicted = 2 * std::atan(std::tan(rho_a1 / 2) / std::cos(s.sector_angle));
      EXPECT_NEAR(rho_b1, predicted, 1e-5 * predicted)
          << "theta " << theta_deg << " deg, share " << share;
      if (share == 1.0) {  // compatible targets: exactly the pattern's fold
        EXPECT_NEAR(rho_b1, 2 * s.fold_angle, 1e-5);
      }
    }
  }
}

TEST(MiuraValidation, OuterDimensionsFollowTheClosedFormOverTheFoldRange) {
  // Folded from flat towards 85 deg along one path, stopping at shares of the targets: each
  // equilibrium is a rigid folding state; theta from its straight creases' fold angle
  // (2 theta), then its width and length must be Schenk and Guest's at that theta.
  // Rigid-motion invariant measures (rows and columns even): |v(0,0) v(0,N)| = N S,
  // |v(0,0) v(M,0)| = M L.
  const MiuraSpec s = miura(4, 4, 85 * kDegToRad);
  auto id = [&](int i, int j) { return i * (s.columns + 1) + j; };
  double worst = 0, previous_theta = 0;
  Folded f = flat_sheet(s);
  for (const double share : {0.1, 0.3, 0.5, 0.7, 0.9, 1.0}) {
    fold_to(f, share);
    const double width = (vertex_W(f, id(0, s.columns)) - vertex_W(f, id(0, 0))).norm();
    const double length = (vertex_W(f, id(s.rows, 0)) - vertex_W(f, id(0, 0))).norm();
    const double theta = crease_angle(f, id(1, 0), id(1, 1)) / 2;
    EXPECT_GT(theta, previous_theta) << "share " << share;  // the fold range is swept
    previous_theta = theta;
    const MiuraCell c = miura_cell(s, theta);
    EXPECT_NEAR(width, s.columns * c.S, 1e-6 * s.side_b) << "share " << share;
    EXPECT_NEAR(length, s.rows * c.L, 1e-6 * s.side_a) << "share " << share;
    worst = std::max({worst, std::abs(width - s.columns * c.S) / s.side_b,
                      std::abs(length - s.rows * c.L) / s.side_a});
  }
  EXPECT_GT(previous_theta, 84 * kDegToRad);
  RecordProperty("worst_error_over_side", std::to_string(worst));
}

}  // namespace validation_miura_test
}  // namespace finseg

#include "patterns/miura_pattern.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "patterns/pattern_checks.hpp"

namespace finseg {
namespace {

void validate(const MiuraSpec& s) {
  auto fail = [](const char* field, const std::string& what) {
    throw InputError("<api>", field, what);
  };
  if (s.rows < 1 || s.rows > 1000) fail("rows", fmt::format("{}; allowed 1..1000", s.rows));
  if (s.columns < 1 || s.columns > 1000)
    fail("columns", fmt::format("{}; allowed 1..1000", s.columns));
  if (!(s.side_a > 0)) fail("side_a", fmt::format("{} m; must be > 0", s.side_a));
  if (!(s.side_b > 0)) fail("side_b", fmt::format("{} m; must be > 0", s.side_b));
  if (!(s.sector_angle > 0 && s.sector_angle < kPi / 2)) {
    fail("sector_angle",
         fmt::format("{} deg; allowed range (0, 90) deg", s.sector_angle / kDegToRad));
  }
  if (!(s.fold_angle >= 0 && s.fold_angle < kPi / 2)) {
    fail("fold_angle", fmt::format("{} deg; allowed range [0, 90) deg", s.fold_angle / kDegToRad));
  }
}

}  // namespace

MiuraCell miura_cell(const MiuraSpec& s, double theta) {
  const double tg = std::tan(s.sector_angle), st = std::sin(theta), ct = std::cos(theta);
  const double sg = std::sin(s.sector_angle);
  const double root = std::sqrt(1 + ct * ct * tg * tg);
  return {s.side_b * ct * tg / root, s.side_a * std::sqrt(1 - st * st * sg * sg), s.side_b / root,
          s.side_a * st * sg};
}

MiuraDimensions miura_dimensions(const MiuraSpec& s, double theta) {
  const MiuraCell c = miura_cell(s, theta);
  return {s.columns * c.S, s.rows * c.L + c.V, c.H};
}

double miura_theta_from_height(const MiuraSpec& s, double z) {
  return std::asin(std::clamp(z / (s.side_a * std::sin(s.sector_angle)), -1.0, 1.0));
}

CreasePattern miura_crease_pattern(const MiuraSpec& s) {
  validate(s);
  const int M = s.rows, N = s.columns;
  auto id = [&](int i, int j) { return i * (N + 1) + j; };
  CreasePattern p;
  // Folded coordinates at theta; the signs of the fold angles are those of any theta in
  // (0, 90) deg, so a flat pattern (theta = 0) gets them from 45 deg.
  // ... turned so that face 0 lies where it lies flat: a fold from the flat sheet with
  // face 0 clamped ends in exactly these coordinates.
  auto folded = [&](double theta) {
    const MiuraCell c = miura_cell(s, theta);
    std::vector<Vec3> v;
    for (int i = 0; i <= M; ++i) {
      for (int j = 0; j <= N; ++j) {
        v.emplace_back(j * c.S, i * c.L + (j % 2) * c.V, (i % 2) * c.H);
      }
    }
    auto frame = [](const Vec3& o, const Vec3& a, const Vec3& b) {
      const Vec3 e1 = (a - o).normalized(), n = e1.cross(b - o).normalized();
      Mat3 F;
      F << e1, n.cross(e1), n;
      return F;
    };
    auto flat3 = [&](int k) { return Vec3(p.vertices_flat_m[k].x(), p.vertices_flat_m[k].y(), 0); };
    const Mat3 R = frame(flat3(id(0, 0)), flat3(id(0, 1)), flat3(id(1, 0))) *
                   frame(v[id(0, 0)], v[id(0, 1)], v[id(1, 0)]).transpose();
    const Vec3 o = v[id(0, 0)];
    for (Vec3& x : v) x = R * (x - o) + flat3(id(0, 0));
    return v;
  };
  p.meta.file_creator = "finseg";
  p.meta.frame_title =
      fmt::format("Miura-ori {} x {}, sector angle {:.6g} deg", M, N, s.sector_angle / kDegToRad);
  const double bs = s.side_b * std::sin(s.sector_angle), bc = s.side_b * std::cos(s.sector_angle);
  for (int i = 0; i <= M; ++i) {
    for (int j = 0; j <= N; ++j)
      p.vertices_flat_m.emplace_back(j * bs, i * s.side_a + (j % 2) * bc);
  }
  for (int i = 0; i < M; ++i) {
    for (int j = 0; j < N; ++j) {
      p.faces.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
    }
  }
  p.edges = edges_from_faces(p.faces);
  derive_edge_faces(p, "<miura>");
  p.vertices_folded_m = folded(kPi / 4);
  std::vector<double> sign(p.edges.size(), 0);
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    if (p.edges[e].face_count() == 2)
      sign[e] = measured_fold_angle(p, static_cast<int>(e)) > 0 ? 1 : -1;
  }
  p.vertices_folded_m = folded(s.fold_angle);
  p.has_fold_angles = true;
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    PatternEdge& edge = p.edges[e];
    if (sign[e] == 0) continue;
    edge.assignment = sign[e] > 0 ? EdgeAssignment::Valley : EdgeAssignment::Mountain;
    edge.fold_angle = s.fold_angle > 0 ? measured_fold_angle(p, static_cast<int>(e)) : 0.0;
  }
  return p;
}

}  // namespace finseg

#include "patterns/miura_tube_pattern.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "core/error.hpp"
#include "patterns/pattern_checks.hpp"

namespace finseg {

namespace {

void check_spec(const MiuraTubeSpec& s) {
  auto refuse = [](const char* field, const std::string& why) {
    throw InputError("<api>", field, why);
  };
  if (s.columns < 1 || s.columns > 1000) {
    refuse("columns", fmt::format("{}; allowed 1..1000", s.columns));
  }
  if (!(s.side_a > 0 && std::isfinite(s.side_a))) {
    refuse("side_a", fmt::format("{} m; must be > 0", s.side_a));
  }
  if (!(s.side_b > 0 && std::isfinite(s.side_b))) {
    refuse("side_b", fmt::format("{} m; must be > 0", s.side_b));
  }
  if (!(s.sector_angle > 0 && s.sector_angle < kPi / 2)) {
    refuse("sector_angle", fmt::format("{} deg; allowed (0, 90) deg", s.sector_angle / kDegToRad));
  }
  // Flat (0) and fully folded (90 deg) enclose no volume: no chamber.
  if (!(s.fold_angle > 0 && s.fold_angle < kPi / 2)) {
    refuse("fold_angle", fmt::format("{} deg; allowed (0, 90) deg", s.fold_angle / kDegToRad));
  }
}

}  // namespace

MiuraSpec miura_tube_sheet(const MiuraTubeSpec& s) {
  MiuraSpec m;
  m.rows = 2;
  m.columns = s.columns;
  m.side_a = s.side_a;
  m.side_b = s.side_b;
  m.sector_angle = s.sector_angle;
  m.fold_angle = s.fold_angle;
  return m;
}

MiuraTubeShape miura_tube_shape(const MiuraTubeSpec& s, double theta) {
  const MiuraCell c = miura_cell(miura_tube_sheet(s), theta);
  return {c.L, c.H, s.columns * c.S};
}

double miura_tube_volume(const MiuraTubeSpec& s, double theta) {
  const MiuraTubeShape t = miura_tube_shape(s, theta);
  return 2 * t.half_width * t.half_height * t.length;
}

double miura_tube_max_volume(const MiuraTubeSpec& s) {
  const double sg = std::sin(s.sector_angle);
  return s.columns * s.side_b * s.side_a * s.side_a * sg * sg;
}

int miura_tube_vertex_index(const MiuraTubeSpec& s, int sheet, int i, int j) {
  return (sheet * 3 + i) * (s.columns + 1) + j;
}

Vec3 miura_tube_vertex(const MiuraTubeSpec& s, double theta, int sheet, int i, int j) {
  const MiuraCell c = miura_cell(miura_tube_sheet(s), theta);
  const double z = i == 1 ? c.H : 0.0;
  return {j * c.S, i * c.L + (j % 2) * c.V, sheet == 0 ? z : -z};
}

std::vector<int> miura_tube_column_faces(const MiuraTubeSpec& s, int column) {
  if (column < 0 || column >= s.columns) {
    throw InputError("<api>", "column", fmt::format("{}; allowed 0..{}", column, s.columns - 1));
  }
  return {4 * column, 4 * column + 1, 4 * column + 2, 4 * column + 3};
}

int miura_tube_cap_face(const MiuraTubeSpec& s, int end) {
  if (!s.caps) throw InputError("<api>", "caps", "the tube has no caps");
  if (end != 0 && end != 1) throw InputError("<api>", "end", fmt::format("{}; 0 or 1", end));
  return 4 * s.columns + end;
}

CreasePattern miura_tube_crease_pattern(const MiuraTubeSpec& s) {
  check_spec(s);
  const int n = s.columns;
  const double a = s.side_a, bs = s.side_b * std::sin(s.sector_angle),
               bc = s.side_b * std::cos(s.sector_angle);
  const double gap = a;  // between the pieces of the development
  CreasePattern p;
  p.meta.file_creator = "finseg";
  p.meta.frame_title = fmt::format("Miura tube of {} columns, sector angle {:.6g} deg", n,
                                   s.sector_angle / kDegToRad);
  auto id = [&](int sheet, int i, int j) { return miura_tube_vertex_index(s, sheet, i, j); };
  for (int sheet : {0, 1}) {
    for (int i = 0; i <= 2; ++i) {
      for (int j = 0; j <= n; ++j) {
        const double y = i * a + (j % 2) * bc;  // the Miura sheet's development
        p.vertices_flat_m.emplace_back(j * bs, sheet == 0 ? y : -y - gap);
        p.vertices_folded_m.push_back(miura_tube_vertex(s, s.fold_angle, sheet, i, j));
      }
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i : {0, 1})
      p.faces.push_back({id(0, i, j), id(0, i, j + 1), id(0, i + 1, j + 1), id(0, i + 1, j)});
    // The mirror image: the loop reversed keeps it counter-clockwise and the normals outward.
    for (int i : {0, 1})
      p.faces.push_back({id(1, i + 1, j), id(1, i + 1, j + 1), id(1, i, j + 1), id(1, i, j)});
  }
  if (s.caps) {
    // Each cap runs the tube's end loop backwards: at x = 0 the tube's faces run R1 -> Bot ->
    // R2 -> T, at the far end R1 -> T -> R2 -> Bot.
    for (int end : {0, 1}) {
      const int j = end == 0 ? 0 : n;
      const std::array<int, 4> loop =
          end == 0 ? std::array<int, 4>{id(0, 0, j), id(0, 1, j), id(0, 2, j), id(1, 1, j)}
                   : std::array<int, 4>{id(0, 0, j), id(1, 1, j), id(0, 2, j), id(0, 1, j)};
      // Developed in the plane x = const: (y, z), mirrored when that runs clockwise.
      std::array<Vec2, 4> uv;
      double area2 = 0;
      for (int k = 0; k < 4; ++k) {
        const Vec3& x = p.vertices_folded_m[loop[k]];
        uv[k] = Vec2(x.y(), x.z());
      }
      for (int k = 0; k < 4; ++k) {
        area2 += uv[k].x() * uv[(k + 1) % 4].y() - uv[k].y() * uv[(k + 1) % 4].x();
      }
      double u_lo = uv[0].x(), u_hi = uv[0].x(), v_lo = 0;
      for (Vec2& q : uv) {
        if (area2 < 0) q.y() = -q.y();
        u_lo = std::min(u_lo, q.x());
        u_hi = std::max(u_hi, q.x());
        v_lo = std::min(v_lo, q.y());
      }
      const double x0 = end == 0 ? -gap - (u_hi - u_lo) : n * bs + gap;
      std::vector<int> face;
      for (int k = 0; k < 4; ++k) {
        face.push_back(static_cast<int>(p.vertices_flat_m.size()));
        p.vertices_flat_m.emplace_back(x0 + uv[k].x() - u_lo, uv[k].y() - v_lo);
        p.vertices_folded_m.push_back(p.vertices_folded_m[loop[k]]);
      }
      p.faces.push_back(face);
    }
  }
  p.edges = edges_from_faces(p.faces);
  derive_edge_faces(p, "<miura tube>");
  std::map<std::pair<int, int>, int> edge_of;
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    const auto [u, v] = p.edges[e].vertices;
    edge_of[{std::min(u, v), std::max(u, v)}] = static_cast<int>(e);
  }
  auto edge = [&](int u, int v) { return edge_of.at({std::min(u, v), std::max(u, v)}); };
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    PatternEdge& ed = p.edges[e];
    if (ed.face_count() != 2) continue;
    ed.fold_angle = measured_fold_angle(p, static_cast<int>(e));
    ed.assignment = ed.fold_angle > 0 ? EdgeAssignment::Valley : EdgeAssignment::Mountain;
  }
  // The ridge lines, upper onto lower; each cap side onto the tube's end edge it runs against.
  for (int i : {0, 2}) {
    for (int j = 0; j < n; ++j) {
      p.seams.push_back({edge(id(0, i, j), id(0, i, j + 1)), edge(id(1, i, j), id(1, i, j + 1))});
    }
  }
  if (s.caps) {
    const int first_cap_vertex = 6 * (n + 1);
    for (int end : {0, 1}) {
      const int j = end == 0 ? 0 : n, c = first_cap_vertex + 4 * end;
      const std::array<int, 4> ring =
          end == 0 ? std::array<int, 4>{id(0, 0, j), id(0, 1, j), id(0, 2, j), id(1, 1, j)}
                   : std::array<int, 4>{id(0, 0, j), id(1, 1, j), id(0, 2, j), id(0, 1, j)};
      for (int k = 0; k < 4; ++k) {
        // The tube's end edge between ring[k] and ring[k + 1]: on the lower sheet where one
        // end is its row-1 vertex (Bot), else on the upper sheet (T).
        const int u = ring[k], v = ring[(k + 1) % 4];
        const int sheet = (u == id(1, 1, j) || v == id(1, 1, j)) ? 1 : 0;
        auto on_sheet = [&](int w) {  // the ring's ridge vertices are the upper sheet's
          if (sheet == 0) return w;
          return w == id(0, 0, j) ? id(1, 0, j) : w == id(0, 2, j) ? id(1, 2, j) : w;
        };
        p.seams.push_back({edge(c + k, c + (k + 1) % 4), edge(on_sheet(u), on_sheet(v))});
      }
    }
  }
  p.has_fold_angles = true;
  return p;
}

}  // namespace finseg

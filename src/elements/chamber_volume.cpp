#include "elements/chamber_volume.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "core/error.hpp"

namespace finseg {
namespace {

Vec3 outward_normal_W(const State& state, const ChamberFace& face) {
  const Vec3 z_W = state.R_WB[face.body].col(2);
  return face.outward_plus_z ? z_W : Vec3(-z_W);
}

std::vector<Vec3> corners_W(const Model& model, const State& state, const ChamberFace& face) {
  std::vector<Vec3> c_W = face_corners_B(model, face);
  for (Vec3& c : c_W) c = state.p_W[face.body] + state.R_WB[face.body] * c;
  return c_W;
}

struct Edge {
  Vec3 a, b;
  int face;
};

// Part [t0, t1] of edge e (parameter along e, 0..1) that the reversed edge o covers, when
// o lies on e's line within tol and runs the opposite way; empty (t0 >= t1) otherwise.
std::pair<double, double> covered_part(const Edge& e, const Edge& o, double tol) {
  const Vec3 d = e.b - e.a;
  const double L2 = d.squaredNorm();
  const auto off_line = [&](const Vec3& x) {
    const Vec3 r = x - e.a;
    return (r - (r.dot(d) / L2) * d).norm() > tol;
  };
  if (off_line(o.a) || off_line(o.b) || (o.b - o.a).dot(d) >= 0) return {1, 0};
  const double ta = (o.a - e.a).dot(d) / L2, tb = (o.b - e.a).dot(d) / L2;
  return {std::max(0.0, std::min(ta, tb)), std::min(1.0, std::max(ta, tb))};
}

// First parameter of edge e (0..1) not covered by opposite edges of other faces; 1 if none.
double first_gap(const Edge& e, const std::vector<Edge>& edges, double tol) {
  std::vector<std::pair<double, double>> parts;
  for (const Edge& o : edges) {
    if (o.face == e.face) continue;
    const auto part = covered_part(e, o, tol);
    if (part.first < part.second) parts.push_back(part);
  }
  std::sort(parts.begin(), parts.end());
  const double t_tol = tol / (e.b - e.a).norm();
  double reached = 0;
  for (const auto& [t0, t1] : parts) {
    if (t0 > reached + t_tol) break;
    reached = std::max(reached, t1);
  }
  return reached >= 1 - t_tol ? 1.0 : reached;
}

}  // namespace

std::vector<Vec3> face_corners_B(const Model& model, const ChamberFace& face) {
  std::vector<Vec3> c_B;
  for (const Vec2& v : model.bodies[face.body].outline_B) c_B.emplace_back(v.x(), v.y(), 0);
  if (!face.outward_plus_z) std::reverse(c_B.begin(), c_B.end());
  return c_B;
}

double chamber_volume(const Model& model, const State& state,
                      const std::vector<ChamberFace>& faces) {
  std::vector<VolumeGradient> unused;
  return chamber_volume(model, state, faces, unused);
}

double chamber_volume(const Model& model, const State& state, const std::vector<ChamberFace>& faces,
                      std::vector<VolumeGradient>& gradient) {
  gradient.clear();
  double v = 0;
  for (const ChamberFace& face : faces) {
    const Vec3 n = outward_normal_W(state, face);
    const Vec3& c = state.p_W[face.body];
    const double A = segment_area(model.bodies[face.body]);
    v += c.dot(n) * A / 3;
    // d(c . n) = dp . n + c . (dphi x n) = dp . n + dphi . (n x c).
    gradient.push_back({face.body, A / 3 * n, A / 3 * n.cross(c)});
  }
  return v;
}

void check_chamber_closed(const Model& model, const State& state,
                          const std::vector<ChamberFace>& faces, const std::string& field,
                          double rel_tol) {
  check_chamber_closed(model, state, faces, {}, field, rel_tol);
}

void check_chamber_closed(const Model& model, const State& state,
                          const std::vector<ChamberFace>& faces,
                          const std::vector<std::vector<Vec3>>& end_plates,
                          const std::string& field, double rel_tol) {
  if (faces.empty()) throw InputError(model.source, field, "a chamber needs faces; none given");
  std::vector<Edge> edges;
  double longest = 0;
  const auto add_loop = [&](const auto& c, int face) {
    const std::size_t n = c.size();
    for (std::size_t k = 0; k < n; ++k) {
      edges.push_back({c[k], c[(k + 1) % n], face});
      longest = std::max(longest, (c[(k + 1) % n] - c[k]).norm());
    }
  };
  for (std::size_t i = 0; i < faces.size(); ++i) {
    add_loop(corners_W(model, state, faces[i]), static_cast<int>(i));
  }
  for (std::size_t p = 0; p < end_plates.size(); ++p) {
    add_loop(end_plates[p], static_cast<int>(faces.size() + p));
  }
  const double tol = rel_tol * longest;
  for (const Edge& e : edges) {
    const double gap = first_gap(e, edges, tol);
    if (gap >= 1) continue;
    const Vec3 x = e.a + gap * (e.b - e.a);
    const bool plate = e.face >= static_cast<int>(faces.size());
    const std::string where =
        plate ? fmt::format("end plate {}", e.face - static_cast<int>(faces.size()))
              : fmt::format("face {} (body '{}')", e.face, model.bodies[faces[e.face].body].name);
    // "chambers[2].faces" names the faces; the plates are the chamber's end_plates.
    const std::string chamber =
        field.ends_with(".faces") ? field.substr(0, field.size() - 6) : field;
    throw InputError(
        model.source,
        plate ? fmt::format("{}.end_plates[{}]", chamber, e.face - static_cast<int>(faces.size()))
              : fmt::format("{}[{}]", field, e.face),
        fmt::format("the chamber is open at {}: its edge from ({:.6g}, {:.6g}, {:.6g}) to "
                    "({:.6g}, {:.6g}, {:.6g}) m is not met by an oppositely running edge of "
                    "another face from ({:.6g}, {:.6g}, {:.6g}) m on (open, or inconsistently "
                    "oriented)",
                    where, e.a.x(), e.a.y(), e.a.z(), e.b.x(), e.b.y(), e.b.z(), x.x(), x.y(),
                    x.z()));
  }
}

}  // namespace finseg

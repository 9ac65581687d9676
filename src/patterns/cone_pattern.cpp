#include "patterns/cone_pattern.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "patterns/pattern_checks.hpp"

namespace finseg {
namespace {

void validate(const ConeSpec& s) {
  auto fail = [](const char* field, const std::string& what) {
    throw InputError("<api>", field, what);
  };
  if (!(s.base_radius > 0)) fail("base_radius", fmt::format("{} m; must be > 0", s.base_radius));
  if (!(s.top_radius > 0 && s.top_radius < s.base_radius)) {
    fail("top_radius",
         fmt::format("{} m; allowed range (0, base_radius = {}) m", s.top_radius, s.base_radius));
  }
  if (!(s.height > 0)) fail("height", fmt::format("{} m; must be > 0", s.height));
  if (s.pleats < 2 || s.pleats > 500) fail("pleats", fmt::format("{}; allowed 2..500", s.pleats));
  if (!(s.hub_fraction > 0 && s.hub_fraction < 1))
    fail("hub_fraction", fmt::format("{}; allowed range (0, 1)", s.hub_fraction));
  if (s.axial_folds < 0 || s.axial_folds > 500)
    fail("axial_folds", fmt::format("{}; allowed 0..500", s.axial_folds));
  if (s.reflect_gather >= 0) {
    if (!(s.reflect_gather < 1)) {
      fail("reflect_gather", fmt::format("{}; allowed range [0, 1)", s.reflect_gather));
    }
    if (s.top_disc || s.base_disc) {
      fail("reflect_gather", "the wall stowed by reflection has open ends (no top or base disc)");
    }
    if (s.wrap) fail("reflect_gather", "not with wrap (the fan fold's assignment)");
  }
  for (const auto& [field, a] : {std::pair{"pleat_fold_angle", s.pleat_fold_angle},
                                 std::pair{"axial_fold_angle", s.axial_fold_angle}}) {
    if (!(a > 0 && a < kPi))
      fail(field, fmt::format("{} deg; allowed range (0, 180) deg", a / kDegToRad));
  }
}

// Angles to the downward axis of the even (a_in) and odd (a_out) generators of the wall
// gathered by `gather` (cone_gathered): a_in = (1 - gather) x the deployed angle, a_out the
// root of cos beta = cos a_in cos a_out + sin a_in sin a_out cos(2 pi / G) (neighbours beta
// apart: the facets rigid) that is the deployed angle at gather = 0.
std::pair<double, double> gathered_axis_angles(const ConeSpec& s, double beta, double gather) {
  const int G = 2 * s.pleats;
  const double z_apex = s.height * s.base_radius / (s.base_radius - s.top_radius);
  const double a0 = std::atan2(s.base_radius, z_apex);
  const double a_in = (1 - gather) * a0;
  const double A = std::cos(a_in), Bc = std::sin(a_in) * std::cos(2 * kPi / G);
  return {a_in, std::atan2(Bc, A) + std::acos(std::cos(beta) / std::hypot(A, Bc))};
}

}  // namespace

int cone_face(const ConeSpec& s, int band, int wedge) {
  return band * (2 * s.pleats + 1) + wedge;
}

int cone_wall_vertex(const ConeSpec& s, int ring, int line) {
  return ring * (2 * s.pleats + 2) + line;
}

int cone_hub_face(const ConeSpec& s, bool top) {
  if (!(top ? s.top_disc : s.base_disc)) return -1;
  const int W = 2 * s.pleats + 1;
  return cone_face(s, s.axial_folds + 1, 0) + (top || !s.top_disc ? 0 : W + 1);
}

CreasePattern cone_crease_pattern(const ConeSpec& s) {
  validate(s);
  const int G = 2 * s.pleats, W = G + 1, B = s.axial_folds + 1;
  // The pyramid: apex on the axis, generator k at azimuth 2 pi (k + 1/2) / G through the base
  // polygon's corner; the flat development puts generator k at angle (k + 1/2) beta.
  const double z_apex = s.height * s.base_radius / (s.base_radius - s.top_radius);
  const Vec3 apex(0, 0, z_apex);
  std::vector<Vec3> g(G + 2);
  for (int k = 0; k <= G + 1; ++k) {
    const double psi = 2 * kPi * (k - 0.5) / G;  // g[k]: generator k - 1 (modulo G)
    g[k] =
        (Vec3(s.base_radius * std::cos(psi), s.base_radius * std::sin(psi), 0) - apex).normalized();
  }
  const double beta = std::acos(g[0].dot(g[1]));
  const double rho_base = std::hypot(s.base_radius, z_apex);
  const double rho_top = rho_base * s.top_radius / s.base_radius;
  // Flat angle of wedge line l (0 and W: the seam's two sides, 1..G: generators 0..G-1).
  auto line_angle = [&](int l) { return l == 0 ? 0.0 : l == W ? G * beta : (l - 0.5) * beta; };
  // 3-D direction of flat angle phi, inside the facet between the generators around it.
  auto direction = [&](double phi) {
    const int k = std::min(G, static_cast<int>(std::floor(phi / beta + 0.5)));
    const Vec3 &a = g[k], &b = g[k + 1];  // generators k - 1 and k
    const Vec3 e = (b - a.dot(b) * a).normalized();
    const double t = phi - (k - 0.5) * beta;
    return Vec3(std::cos(t) * a + std::sin(t) * e);
  };

  CreasePattern p;
  p.meta.file_creator = "finseg";
  p.meta.frame_title = fmt::format("cone, {} pleats, {} axial folds", s.pleats, s.axial_folds);
  // Interior rings zigzag as a Miura sheet's zigzag lines do: odd generators' vertices lie
  // further out by delta (a sector angle of about 60 degrees at mid-height).
  // Stowed by reflection they lie further out by a factor instead, the one that puts each
  // ring in a horizontal plane when the wall is gathered (even generators at a_in to the
  // axis, odd at a_out: rho cos a_in = factor rho cos a_out), so that it can be reflected.
  const double rho_mid = 0.5 * (rho_top + rho_base);
  const double delta =
      std::min(0.4 * (rho_base - rho_top) / B, rho_mid * beta / std::tan(60 * kDegToRad));
  double factor = 1;
  if (s.reflect_gather >= 0) {
    const auto [a_in, a_out] = gathered_axis_angles(s, beta, s.reflect_gather);
    factor = std::cos(a_in) / std::cos(a_out);
    const double rho_last = rho_top + (rho_base - rho_top) * (B - 1) / B;
    if (!(std::cos(a_out) > 0 && factor * rho_last < rho_base - 0.5 * (rho_base - rho_top) / B)) {
      throw InputError("<api>", "reflect_gather",
                       fmt::format("{}: the rings' zigzag (factor {:.4g}) would reach the next "
                                   "ring; a smaller share or fewer axial folds",
                                   s.reflect_gather, factor));
    }
  }
  auto ring_radius = [&](int r, int k) {  // ring r on generator k (modulo G)
    const double rho = rho_top + (rho_base - rho_top) * r / B;
    const bool zigzag = r > 0 && r < B && ((k % G) + G) % G % 2 == 1;
    if (!zigzag) return rho;
    return s.reflect_gather >= 0 ? factor * rho : rho + delta;
  };
  for (int r = 0; r <= B; ++r) {
    for (int l = 0; l <= W; ++l) {
      const double phi = line_angle(l);
      double rad = 0;
      if (l == 0 || l == W) {  // the seam (mid-facet): where the facet's ring chord crosses it
        const double ra = ring_radius(r, G - 1), rb = ring_radius(r, 0);
        rad = std::cos(beta / 2) * (ra + ra / (ra + rb) * (rb - ra));
      } else {
        rad = ring_radius(r, l - 1);
      }
      p.vertices_flat_m.emplace_back(rad * std::cos(phi), rad * std::sin(phi));
      p.vertices_folded_m.push_back(apex + rad * direction(phi));
    }
  }
  for (int b = 0; b < B; ++b) {
    for (int w = 0; w < W; ++w) {
      p.faces.push_back({cone_wall_vertex(s, b, w), cone_wall_vertex(s, b + 1, w),
                         cone_wall_vertex(s, b + 1, w + 1), cone_wall_vertex(s, b, w + 1)});
    }
  }
  // The end discs: a rigid hub and a band of trapezoids out to the wall's ring, pleated on
  // the generators' azimuths so that the ring can draw in as the wall folds. Each is laid
  // flat beside the development (its own piece of the flat sheet, seamed to the wall); the
  // top one seen from above (+z up, out of the cone as the wall's +z is), the base one seen
  // from below (mirrored in y).
  struct Disc {
    int ring0, hub0;  // first vertex of its ring copy and of its hub
  };
  auto add_disc = [&](int wall_ring, const Vec2& centre, bool from_below) {
    Disc d{static_cast<int>(p.vertices_flat_m.size()), 0};
    const double z = p.vertices_folded_m[cone_wall_vertex(s, wall_ring, 1)].z();
    for (const double scale : {1.0, s.hub_fraction}) {
      if (scale != 1.0) d.hub0 = static_cast<int>(p.vertices_flat_m.size());
      for (int l = 0; l < W; ++l) {
        const Vec3 x = p.vertices_folded_m[cone_wall_vertex(s, wall_ring, l)];
        const Vec3 at(scale * x.x(), scale * x.y(), z);
        p.vertices_flat_m.emplace_back(centre + Vec2(at.x(), from_below ? -at.y() : at.y()));
        p.vertices_folded_m.push_back(at);
      }
    }
    std::vector<int> hub;
    for (int l = 0; l < W; ++l) hub.push_back(d.hub0 + (from_below ? W - 1 - l : l));
    p.faces.push_back(hub);
    for (int l = 0; l < W; ++l) {
      const int h0 = d.hub0 + l, h1 = d.hub0 + (l + 1) % W, r0 = d.ring0 + l,
                r1 = d.ring0 + (l + 1) % W;
      p.faces.push_back(from_below ? std::vector<int>{h0, h1, r1, r0}
                                   : std::vector<int>{h0, r0, r1, h1});
    }
    return d;
  };
  const double away = 1.2 * rho_base + 2 * s.base_radius;
  std::vector<std::pair<Disc, int>> discs;  // a disc and its wall ring
  if (s.top_disc) discs.emplace_back(add_disc(0, Vec2(-away, 0), false), 0);
  if (s.base_disc) discs.emplace_back(add_disc(B, Vec2(-away, 2.5 * s.base_radius), true), B);

  p.edges = edges_from_faces(p.faces);
  std::map<std::pair<int, int>, int> edge_of;
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    const auto& v = p.edges[e].vertices;
    edge_of[{std::min(v[0], v[1]), std::max(v[0], v[1])}] = static_cast<int>(e);
  }
  auto edge = [&](int a, int b) { return edge_of.at({std::min(a, b), std::max(a, b)}); };
  // Mountains and valleys of the fan fold (docs/folding.md, "Why the cone does not fold"):
  // generator k all one kind, (-1)^k (valley for even k), so that with every generator at
  // 180 degrees the wall is a flat fan of its facets stacked on one another; ring r in the
  // facet left of generator k (wedge k) of kind (-1)^(r + k), alternating facet by facet
  // (the stacked facets lie alternately mirrored) and ring by ring (a Z-fold of the stack).
  // Every ring vertex: the generator's two creases one kind, the ring's two opposite
  // (Maekawa), sector angles psi, pi - psi, pi - psi, psi (Kawasaki).
  auto generator_sign = [&](int k) { return k % 2 == 0 && !(s.wrap && k == 0) ? 1.0 : -1.0; };
  auto ring_sign = [&](int r, int wedge) {  // wedge 0 is the far part of wedge G's facet
    return ((r + (wedge == 0 ? G : wedge)) % 2 == 0) ? 1.0 : -1.0;
  };
  auto set = [&](PatternEdge& e, double sgn, double angle) {
    e.assignment = sgn > 0 ? EdgeAssignment::Valley : EdgeAssignment::Mountain;
    e.fold_angle = sgn * angle;
  };
  p.has_fold_angles = true;
  for (int b = 0; b < B; ++b) {
    for (int k = 0; k < G; ++k) {  // generator k is line k + 1
      set(p.edges[edge(cone_wall_vertex(s, b, k + 1), cone_wall_vertex(s, b + 1, k + 1))],
          generator_sign(k), s.pleat_fold_angle);
    }
    p.seams.push_back({edge(cone_wall_vertex(s, b, 0), cone_wall_vertex(s, b + 1, 0)),
                       edge(cone_wall_vertex(s, b, W), cone_wall_vertex(s, b + 1, W))});
  }
  for (int r = 1; r < B; ++r) {
    for (int l = 0; l < W; ++l) {
      set(p.edges[edge(cone_wall_vertex(s, r, l), cone_wall_vertex(s, r, l + 1))], ring_sign(r, l),
          s.axial_fold_angle);
    }
  }
  for (const auto& [d, ring] : discs) {
    for (int l = 0; l < W; ++l) {  // the disc's rim to the wall's ring
      p.seams.push_back({edge(cone_wall_vertex(s, ring, l), cone_wall_vertex(s, ring, l + 1)),
                         edge(d.ring0 + l, d.ring0 + (l + 1) % W)});
    }
    for (int l = 1; l < W; ++l) {  // pleats on the generators' azimuths
      PatternEdge& e = p.edges[edge(d.hub0 + l, d.ring0 + l)];
      set(e, generator_sign(l - 1), s.pleat_fold_angle);
    }
    p.edges[edge(d.hub0, d.ring0)].assignment = EdgeAssignment::Join;  // mid-facet
    for (int l = 0; l < W; ++l) {  // the hub's sides: hinges (creases resting flat)
      p.edges[edge(d.hub0 + l, d.hub0 + (l + 1) % W)].assignment = EdgeAssignment::Mountain;
    }
  }
  derive_edge_faces(p, "<cone>");
  if (s.reflect_gather >= 0) {  // kinds and fold angles of the stowed state
    CreasePattern stowed = p;
    stowed.vertices_folded_m = cone_reflected(s, p);
    for (std::size_t e = 0; e < p.edges.size(); ++e) {
      if (p.edges[e].face_count() != 2) continue;
      const double angle = measured_fold_angle(stowed, static_cast<int>(e));
      set(p.edges[e], angle > 0 ? 1.0 : -1.0, std::abs(angle));
    }
  }
  return p;
}

std::vector<Vec3> cone_fan_stack(const ConeSpec& s, const CreasePattern& p, double ring_angle) {
  validate(s);
  if (s.top_disc || s.base_disc) {
    throw InputError("<api>", s.top_disc ? "top_disc" : "base_disc",
                     "the fan stack is the open wall's: both ends must be open");
  }
  if (s.wrap) throw InputError("<api>", "wrap", "the fan stack is the fan fold's (wrap = false)");
  if (!(ring_angle >= 0 && ring_angle <= kPi)) {
    throw InputError("<api>", "ring_angle",
                     fmt::format("{} deg; allowed range [0, 180] deg", ring_angle / kDegToRad));
  }
  const int G = 2 * s.pleats, W = G + 1, B = s.axial_folds + 1;
  // Generator k lies at flat angle (k + 1/2) beta; beta from the first two generators.
  auto flat_angle = [&](int v) {
    const Vec2 u = p.vertices_flat_m[v];
    return std::atan2(u.y(), u.x());
  };
  const double beta = flat_angle(2) - flat_angle(1);
  // Every generator folded by 180 degrees maps the development onto the facet
  // [-beta / 2, beta / 2]: a triangle wave of the flat angle (period 2 beta).
  auto stacked = [&](const Vec2& u) {
    const double a = std::fmod(std::atan2(u.y(), u.x()) + 0.5 * beta, 2 * beta);
    const double t = (a > beta ? 2 * beta - a : a) - 0.5 * beta;
    return Vec3(u.norm() * std::cos(t), u.norm() * std::sin(t), 0);
  };
  std::vector<Vec3> x(p.vertices_flat_m.size());
  for (std::size_t v = 0; v < x.size(); ++v) x[v] = stacked(p.vertices_flat_m[v]);
  // Ring r's chord in the stack: its vertices on generators 0 and 1 (lines 1 and 2).
  for (int r = B - 1; r >= 1; --r) {  // fold the distal part, innermost ring last
    const Vec3 a = x[cone_wall_vertex(s, r, 1)],
               e = (x[cone_wall_vertex(s, r, 2)] - a).normalized();
    // Ring r in wedge 1 is of kind (-1)^(r + 1) (valley positive); wedge 1 lies mirrored
    // in the stack, so its valley is a negative turn about the chord.
    const double angle = (r % 2 == 0 ? 1.0 : -1.0) * ring_angle;
    const Eigen::AngleAxisd turn(angle, e);
    for (int q = r + 1; q <= B; ++q) {
      for (int l = 0; l <= W; ++l)
        x[cone_wall_vertex(s, q, l)] = a + turn * (x[cone_wall_vertex(s, q, l)] - a);
    }
  }
  return x;
}

std::vector<Vec3> cone_gathered(const ConeSpec& s, const CreasePattern& p, double gather) {
  validate(s);
  if (s.top_disc || s.base_disc) {
    throw InputError("<api>", s.top_disc ? "top_disc" : "base_disc",
                     "a disc blocks the gathering: both ends must be open");
  }
  if (s.wrap) {
    throw InputError("<api>", "wrap", "the gathered wall is the fan fold's (wrap = false)");
  }
  if (!(gather >= 0 && gather < 1)) {
    throw InputError("<api>", "gather", fmt::format("{}; allowed range [0, 1)", gather));
  }
  const int G = 2 * s.pleats;
  const double z_apex = s.height * s.base_radius / (s.base_radius - s.top_radius);
  const Vec3 apex(0, 0, z_apex);
  auto flat_angle = [&](int v) {
    const Vec2 u = p.vertices_flat_m[v];
    const double a = std::atan2(u.y(), u.x());
    return a < -1e-12 ? a + 2 * kPi : std::max(a, 0.0);  // the development spans [0, G beta]
  };
  const double beta = flat_angle(2) - flat_angle(1);
  // Generator k at azimuth 2 pi (k + 1/2) / G, at angle a_k to the downward axis: even ones
  // at a_in, odd ones at a_out.
  const auto [a_in, a_out] = gathered_axis_angles(s, beta, gather);
  std::vector<Vec3> g(G + 2);  // g[k]: generator k - 1 (modulo G), as in cone_crease_pattern
  for (int k = 0; k <= G + 1; ++k) {
    const int gen = ((k - 1) % G + G) % G;
    const double psi = 2 * kPi * (k - 0.5) / G, a = gen % 2 == 0 ? a_in : a_out;
    g[k] = Vec3(std::sin(a) * std::cos(psi), std::sin(a) * std::sin(psi), -std::cos(a));
  }
  // A vertex at flat angle phi lies in its facet's plane, turned from the facet's first
  // generator by phi less that generator's flat angle.
  std::vector<Vec3> x(p.vertices_flat_m.size());
  for (std::size_t v = 0; v < x.size(); ++v) {
    const double phi = flat_angle(static_cast<int>(v));
    const int k = std::min(G, static_cast<int>(std::floor(phi / beta + 0.5)));
    const Vec3 &a = g[k], &b = g[k + 1];
    const Vec3 e = (b - a.dot(b) * a).normalized();
    const double t = phi - (k - 0.5) * beta;
    x[v] = apex + p.vertices_flat_m[v].norm() * (std::cos(t) * a + std::sin(t) * e);
  }
  return x;
}

std::vector<Vec3> cone_reflected(const ConeSpec& s, const CreasePattern& p) {
  if (s.reflect_gather < 0) {
    throw InputError("<api>", "reflect_gather",
                     fmt::format("{}; allowed range [0, 1)", s.reflect_gather));
  }
  std::vector<Vec3> x = cone_gathered(s, p, s.reflect_gather);
  const int W = 2 * s.pleats + 1, B = s.axial_folds + 1;
  for (int r = B - 1; r >= 1; --r) {  // the distal part first: ring r is where gathering left it
    Vec3 centre = Vec3::Zero(), normal = Vec3::Zero();  // Newell's normal of the ring polygon
    for (int l = 0; l < W; ++l) {
      centre += x[cone_wall_vertex(s, r, l)] / W;
      normal += x[cone_wall_vertex(s, r, l)].cross(x[cone_wall_vertex(s, r, l + 1)]);
    }
    normal.normalize();
    for (int q = r + 1; q <= B; ++q) {
      for (int l = 0; l <= W; ++l) {
        Vec3& v = x[cone_wall_vertex(s, q, l)];
        v -= 2 * normal.dot(v - centre) * normal;
      }
    }
  }
  return x;
}

}  // namespace finseg

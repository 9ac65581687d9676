// Plate-plate clipping (Sutherland-Hodgman with vertex identities).
#include "collision/narrowphase.hpp"

namespace finseg {

namespace {

struct ClipVertex {
  double u = 0, v = 0;
  PolygonVertex tag;
  int out = 0;  ///< carrier of the edge leaving this vertex: 0..3 incident edge, 4 + j line j
};

// Signed coordinate that line j bounds (inside: coord <= h).
double line_coord(const ClipVertex& p, int j) {
  switch (j) {
    case 0:
      return p.u;
    case 1:
      return p.v;
    case 2:
      return -p.u;
    default:
      return -p.v;
  }
}

// Reference corner where lines j1 and j2 meet (-1 if parallel).
int corner_of_lines(int j1, int j2) {
  if (j1 % 2 == j2 % 2) return -1;
  const int jx = j1 % 2 == 0 ? j1 : j2, jy = j1 % 2 == 0 ? j2 : j1;
  const bool xp = jx == 0, yp = jy == 1;
  if (!xp && !yp) return 0;
  if (xp && !yp) return 1;
  if (xp && yp) return 2;
  return 3;
}

}  // namespace

bool clip_plates(const BodyKin<double>& A, const PlateShape& sa, const BodyKin<double>& B,
                 const PlateShape& sb, int ref_hint, Manifold& out) {
  bool ref_is_a = true;
  if (ref_hint == 0) {
    ref_is_a = true;
  } else if (ref_hint == 1) {
    ref_is_a = false;
  } else {
    const Vec3 na = A.R_WB.col(2), nb = B.R_WB.col(2);
    if (std::abs(na.dot(nb)) > std::cos(5.0 * kDegToRad)) {
      ref_is_a = sa.hx * sa.hy >= sb.hx * sb.hy;
    } else {
      const Vec3 d = B.p_W - A.p_W;
      ref_is_a = std::abs(na.dot(d)) >= std::abs(nb.dot(d));
    }
  }
  const BodyKin<double>& ref = ref_is_a ? A : B;
  const BodyKin<double>& inc = ref_is_a ? B : A;
  const PlateShape& sr = ref_is_a ? sa : sb;
  const PlateShape& si = ref_is_a ? sb : sa;
  out.ref_is_a = ref_is_a;
  out.count = 0;

  // Incident rectangle projected onto the reference plane.
  std::array<ClipVertex, 16> buf_a, buf_b;
  int n = 4;
  for (int k = 0; k < 4; ++k) {
    const Vec3 d = inc.point_W(plate_corner(si, k)) - ref.p_W;
    buf_a[k].u = ref.R_WB.col(0).dot(d);
    buf_a[k].v = ref.R_WB.col(1).dot(d);
    buf_a[k].tag = {VertexKind::Incident, static_cast<std::uint8_t>(k), 0};
    buf_a[k].out = k;
  }
  ClipVertex* in = buf_a.data();
  ClipVertex* res = buf_b.data();
  for (int j = 0; j < 4; ++j) {
    const double h = j % 2 == 0 ? sr.hx : sr.hy;
    int m = 0;
    for (int k = 0; k < n; ++k) {
      const ClipVertex& S = in[k];
      const ClipVertex& E = in[(k + 1) % n];
      const double cs = line_coord(S, j), ce = line_coord(E, j);
      const bool s_in = cs <= h, e_in = ce <= h;
      auto crossing = [&](int out_carrier) {
        ClipVertex X;
        const double t = (h - cs) / (ce - cs);
        X.u = S.u + t * (E.u - S.u);
        X.v = S.v + t * (E.v - S.v);
        if (S.out < 4) {
          X.tag = {VertexKind::Crossing, static_cast<std::uint8_t>(S.out),
                   static_cast<std::uint8_t>(j)};
        } else {
          const int c = corner_of_lines(S.out - 4, j);
          X.tag = {VertexKind::Reference, static_cast<std::uint8_t>(c < 0 ? 0 : c), 0};
        }
        X.out = out_carrier;
        return X;
      };
      if (e_in) {
        if (!s_in) res[m++] = crossing(S.out);
        res[m++] = E;
      } else if (s_in) {
        res[m++] = crossing(4 + j);
      }
      if (m > 14) break;  // cannot happen for convex quadrilaterals; guards the buffer
    }
    std::swap(in, res);
    n = m;
    if (n == 0) return false;
  }
  if (n > 8) n = 8;
  out.count = n;
  for (int k = 0; k < n; ++k) out.poly[k] = in[k].tag;
  return n >= 2;
}

}  // namespace finseg

// Closed-form Jacobian of the contact wrenches; the derivation in docs/contact.md,
// "Jacobian". Every branch (closest polygon feature, side, force clamp, friction regime,
// cap) is the one the kernel's double evaluation took (its PointReport), so that the
// Jacobian is that of the forces the solver sees, also on a boundary between branches.
#include "collision/contact_jacobian.hpp"

#include <cmath>

#include "collision/contact_laws.hpp"
#include "collision/sunk_edge.hpp"
#include "core/so3.hpp"

namespace finseg {
namespace {

using Mat3x12 = Eigen::Matrix<double, 3, 12>;
using Row12 = Eigen::Matrix<double, 1, 12>;

/// Derivatives of a vector by the 12 pose perturbations (q) and the 12 velocities (v).
struct VecJac {
  Mat3x12 q = Mat3x12::Zero();
  Mat3x12 v = Mat3x12::Zero();
};

/// Derivatives of a scalar.
struct ScalarJac {
  Row12 q = Row12::Zero();
  Row12 v = Row12::Zero();
};

/// Derivative of the kernel's cap of f at |f| = limit (f scaled to the limit) where the
/// kernel capped it, else of f itself.
void capped(bool was_capped, const Vec3& f, const VecJac& Jf, double limit, const ScalarJac& Jlimit,
            VecJac& out) {
  const double f2 = f.squaredNorm();
  if (!was_capped) {
    out = Jf;
    return;
  }
  if (!(f2 > 0)) {
    out = VecJac{};
    return;
  }
  const double norm = std::sqrt(f2);
  const Vec3 u = f / norm;
  const Mat3 project = (limit / norm) * (Mat3::Identity() - u * u.transpose());
  out.q = project * Jf.q + u * Jlimit.q;
  out.v = project * Jf.v + u * Jlimit.v;
}

/// Derivative of the anchor friction of a point with an anchor (contact_forces.cpp's
/// friction_force): spring -k_t z_t to the anchor and damper -c_t v_t, capped at mu F_n
/// (apart while sticking) where the kernel capped them.
void anchor_friction(const ContactDef& def, const ActivePoint& pt, const PointReport& r,
                     const BodyKin<double>& src, const BodyKin<double>& tgt, int Sp, int Gp,
                     const Mat3x12& Jn, const ScalarJac& Jfn, const VecJac& Jvt, VecJac& Jft) {
  const Vec3& n = r.n_W;
  const double fn = r.normal;
  const ContactAnchor& an = *pt.anchor;
  const Vec3 arm_s = src.R_WB * an.r_src_B, arm_g = tgt.R_WB * an.r_tgt_B;
  const Vec3 z = (src.p_W + arm_s) - (tgt.p_W + arm_g);
  Mat3x12 Jz = Mat3x12::Zero();
  Jz.block<3, 3>(0, Sp).setIdentity();
  Jz.block<3, 3>(0, Sp + 3) = -hat(arm_s);
  Jz.block<3, 3>(0, Gp) = -Mat3::Identity();
  Jz.block<3, 3>(0, Gp + 3) = hat(arm_g);
  const double nz = n.dot(z);
  const Vec3 z_t = z - n * nz;
  const Mat3 tangential = Mat3::Identity() - n * n.transpose();
  const double mu = an.sliding ? def.mu_dynamic : def.mu_static;
  const double limit = mu * fn;
  ScalarJac Jlimit;
  Jlimit.q = mu * Jfn.q;
  Jlimit.v = mu * Jfn.v;
  const double kt = pt.share * def.tangential_stiffness, ct = pt.share * def.tangential_damping;
  const Vec3 spring = -kt * z_t, damper = -ct * r.v_t;
  VecJac Js, Jd;
  Js.q = -kt * (tangential * Jz - (n * z.transpose() + nz * Mat3::Identity()) * Jn);
  Jd.q = -ct * Jvt.q;
  Jd.v = -ct * Jvt.v;
  if (an.sliding) {
    VecJac Jsum;
    Jsum.q = Js.q + Jd.q;
    Jsum.v = Jd.v;
    capped(r.spring_capped, spring + damper, Jsum, limit, Jlimit, Jft);
    return;
  }
  VecJac Jcs, Jcd;
  capped(r.spring_capped, spring, Js, limit, Jlimit, Jcs);
  capped(r.damper_capped, damper, Jd, limit, Jlimit, Jcd);
  Jft.q = Jcs.q + Jcd.q;
  Jft.v = Jcs.v + Jcd.v;
}

/// Slopes of a sunk point's distance beside the polygon and of its normal (less the normal's
/// turn with the target, -[n] dphi_G) from those of m = (du, dv, h), the offset in the target's
/// frame (Jm), L the two half thicknesses summed, R_G the target's orientation.
void sunk_edge_slopes(const Vec3& m, double L, const Mat3& R_G, const Mat3x12& Jm, Row12& Jdist,
                      Mat3x12& Jn) {
  const Eigen::Vector2d p = m.head<2>();
  const double delta = p.norm();
  const Eigen::Vector2d e = p / delta;
  const SunkEdgeDistance<double> s = sunk_edge_distance(delta, m.z(), L);
  const SunkEdgeCurvature c = sunk_edge_curvature(delta, m.z(), L);
  Vec3 g;
  g << s.f_delta * e, s.f_h;
  Mat3 H;
  H.topLeftCorner<2, 2>() = c.f_dd * e * e.transpose() +
                            (s.f_delta / delta) * (Eigen::Matrix2d::Identity() - e * e.transpose());
  H.topRightCorner<2, 1>() = c.f_dh * e;
  H.bottomLeftCorner<1, 2>() = c.f_dh * e.transpose();
  H(2, 2) = c.f_hh;
  const double norm = g.norm();
  const Vec3 n_G = g / norm;
  Jdist = g.transpose() * Jm;
  Jn = R_G * (((Mat3::Identity() - n_G * n_G.transpose()) / norm) * H * Jm);
}

}  // namespace

bool add_contact_pair_jacobian(const ContactDef& def, const PairContact& pc,
                               const std::vector<PointReport>& reports, const BodyKin<double>& A,
                               const BodyKin<double>& B, bool with_velocity, FrictionSlope friction,
                               Mat12& dq, Mat12& dv) {
  const Mat3 I = Mat3::Identity();
  bool secant = false;
  for (std::size_t k = 0; k < pc.points.size(); ++k) {
    const ActivePoint& pt = pc.points[k];
    const PointReport& r = reports[k];
    // Column (and row) offsets of the source and target bodies.
    const int Sp = pt.dir == 0 ? 0 : 6, Gp = 6 - Sp;
    const BodyKin<double>& src = pt.dir == 0 ? A : B;
    const BodyKin<double>& tgt = pt.dir == 0 ? B : A;
    const PlateShape& ss = pt.dir == 0 ? pc.sa : pc.sb;
    const PlateShape& st = pt.dir == 0 ? pc.sb : pc.sa;
    const Vec3 arm = src.R_WB * pt.r_B;
    const Vec3 p = src.p_W + arm;

    // The sample point p and its coordinates l = R_G^T (p - p_G) in the target's frame:
    // dl = R_G^T (dp - dp_G + [p - p_G] dphi_G), dp = dp_S - [arm] dphi_S.
    const Vec3 d = p - tgt.p_W;
    const Mat3 Rt = tgt.R_WB.transpose();
    Mat3x12 Jl;
    Jl.block<3, 3>(0, Sp) = Rt;
    Jl.block<3, 3>(0, Sp + 3) = -Rt * hat(arm);
    Jl.block<3, 3>(0, Gp) = -Rt;
    Jl.block<3, 3>(0, Gp + 3) = Rt * hat(d);

    // Distance and normal (point_on_plate): over the face dist = side h and n = side e_z;
    // outside it, with m = (du, dv, h) in the target's frame, q = R_G m, dist = |q|,
    // n = q / dist, dn = (I - n n^T) dq / dist; sunk beside it dist = f(m) (sunk_edge.hpp),
    // n = R_G g / |g| with g = grad f, dn = R_G (I - n_G n_G^T) H dm / |g| - [n] dphi_G.
    const double dist = r.dist;
    const Vec3& n = r.n_W;
    Row12 Jdist;
    Mat3x12 Jn;
    if (r.du == 0 && r.dv == 0) {
      Jdist = pt.side * Jl.row(2);
      Jn.setZero();
      Jn.block<3, 3>(0, Gp + 3) = -hat(n);
    } else {
      const Eigen::Matrix2d P = polygon_offset_slope(*st.outline, r.feature);
      Mat3x12 Jm;
      Jm.topRows<2>() = P * Jl.topRows<2>();
      Jm.row(2) = Jl.row(2);
      if (pt.sunk && pt.side * r.height < 0) {
        sunk_edge_slopes(Vec3(r.du, r.dv, r.height), ss.r + st.r, tgt.R_WB, Jm, Jdist, Jn);
        Jn.block<3, 3>(0, Gp + 3) -= hat(n);
      } else {
        const Vec3 q = tgt.R_WB * Vec3(r.du, r.dv, r.height);
        Mat3x12 Jq = tgt.R_WB * Jm;
        Jq.block<3, 3>(0, Gp + 3) -= hat(q);
        Jdist = n.transpose() * Jq;
        Jn = ((I - n * n.transpose()) / dist) * Jq;
      }
    }

    // Contact point x = p - n (dist + r_s - r_t) / 2 and the relative velocity there.
    const double half = (dist + (ss.r - st.r)) / 2;
    Mat3x12 Jx = -half * Jn - 0.5 * n * Jdist;
    Jx.block<3, 3>(0, Sp) += I;
    Jx.block<3, 3>(0, Sp + 3) -= hat(arm);
    const Vec3& x = r.x_W;
    const Vec3 rs = x - src.p_W, rg = x - tgt.p_W;
    const Vec3 v_rel = (src.v_W + src.w_W.cross(rs)) - (tgt.v_W + tgt.w_W.cross(rg));
    VecJac Jvr;
    Jvr.q = hat(Vec3(src.w_W - tgt.w_W)) * Jx;
    Jvr.q.block<3, 3>(0, Sp) -= hat(src.w_W);
    Jvr.q.block<3, 3>(0, Gp) += hat(tgt.w_W);
    if (with_velocity) {  // else every .v below stays zero
      Jvr.v.block<3, 3>(0, Sp) = I;
      Jvr.v.block<3, 3>(0, Sp + 3) = -hat(rs);
      Jvr.v.block<3, 3>(0, Gp) = -I;
      Jvr.v.block<3, 3>(0, Gp + 3) = hat(rg);
    }

    // Normal force F_n = share F(delta, rate), delta = r_s + r_t - dist, rate = -n . v_rel.
    const double rate = r.penetration_rate;
    ScalarJac Jrate;
    Jrate.q = -(v_rel.transpose() * Jn + n.transpose() * Jvr.q);
    if (with_velocity) Jrate.v = -n.transpose() * Jvr.v;
    const double fn = r.normal;
    ScalarJac Jfn;
    if (fn > 0) {  // else the kernel clamped the force to zero
      const double v0 = pt.anchor ? pt.anchor->impact_speed : rate;
      const NormalForceSlopes law = normal_force_slopes(def, r.depth, rate, v0);
      Jfn.q = pt.share * (-law.d_delta * Jdist + law.d_rate * Jrate.q);
      if (with_velocity) Jfn.v = pt.share * law.d_rate * Jrate.v;
    }

    // Friction from the tangential velocity v_t = v_rel + n rate.
    VecJac Jvt;
    Jvt.q = Jvr.q + rate * Jn + n * Jrate.q;
    if (with_velocity) Jvt.v = Jvr.v + n * Jrate.v;
    VecJac Jft;
    if (def.friction == FrictionModel::Continuous ||
        (def.friction == FrictionModel::Anchor && pt.anchor == nullptr)) {
      const FrictionSlopes fr =
          continuous_friction_slopes(def, fn, r.v_t, lag_speed(def, pt), friction);
      secant = secant || fr.secant_differs;
      Jft.q = fr.d_fn * Jfn.q + fr.d_vt * Jvt.q;
      if (with_velocity) Jft.v = fr.d_fn * Jfn.v + fr.d_vt * Jvt.v;
    } else if (def.friction == FrictionModel::Anchor) {
      anchor_friction(def, pt, r, src, tgt, Sp, Gp, Jn, Jfn, Jvt, Jft);
    }

    const Vec3 f = fn * n + r.f_t;
    VecJac Jf;
    Jf.q = n * Jfn.q + fn * Jn + Jft.q;
    if (with_velocity) Jf.v = n * Jfn.v + Jft.v;
    const Mat3 hf = hat(f), hrs = hat(rs), hrg = hat(rg);
    Mat3x12 Jarm_s = Jx, Jarm_g = Jx;
    Jarm_s.block<3, 3>(0, Sp) -= I;
    Jarm_g.block<3, 3>(0, Gp) -= I;
    dq.block<3, 12>(Sp, 0) += Jf.q;
    dq.block<3, 12>(Sp + 3, 0) += hrs * Jf.q - hf * Jarm_s;
    dq.block<3, 12>(Gp, 0) -= Jf.q;
    dq.block<3, 12>(Gp + 3, 0) -= hrg * Jf.q - hf * Jarm_g;
    if (with_velocity) {
      dv.block<3, 12>(Sp, 0) += Jf.v;
      dv.block<3, 12>(Sp + 3, 0) += hrs * Jf.v;
      dv.block<3, 12>(Gp, 0) -= Jf.v;
      dv.block<3, 12>(Gp + 3, 0) -= hrg * Jf.v;
    }
  }
  return secant;
}

}  // namespace finseg

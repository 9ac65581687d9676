#include "elements/drive_gauge.hpp"

#include "core/so3.hpp"
#include "elements/assemble.hpp"
#include "elements/assembler.hpp"

namespace finseg {
namespace {

// Drive i's target and its velocity: the drive stops moving at its travel.
struct Target {
  Vec3 x_W, v_W;
};

Target target_of(const DriveDef& d, const State& state, int i) {
  const double rate = (d.travel > 0 && state.drive_s[i] >= d.travel) ? 0.0 : d.speed;
  return {d.start_W + state.drive_s[i] * d.direction_W, rate * d.direction_W};
}

// Where the gauge's point is against its target: x - X and v + w x r - V, world frame.
struct GaugeMotion {
  Vec3 stretch, rate;
};

GaugeMotion gauge_motion(const DriveDef& d, const Target& tgt, const State& s) {
  const Vec3 r = s.R_WB[d.body] * d.point_B;
  const Vec3 v_P = s.v_W[d.body] + s.w_W[d.body].cross(r);
  return {s.p_W[d.body] + r - tgt.x_W, v_P - tgt.v_W};
}

// The gauge's stiffness K and damping C: k and c along direction_W, lateral_ratio times them
// across it; a pull-only gauge has none along it where its force there would hold the point
// back (slack). The side is decided on the state's values, so that the Jacobian is the
// derivative of the branch taken.
struct GaugeAxes {
  Mat3 K, C;
};

GaugeAxes gauge_axes(const DriveDef& d, const GaugeMotion& m) {
  const Vec3& n = d.direction_W;
  const Mat3 nn = n * n.transpose();
  const bool slack = d.pull_only && -d.stiffness * n.dot(m.stretch) - d.damping * n.dot(m.rate) < 0;
  const Mat3 axes = slack ? Mat3(d.lateral_ratio * (Mat3::Identity() - nn))
                          : Mat3(d.lateral_ratio * Mat3::Identity() + (1 - d.lateral_ratio) * nn);
  return {d.stiffness * axes, d.damping * axes};
}

// f = -K (x - X) - C (v + w x r - V) at the point x = p + r, its moment r x f about the
// centroid. With dx = dp - [r]x dphi and d(w x r) = -[w]x [r]x dphi + ... (world-frame
// increments): df/dp = -K, df/dphi = K [r]x + C [w]x [r]x, dm = -[f]x dr + [r]x df;
// df/dv = -C, df/dw = C [r]x.
Vec3 gauge_force(const GaugeAxes& g, const GaugeMotion& m) {
  return -g.K * m.stretch - g.C * m.rate;
}

void add_closed_form(const DriveDef& d, const Target& tgt, const State& s, Assembler& as) {
  const Vec3 r = s.R_WB[d.body] * d.point_B;
  const GaugeMotion m = gauge_motion(d, tgt, s);
  const Vec3& stretch = m.stretch;
  const GaugeAxes g = gauge_axes(d, m);
  const Mat3 &K = g.K, &C = g.C;
  const Vec3 f = gauge_force(g, m);
  as.add(d.body, {f, r.cross(f)});
  as.add_energy(0.5 * stretch.dot(K * stretch));
  const Mat3 hr = hat(r);
  const Mat3 df_dphi = K * hr + C * hat(s.w_W[d.body]) * hr;
  Mat6 q;
  q << -K, df_dphi, -hr * K, hat(f) * hr + hr * df_dphi;
  as.add_pose_block(d.body, d.body, q);
  if (d.damping == 0) return;
  Mat6 v;
  v << -C, C * hr, -hr * C, hr * C * hr;
  as.add_velocity_block(d.body, d.body, v);
}

}  // namespace

Vec3 drive_force(const Model& model, const State& state, int i) {
  const DriveDef& d = model.drives[i];
  const GaugeMotion m = gauge_motion(d, target_of(d, state, i), state);
  return gauge_force(gauge_axes(d, m), m);
}

void add_drive_gauges(const Model& model, const State& state, Assembler& as) {
  for (size_t i = 0; i < model.drives.size(); ++i) {
    const DriveDef& d = model.drives[i];
    const Target tgt = target_of(d, state, static_cast<int>(i));
    if (!as.autodiff_elements()) {
      add_closed_form(d, tgt, state, as);
      continue;
    }
    as.single(d.body, [&](const auto& A, auto& w) {
      using T = typename std::decay_t<decltype(A.p_W)>::Scalar;
      const Vec3T<T> P = A.point_W(d.point_B);
      const Vec3T<T> stretch = P - tgt.x_W.cast<T>();
      const GaugeAxes g = gauge_axes(d, gauge_motion(d, tgt, state));
      const Mat3T<T> K = g.K.cast<T>(), C = g.C.cast<T>();
      const Vec3T<T> f = -K * stretch - C * (A.point_velocity_W(d.point_B) - tgt.v_W.cast<T>());
      w.add_force_at(f, P, A.p_W);
      return T(0.5) * stretch.dot(K * stretch);
    });
  }
}

}  // namespace finseg

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

// A pull-only gauge's tension along direction_W from u, the pull a two-way gauge would give
// there: max(0, u), or with a toe band b > 0 eased in over [-b, b] by (u + b)^2 / (4 b), so
// that strings hovering at zero tension give Newton no kink (value and slope continuous).
// Plain or autodiff scalar: the oracle differentiates the same arithmetic.
template <class T>
T string_tension(const T& u, double toe) {
  const double v = value_of(u);
  if (v >= toe) return u;
  if (v <= -toe) return T(0);
  const T a = u + toe;
  return a * a / (4 * toe);
}

// dT/du of string_tension.
double string_slope(double u, double toe) {
  if (u >= toe) return 1;
  if (u <= -toe) return 0;
  return (u + toe) / (2 * toe);
}

// The integral of the tension over u from the slack side (the string's energy times k).
template <class T>
T string_energy_k(const T& u, double toe) {
  const double v = value_of(u);
  if (v <= -toe) return T(0);
  if (v >= toe) return T(0.5) * u * u + toe * toe / 6;
  const T a = u + toe;
  return a * a * a / (12 * toe);
}

// A string's energy: its spring's, the lateral part and the integral of its tension (without
// the damper's share of u). Plain or autodiff scalar.
template <class T>
T string_energy(const DriveDef& d, const Vec3T<T>& stretch) {
  const Vec3T<T> n = d.direction_W.cast<T>();
  const T along = n.dot(stretch);
  const T across2 = stretch.squaredNorm() - along * along;
  return T(0.5 * d.stiffness * d.lateral_ratio) * across2 +
         string_energy_k(T(-d.stiffness * along), d.toe_force) / d.stiffness;
}

// The gauge's axes across direction_W, lateral_ratio (I - n n^T): its stiffness and damping
// there over k and c.
Mat3 lateral_axes(const DriveDef& d) {
  return d.lateral_ratio * (Mat3::Identity() - d.direction_W * d.direction_W.transpose());
}

// The gauge's force f and its derivatives K = -df/dx, C = -df/dv: k and c along direction_W,
// lateral_ratio times them across it; a pull-only gauge's part along it is its tension (slack
// where it would hold the point back). The side is decided on the state's values, so that the
// Jacobian is the derivative of the branch taken.
struct GaugeAxes {
  Mat3 K, C;
  Vec3 f;
  double energy;  // J, the spring's (damping has none)
};

GaugeAxes gauge_axes(const DriveDef& d, const GaugeMotion& m) {
  const Vec3& n = d.direction_W;
  const Mat3 nn = n * n.transpose();
  const double u = -d.stiffness * n.dot(m.stretch) - d.damping * n.dot(m.rate);
  const double slope = d.pull_only ? string_slope(u, d.toe_force) : 1.0;
  const Mat3 across = lateral_axes(d);
  if (slope == 1 || slope == 0) {
    // Outside the toe the force is linear in the motion (the two-way gauge's arithmetic).
    const Mat3 axes =
        slope == 0 ? across : Mat3(d.lateral_ratio * Mat3::Identity() + (1 - d.lateral_ratio) * nn);
    const Mat3 K = d.stiffness * axes, C = d.damping * axes;
    const Vec3 f = -K * m.stretch - C * m.rate;
    return {K, C, f,
            d.pull_only ? string_energy(d, m.stretch) : 0.5 * m.stretch.dot(K * m.stretch)};
  }
  const Mat3 K = d.stiffness * (across + slope * nn), C = d.damping * (across + slope * nn);
  const Vec3 f = -d.stiffness * across * m.stretch - d.damping * across * m.rate +
                 string_tension(u, d.toe_force) * n;
  return {K, C, f, string_energy(d, m.stretch)};
}

// f at the point x = p + r, its moment r x f about the centroid. With dx = dp - [r]x dphi and
// d(w x r) = -[w]x [r]x dphi + ... (world-frame increments): df/dp = -K, df/dphi = K [r]x +
// C [w]x [r]x, dm = -[f]x dr + [r]x df; df/dv = -C, df/dw = C [r]x.
void add_closed_form(const DriveDef& d, const Target& tgt, const State& s, Assembler& as) {
  const Vec3 r = s.R_WB[d.body] * d.point_B;
  const GaugeAxes g = gauge_axes(d, gauge_motion(d, tgt, s));
  const Mat3 &K = g.K, &C = g.C;
  const Vec3& f = g.f;
  as.add(d.body, {f, r.cross(f)});
  as.add_energy(g.energy);
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
  return gauge_axes(d, gauge_motion(d, target_of(d, state, i), state)).f;
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
      const Vec3T<T> rate = A.point_velocity_W(d.point_B) - tgt.v_W.cast<T>();
      if (!d.pull_only) {
        const GaugeAxes g = gauge_axes(d, gauge_motion(d, tgt, state));
        const Mat3T<T> K = g.K.cast<T>(), C = g.C.cast<T>();
        w.add_force_at(Vec3T<T>(-K * stretch - C * rate), P, A.p_W);
        return T(T(0.5) * stretch.dot(K * stretch));
      }
      // The string: its lateral part, and its tension along direction_W.
      const Vec3T<T> n = d.direction_W.cast<T>();
      const Mat3T<T> across = lateral_axes(d).cast<T>();
      const T u = -d.stiffness * n.dot(stretch) - d.damping * n.dot(rate);
      const Vec3T<T> f = -d.stiffness * (across * stretch) - d.damping * (across * rate) +
                         string_tension(u, d.toe_force) * n;
      w.add_force_at(f, P, A.p_W);
      return string_energy(d, stretch);
    });
  }
}

}  // namespace finseg

// With `error_measure: points` the implicit solvers measure their local error and Newton's
// corrections in metres: a rotation counts by how far it moves its body's farthest point
// (docs/solvers.md, "Step control"), so a small segment's spin does not set the steps of a
// whole sheet.
#include <gtest/gtest.h>

#include <cmath>

#include "contact_test_util.hpp"
#include "solvers/dofs.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace error_in_metres_test {

using test::plate;

TEST(ErrorInMetres, RotationsWeighByTheDistanceToTheFarthestCorner) {
  Model m;
  m.bodies.push_back(
      plate("clamped", 1e-3, Vec3(0.01, 0.01, 1e-3), Vec3::Zero(), Mat3::Identity(), true));
  m.bodies.push_back(plate("plate", 1e-3, Vec3(0.03, 0.04, 2e-3), Vec3(0, 0, 0.1)));
  m.finalize_dofs();
  const Eigen::VectorXd w = displacement_weights(m);
  ASSERT_EQ(w.size(), 6);  // the clamped plate has no degrees of freedom
  // Corner (15, 20, 1) mm from the centroid.
  const double r = std::sqrt(0.015 * 0.015 + 0.02 * 0.02 + 0.001 * 0.001);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(w[i], 1.0);
    EXPECT_NEAR(w[3 + i], r, 1e-15);
  }
}

struct Spin {
  long steps = 0;
  double angle = 0;  // rad about z at the end
};

// A square plate of side a (thickness a / 20, 1 g, no gravity) spun up from rest by a moment
// about its normal that gives its corners the tangential acceleration `corner_accel` (m/s^2),
// run by the implicit solver for 0.1 s at a fixed tolerance.
Spin spin_up(double a, double corner_accel, bool at_points) {
  Model m;
  m.bodies.push_back(plate("plate", 1e-3, Vec3(a, a, a / 20), Vec3::Zero()));
  m.finalize_dofs();
  const double r = std::hypot(a / std::sqrt(2.0), a / 40);
  const double alpha = corner_accel / r;  // rad/s^2
  m.loads.push_back(
      {0, Vec3::Zero(), Vec3::Zero(), Vec3(0, 0, m.bodies[0].J_B(2, 2) * alpha), false});
  State s = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Implicit;
  set.t_end = 0.1;
  set.output_interval = 0.1;
  set.rtol = 1e-4;  // with atol, 2e-7 m (and rad) for a model without a sheet
  set.error_at_points = at_points;
  const SolverStats st = run_solver(m, s, set, {});
  EXPECT_EQ(st.status, "ok") << st.message;
  return {st.steps, std::atan2(s.R_WB[0](1, 0), s.R_WB[0](0, 0))};
}

// The same motion of every point at a tenth of the size: the corners follow the same path, so
// the steps are the same; measured in radians the small plate's error would be ten times the
// large one's and take sqrt(10) times the steps.
TEST(ErrorInMetres, APlateTenTimesSmallerSpinningAlikeTakesTheSameSteps) {
  const double corner_accel = 0.5;  // m/s^2: corners 2.5 mm along their circle in 0.1 s
  const Spin large = spin_up(0.02, corner_accel, true);
  const Spin small = spin_up(0.002, corner_accel, true);
  ASSERT_GT(large.steps, 20);  // the tolerance, not dt_max, sets them
  EXPECT_NEAR(static_cast<double>(small.steps), static_cast<double>(large.steps), 1);
  EXPECT_NEAR(small.angle / large.angle, 10.0, 1e-6);
  // Backward Euler's angle against the closed form alpha t^2 / 2, first order in the steps.
  const double alpha = corner_accel / std::hypot(0.02 / std::sqrt(2.0), 0.02 / 40);
  EXPECT_NEAR(large.angle / (0.5 * alpha * 0.01), 1.0, 5.0 / static_cast<double>(large.steps));
  // In m and rad (the default) the small plate's error is ten times the large one's: steps
  // about sqrt(10) times as many (the step factor err^(-1/2)).
  const Spin small_dofs = spin_up(0.002, corner_accel, false);
  const Spin large_dofs = spin_up(0.02, corner_accel, false);
  const double ratio =
      static_cast<double>(small_dofs.steps) / static_cast<double>(large_dofs.steps);
  EXPECT_NEAR(ratio, std::sqrt(10.0), 0.35);
}

}  // namespace error_in_metres_test
}  // namespace finseg

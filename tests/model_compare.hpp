// Field-by-field comparison of two models (generator API vs scene file read back).
#pragma once

#include <gtest/gtest.h>

#include "elements/crease_law.hpp"
#include "model/model.hpp"

namespace finseg::test {

inline void expect_same_model(const Model& a, const Model& b) {
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const BodyDef &x = a.bodies[i], &y = b.bodies[i];
    SCOPED_TRACE("body " + x.name);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.mass, y.mass);
    EXPECT_EQ(x.J_B, y.J_B);
    EXPECT_EQ(x.outline_B, y.outline_B);
    EXPECT_EQ(x.thickness, y.thickness);
    EXPECT_EQ(x.p0_W, y.p0_W);
    EXPECT_EQ(x.R0_WB, y.R0_WB);
    EXPECT_EQ(x.fixed, y.fixed);
    EXPECT_EQ(x.panel, y.panel);
    EXPECT_EQ(x.centroid_M, y.centroid_M);
  }
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (std::size_t k = 0; k < a.elements.size(); ++k) {
    const ElementDef &x = a.elements[k], &y = b.elements[k];
    SCOPED_TRACE("element " + x.name);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.inner, y.inner);
    EXPECT_EQ(x.outer, y.outer);
    EXPECT_EQ(x.c_inner_B, y.c_inner_B);
    EXPECT_EQ(x.c_outer_B, y.c_outer_B);
    EXPECT_EQ(x.R_inner_E, y.R_inner_E);
    EXPECT_EQ(x.R_outer_F, y.R_outer_F);
    EXPECT_EQ(x.K, y.K);
    EXPECT_EQ(x.C, y.C);
    EXPECT_EQ(x.z0_F, y.z0_F);
    EXPECT_EQ(x.crease, y.crease);
  }
  ASSERT_EQ(a.creases.size(), b.creases.size());
  for (std::size_t c = 0; c < a.creases.size(); ++c) {
    EXPECT_EQ(a.creases[c].initial_fold_angle, b.creases[c].initial_fold_angle);
    EXPECT_EQ(a.creases[c].law->describe(), b.creases[c].law->describe());
    for (double phi : {-2.5, -1.0, 0.0, 0.7, 2.9}) {
      EXPECT_EQ(a.creases[c].law->evaluate(phi, {}, 0).moment,
                b.creases[c].law->evaluate(phi, {}, 0).moment);
    }
  }
  ASSERT_EQ(a.loads.size(), b.loads.size());
  for (std::size_t i = 0; i < a.loads.size(); ++i) {
    EXPECT_EQ(a.loads[i].body, b.loads[i].body);
    EXPECT_EQ(a.loads[i].point_B, b.loads[i].point_B);
    EXPECT_EQ(a.loads[i].force, b.loads[i].force);
    EXPECT_EQ(a.loads[i].moment, b.loads[i].moment);
    EXPECT_EQ(a.loads[i].follower, b.loads[i].follower);
  }
  ASSERT_EQ(a.drives.size(), b.drives.size());
  for (std::size_t i = 0; i < a.drives.size(); ++i) {
    const DriveDef &x = a.drives[i], &y = b.drives[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.body, y.body);
    EXPECT_EQ(x.point_B, y.point_B);
    EXPECT_EQ(x.start_W, y.start_W);
    EXPECT_EQ(x.direction_W, y.direction_W);
    EXPECT_EQ(x.stiffness, y.stiffness);
    EXPECT_EQ(x.lateral_ratio, y.lateral_ratio);
    EXPECT_EQ(x.pull_only, y.pull_only);
    EXPECT_EQ(x.toe_force, y.toe_force);
    EXPECT_EQ(x.damping, y.damping);
    EXPECT_EQ(x.speed, y.speed);
    EXPECT_EQ(x.travel, y.travel);
    EXPECT_EQ(x.step, y.step);
  }
  ASSERT_EQ(a.probes.size(), b.probes.size());
  for (std::size_t i = 0; i < a.probes.size(); ++i) {
    EXPECT_EQ(a.probes[i].name, b.probes[i].name);
    EXPECT_EQ(a.probes[i].kind, b.probes[i].kind);
    EXPECT_EQ(a.probes[i].body, b.probes[i].body);
    EXPECT_EQ(a.probes[i].point_B, b.probes[i].point_B);
    EXPECT_EQ(a.probes[i].drives, b.probes[i].drives);
  }
  EXPECT_EQ(a.gravity_W, b.gravity_W);
  EXPECT_EQ(a.contact.enabled, b.contact.enabled);
  EXPECT_EQ(a.dof_of_body, b.dof_of_body);
  EXPECT_EQ(a.num_dofs, b.num_dofs);
}

}  // namespace finseg::test

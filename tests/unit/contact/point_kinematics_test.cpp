// What the shared part hands a law at each point (point_law.hpp's PointKinematics): the normal
// gap and the tangential relative displacement in the point's frame, and their change since the
// step's start, from the point discretisations (integration points, node to segment) with the
// pairing frozen. A rigid motion of the slave block over the master one is read back exactly.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/contact/contact_problem.hpp"
#include "engine/contact/linear_gap.hpp"
#include "two_blocks.hpp"

using namespace contact_test;
using lunaster::engine::contact::ContactPoint;
using lunaster::engine::contact::ContactProblem;
using lunaster::engine::contact::PointKinematics;

TEST(PointKinematics, SlipAndGapOfARigidMotionOverTheMasterOnEveryDiscretisation) {
  const TwoBlocks tb = make_two_blocks(4, 3, false);
  const FeModel model = make_model(tb.mesh, 2e6, 0.0);
  for (ContactMethod method : {ContactMethod::Continuous, ContactMethod::DiscreteLagrange}) {
    std::unique_ptr<ContactProblem> p(dynamic_cast<ContactProblem*>(
        make_contact_hook(zone_ab_on_ef(tb, method, ContactInit::No), tb.mesh, 2).release()));
    DofMap dofs(tb.mesh, model.volume_cells(), 2);
    p->add_dofs(dofs);
    const Vector u0 = Vector::Zero(dofs.n_dofs());
    p->begin_step(u0, quiet_log());
    // The upper (slave) block moved by (0.03, 0.01) at the step's start, then by (0.05, 0.02)
    // more; the lower (master) block by (-0.01, 0) throughout.
    Vector start = u0, now = u0;
    for (int node = 0; node < tb.mesh.n_nodes(); ++node) {
      const bool upper = tb.mesh.node(node)[1] > 1e-12;
      if (dofs.dof(node, DX) < 0) continue;
      start[dofs.dof(node, DX)] = upper ? 0.03 : -0.01;
      start[dofs.dof(node, DY)] = upper ? 0.01 : 0.0;
      now[dofs.dof(node, DX)] = upper ? 0.08 : -0.01;
      now[dofs.dof(node, DY)] = upper ? 0.03 : 0.0;
    }
    // Both blocks have nodes at y = 0: the interface's are told apart by the cells of AB (slave,
    // upper block) and EF (master, lower block).
    for (int c : tb.ab)
      for (int a = 0; a < tb.mesh.cell_n_nodes(c); ++a) {
        const int node = tb.mesh.cell(c)[a];
        start[dofs.dof(node, DX)] = 0.03, start[dofs.dof(node, DY)] = 0.01;
        now[dofs.dof(node, DX)] = 0.08, now[dofs.dof(node, DY)] = 0.03;
      }
    for (int c : tb.ef)
      for (int a = 0; a < tb.mesh.cell_n_nodes(c); ++a) {
        const int node = tb.mesh.cell(c)[a];
        start[dofs.dof(node, DX)] = -0.01, start[dofs.dof(node, DY)] = 0.0;
        now[dofs.dof(node, DX)] = -0.01, now[dofs.dof(node, DY)] = 0.0;
      }
    int n_paired = 0;
    for (const ContactPoint& point : p->points()) {
      if (!point.paired) continue;
      ++n_paired;
      // The master normal is +y, its tangent -x (the normal turned by +90 degrees).
      EXPECT_NEAR(point.normal[1], 1.0, 1e-14);
      const PointKinematics in = p->kinematics(point, now, start, 1);
      EXPECT_NEAR(in.q[0], 0.03, 1e-14);             // the gap opened by the slave's rise
      EXPECT_NEAR(in.q[1], -(0.08 + 0.01), 1e-14);   // -(x_slave - x_master) motion
      EXPECT_NEAR(in.dq_step[0], 0.02, 1e-14);
      EXPECT_NEAR(in.dq_step[1], -0.05, 1e-14);      // the slip since the step's start
      EXPECT_GT(in.weight, 0.0);
      const PointKinematics normal_only = p->kinematics(point, now, start, 0);
      EXPECT_EQ(normal_only.q[0], in.q[0]);
      EXPECT_EQ(normal_only.q[1], 0.0);
    }
    EXPECT_GT(n_paired, 3);
  }
}

TEST(PointKinematics, TangentFrameIsOrthonormalAndRightHanded) {
  const double n3[3] = {0.48, -0.6, 0.64};  // unit
  double t[2][3];
  lunaster::engine::contact::tangent_frame(n3, 3, t);
  auto dot = [](const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  EXPECT_NEAR(dot(t[0], t[0]), 1.0, 1e-15);
  EXPECT_NEAR(dot(t[1], t[1]), 1.0, 1e-15);
  EXPECT_NEAR(dot(t[0], n3), 0.0, 1e-15);
  EXPECT_NEAR(dot(t[1], n3), 0.0, 1e-15);
  EXPECT_NEAR(dot(t[0], t[1]), 0.0, 1e-15);
  // n . (t1 x t2) = 1: (t1, t2, n) right-handed.
  const double c[3] = {t[0][1] * t[1][2] - t[0][2] * t[1][1], t[0][2] * t[1][0] - t[0][0] * t[1][2],
                       t[0][0] * t[1][1] - t[0][1] * t[1][0]};
  EXPECT_NEAR(dot(c, n3), 1.0, 1e-15);
  const double n2[3] = {0.6, 0.8, 0.0};
  lunaster::engine::contact::tangent_frame(n2, 2, t);
  EXPECT_DOUBLE_EQ(t[0][0], -0.8);
  EXPECT_DOUBLE_EQ(t[0][1], 0.6);
}

// A nonlinear behaviour added through the behaviour interface alone, solved by a Newton loop
// that sees only the Tangent (internal force, tangent, commit, restore) and a sparse LU.
//
// The law (hardening_bar.hpp, shared with the driver's test in tests/unit/nonlinear): the xx
// component follows a 1D plasticity with the nonlinear isotropic hardening
// R(p) = sy + Q (1 - exp(-b p)), return mapping solved by a local Newton, consistent tangent
// E R'/(E + R'); yy and xy are linear (E, E/2: no Poisson coupling), zz carries no stress.
// Internal variables EPSPEQ (p) and EPSPXX (the plastic xx strain).
//
// The problem: the unit square (distorted interior nodes, QUAD4, plane strain), u_x = 0 on x = 0,
// u_y = 0 at the origin, a uniform traction t along x on x = 1. The exact solution is uniform:
// sigma_xx = t, sigma_yy = sigma_xy = 0 (no Poisson coupling), so eps_yy = 0, and on the yield
// surface t = R(p), i.e. p = -ln(1 - (t - sy) / Q) / b, eps_xx = t / E + p, u_x(1, y) = eps_xx.
// A uniform strain is linear in x, which bilinear isoparametric cells hold exactly, and the
// nodal forces of a uniform traction on straight edges are exact: the discrete solution is the
// exact one, to the Newton tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <tuple>

#include "engine/assembly/assembly.hpp"
#include "engine/assembly/point_fields.hpp"
#include "engine/io/med_writer.hpp"
#include "engine/assembly/tangent.hpp"
#include "engine/material/behaviour.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "fe_test_util.hpp"
#include "hardening_bar.hpp"
#include "med_elga.hpp"
#include "newton_test_util.hpp"

namespace lunaster::engine {
namespace {

using namespace hardening_bar;

struct Bar {
  static constexpr int kCells = 4;
  test::BlockBuilder block{CellType::Quad4, kCells, 0.3};
  FeModel model;
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<CellBehaviours> behaviours;
  std::vector<int> free;     ///< free equations
  Vector unit_load;          ///< nodal forces of a unit traction on x = 1
  Bar() {
    block.fill();
    model = test::make_model(block.mesh(), 2, Modelisation::PlaneStrain, ElasticMaterial{kE, 0.0, 0.0});
    dofs = std::make_unique<DofMap>(block.mesh(), model.volume_cells(), 2);
    behaviours = std::make_unique<CellBehaviours>(model);
    behaviours->assign(model.volume_cells(), std::make_shared<HardeningBar>());
    std::vector<char> fixed(dofs->n_dofs(), 0);
    for (int j = 0; j <= kCells; ++j) fixed[dofs->dof(block.vertex(0, j), DX)] = 1;
    fixed[dofs->dof(block.vertex(0, 0), DY)] = 1;
    free = test::free_equations(fixed);
    unit_load = Vector::Zero(dofs->n_dofs());
    for (int j = 0; j < kCells; ++j)
      for (int end : {j, j + 1}) unit_load(dofs->dof(block.vertex(kCells, end), DX)) += 0.5 / kCells;
  }
};

/// Newton on one load step: u from the step's start to equilibrium with traction t.
test::NewtonLog newton_step(const Bar& bar, Tangent& tangent, double t, Vector& u) {
  std::printf("  t = %g\n", t);
  const Vector f_ext = t * bar.unit_load;
  return test::newton_step(tangent, bar.free, f_ext, f_ext.norm(), u);
}

void expect_exact(const Bar& bar, const Tangent& tangent, const Vector& u, double t) {
  const double p = exact_p(t), exx = t / kE + p;
  for (int j = 0; j <= Bar::kCells; ++j) {
    const int v = bar.block.vertex(Bar::kCells, j);
    test::expect_close(u(bar.dofs->dof(v, DX)), exx, 1e-10, 0.0, "u_x at x = 1");
    test::expect_close(u(bar.dofs->dof(v, DY)), 0.0, 0.0, 1e-12 * exx, "u_y at x = 1");
  }
  for (int cell : bar.model.volume_cells())
    for (int q = 0; q < tangent.states().n_points(cell); ++q) {
      const double* vari = tangent.states().variables(MaterialStates::Slot::End, cell, q);
      test::expect_close(vari[0], p, 1e-10, 1e-14, "EPSPEQ");
      test::expect_close(tangent.states().stress(MaterialStates::Slot::End, cell, q)[0], t, 1e-10, 0.0, "SIXX");
    }
}

TEST(ToyPlasticity, NewtonOnTheTangentConvergesQuadraticallyToTheExactSolution) {
  Bar bar;
  Tangent tangent(*bar.behaviours, *bar.dofs);
  EXPECT_FALSE(tangent.constant());
  Vector u = Vector::Zero(bar.dofs->n_dofs());
  for (double t : {150.0, 250.0, 290.0}) {  // elastic, then twice plastic
    const test::NewtonLog log = newton_step(bar, tangent, t, u);
    ASSERT_TRUE(log.converged) << "t = " << t;
    expect_exact(bar, tangent, u, t);
    tangent.commit();
    if (t < kSy) {
      EXPECT_LE(log.residuals.size(), 2u) << "an elastic step is one linear solve";
      continue;
    }
    // Quadratic: the iterates stay uniform (a uniform start, a uniform load, a uniform
    // tangent), so this is Newton on sigma(eps_xx) = t, whose residuals r_k = |sigma - t| / t
    // (relative) go as r_{k+1} ~ C r_k^2 with C = t |sigma''| / (2 sigma'^2) at the solution.
    // Every iteration whose residual is above round-off and below 1e-2 (near enough for the
    // asymptote) is held to 2 C, and the last one's ratio is C to 5 %: the rate is the law's.
    // A linear rate would give ratios ~ 1 / r_k, over 1e2 here.
    const double c = rate_constant(t);
    double last = 0.0;
    ASSERT_GE(log.residuals.size(), 4u) << "t = " << t << ": too few iterations to see a rate";
    int rated = 0;
    for (size_t k = 1; k + 1 < log.residuals.size(); ++k) {
      if (log.residuals[k] < 1e-11 || log.residuals[k - 1] > 1e-2) continue;
      const double ratio = log.residuals[k] / (log.residuals[k - 1] * log.residuals[k - 1]);
      std::printf("  t = %g, iteration %zu: r_k / r_{k-1}^2 = %.3g (C = %.3g)\n", t, k, ratio, c);
      EXPECT_LE(ratio, 2.0 * c) << "t = " << t << ", iteration " << k;
      last = ratio;
      ++rated;
    }
    EXPECT_NEAR(last, c, 0.05 * c) << "t = " << t << ": the asymptotic rate";
    EXPECT_GE(rated, 1) << "t = " << t;
  }
}

TEST(ToyPlasticity, ARestoredStepReproducesItsNumbers) {
  // Run A: 250, then 290. Run B: 250, then a step to 320 that cannot converge (the hardening
  // saturates at sy + Q = 300: no equilibrium exists), restored, then 290: the same iterations,
  // displacements and states as A, bit for bit.
  Bar bar;
  Tangent run_a(*bar.behaviours, *bar.dofs), run_b(*bar.behaviours, *bar.dofs);
  Vector u_a = Vector::Zero(bar.dofs->n_dofs()), u_b = u_a;
  ASSERT_TRUE(newton_step(bar, run_a, 250.0, u_a).converged);
  run_a.commit();
  const test::NewtonLog log_a = newton_step(bar, run_a, 290.0, u_a);
  ASSERT_TRUE(log_a.converged);

  ASSERT_TRUE(newton_step(bar, run_b, 250.0, u_b).converged);
  run_b.commit();
  const Vector u_start = u_b;
  EXPECT_FALSE(newton_step(bar, run_b, 320.0, u_b).converged);
  run_b.restore();
  // The trial slot is back at the step's start (what a result written now would show).
  test::expect_close(run_b.states().variables(MaterialStates::Slot::End, 0, 0)[0], exact_p(250.0), 1e-10, 0.0,
                     "EPSPEQ after restore");
  u_b = u_start;
  const test::NewtonLog log_b = newton_step(bar, run_b, 290.0, u_b);
  ASSERT_TRUE(log_b.converged);
  EXPECT_EQ(log_a.residuals, log_b.residuals);
  EXPECT_EQ((u_a - u_b).lpNorm<Eigen::Infinity>(), 0.0);
  long differ = 0;
  using Slot = MaterialStates::Slot;
  for (int cell : bar.model.volume_cells())
    for (int q = 0; q < run_a.states().n_points(cell); ++q)
      for (int k = 0; k < 2; ++k)
        differ += run_a.states().variables(Slot::End, cell, q)[k] != run_b.states().variables(Slot::End, cell, q)[k] ||
                  run_a.states().stress(Slot::End, cell, q)[k] != run_b.states().stress(Slot::End, cell, q)[k];
  EXPECT_EQ(differ, 0);
  expect_exact(bar, run_b, u_b, 290.0);
}

TEST(ToyPlasticity, InternalVariablesReachTheResultFileAsVariElga) {
  // VARI_ELGA and SIEF_ELGA of the converged state, through the result step to its MED file
  // (one localization per cell type), read back with the MED library: EPSPEQ (V1) = p(t) and
  // SIXX = t at every point.
  Bar bar;
  Tangent tangent(*bar.behaviours, *bar.dofs);
  Vector u = Vector::Zero(bar.dofs->n_dofs());
  ASSERT_TRUE(newton_step(bar, tangent, 270.0, u).converged);
  tangent.commit();
  std::vector<ResultStep> steps(1);
  steps[0].nume_ordre = 1;
  steps[0].inst = 1.0;
  steps[0].elga["VARI_ELGA"] = variables_at_points(bar.model, tangent.states());
  steps[0].elga["SIEF_ELGA"] = stresses_at_points(bar.model, tangent.states());
  EXPECT_EQ(steps[0].elga["VARI_ELGA"].components, (std::vector<std::string>{"V1", "V2"}));
  EXPECT_EQ(bar.behaviours->of(0).variable_names(), (std::vector<std::string>{"EPSPEQ", "EPSPXX"}));
  const std::string path = test::write_bar_result(bar.block.mesh(), steps, "vari_elga");

  const int n_cells = static_cast<int>(bar.model.volume_cells().size());
  for (const auto& [field, column, expected] :
       {std::tuple<const char*, int, double>{"RESU____VARI_ELGA", 0, exact_p(270.0)},
        std::tuple<const char*, int, double>{"RESU____VARI_ELGA", 1, exact_p(270.0)},
        std::tuple<const char*, int, double>{"RESU____SIEF_ELGA", 0, 270.0}}) {
    const int nc = std::string(field).find("VARI") != std::string::npos ? 2 : 4;
    const test::Quad4Elga read = test::read_quad4_elga(path, field, 1, nc);
    ASSERT_EQ(read.n_cells, n_cells) << field;
    ASSERT_EQ(read.n_points, 4) << field;
    EXPECT_EQ(read.localization, "QUAD4_4_POINTS");
    for (size_t r = 0; r < read.values.size() / nc; ++r)
      test::expect_close(column == 1 ? std::abs(read.values[r * nc + column]) : read.values[r * nc + column], expected,
                         1e-10, 1e-14, field);
  }
}

}  // namespace
}  // namespace lunaster::engine

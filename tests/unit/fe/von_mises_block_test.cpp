// von Mises plasticity on a block of cells: the unit cube (HEXA8) or square (QUAD4, axisymmetric
// and plane stress), interior nodes distorted, stretched along one axis by an imposed
// displacement delta on the face x_a = 1, each face x_c = 0 held in its normal direction c (the
// symmetry planes), the other faces free. The exact solution is uniaxial stress: a uniform strain
// (eps = delta along the axis, the lateral strain -nu sigma / E - p / 2 across), which
// isoparametric cells hold exactly, and whose nodal forces balance exactly (2x2(x2) Gauss points
// integrate the element's B^T sigma for a uniform sigma): the discrete solution is the closed form
// sigma = SY + E_T (eps - SY / E), p = (sigma - SY) / H (the linear law; SSNP159's 1570 and
// 0.28215 at 29 %) or the traction curve's broken line (the piecewise law), to the Newton
// tolerance. Solved by Newton on assembly's Tangent (the consistent tangent: quadratic rate),
// loaded in steps to 29 %, then unloaded elastically.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>
#include <ostream>
#include <vector>

#include "engine/assembly/tangent.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "fe_test_util.hpp"
#include "newton_test_util.hpp"
#include "von_mises_test_util.hpp"

namespace lunaster::engine::von_mises_test::block {

struct BlockCase {
  const char* what;
  CellType type;
  Modelisation hyp;
  Law law;
  int axis;  ///< the stretched direction (the axial y in an axisymmetric model)
};

/// GoogleTest prints a case by its name.
void PrintTo(const BlockCase& c, std::ostream* os) { *os << c.what; }

struct Block {
  const BlockCase& c;
  test::BlockBuilder builder;
  FeModel model;
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<CellBehaviours> behaviours;
  std::vector<int> free, pulled;  ///< free equations; those of the face x_axis = 1
  double measure = 1.0;           ///< the pulled face's measure (per radian in an axisymmetric model)

  explicit Block(const BlockCase& bc) : c(bc), builder(bc.type, 2, 0.3) {
    builder.fill();
    const int dim = builder.dim();
    model = test::make_model(builder.mesh(), dim, c.hyp, ElasticMaterial{kE, kNu, 0.0});
    dofs = std::make_unique<DofMap>(builder.mesh(), model.volume_cells(), dim);
    behaviours = std::make_unique<CellBehaviours>(model);
    behaviours->assign(model.volume_cells(), make_law(c.law));
    std::vector<char> fixed(dofs->n_dofs(), 0);
    const Mesh& mesh = builder.mesh();
    for (int v = 0; v < mesh.n_nodes(); ++v)
      for (int comp = 0; comp < dim; ++comp) {
        const double x = mesh.node(v)[comp];
        if (x == 0.0) fixed[dofs->dof(v, comp)] = 1;
        if (comp == c.axis && x == 1.0) {
          fixed[dofs->dof(v, comp)] = 1;
          pulled.push_back(dofs->dof(v, comp));
        }
      }
    free = test::free_equations(fixed);
    if (c.hyp == Modelisation::Axisymmetric) measure = 0.5;  // int_0^1 r dr
  }

  /// The exact displacement of node v at axial strain eps and lateral strain `lateral`.
  double exact(int v, int comp, double eps, double lateral) {
    return (comp == c.axis ? eps : lateral) * builder.mesh().node(v)[comp];
  }
};

/// Newton's ratios r_{k+1} / r_k^2 over the iterations near the solution (r_k < 1e-2) whose next
/// residual is above round-off (1e-13: the last residual, at round-off, says nothing of the rate).
std::vector<double> quadratic_ratios(const std::vector<double>& r) {
  std::vector<double> ratios;
  for (size_t k = 0; k + 1 < r.size(); ++k)
    if (r[k] < 1e-2 && r[k + 1] > 1e-13) ratios.push_back(r[k + 1] / (r[k] * r[k]));
  return ratios;
}

void check_state(Block& block, Tangent& tangent, const Vector& u, double eps, Uniaxial exact, double lateral) {
  const Mesh& mesh = block.builder.mesh();
  const std::string what = std::string(block.c.what) + " at eps = " + std::to_string(eps);
  for (int v = 0; v < mesh.n_nodes(); ++v)
    for (int comp = 0; comp < block.builder.dim(); ++comp)
      test::expect_close(u(block.dofs->dof(v, comp)), block.exact(v, comp, eps, lateral), 1e-10, 1e-12 * eps,
                         what + ": u");
  using Slot = MaterialStates::Slot;
  const int axial = block.c.axis;
  for (int cell : block.model.volume_cells())
    for (int q = 0; q < tangent.states().n_points(cell); ++q) {
      const double* stress = tangent.states().stress(Slot::End, cell, q);
      for (int i = 0; i < tangent.states().tensor_size(); ++i)
        test::expect_close(stress[i], i == axial ? exact.stress : 0.0, 1e-10, 1e-10 * exact.stress, what + ": stress");
      test::expect_close(tangent.states().variables(Slot::End, cell, q)[0], exact.p, 1e-10, 1e-14, what + ": p");
    }
  Vector f_int;
  ASSERT_TRUE(tangent.assemble(u, nullptr, &f_int));
  double reaction = 0.0;
  for (int eq : block.pulled) reaction += f_int(eq);
  test::expect_close(reaction, exact.stress * block.measure, 1e-10, 0.0, what + ": reaction");
}

class VonMisesBlock : public ::testing::TestWithParam<BlockCase> {};

TEST_P(VonMisesBlock, ImposedStretchGivesTheClosedFormAtNewtonsQuadraticRate) {
  Block block(GetParam());
  Tangent tangent(*block.behaviours, *block.dofs);
  EXPECT_FALSE(tangent.constant());
  Vector u = Vector::Zero(block.dofs->n_dofs());
  const Vector no_load = Vector::Zero(block.dofs->n_dofs());
  const double scale = kSy * block.measure;  // the residual's force scale: the yield force
  auto solve = [&](double eps) {
    for (int eq : block.pulled) u(eq) = eps;
    std::printf("  %s, eps = %g\n", block.c.what, eps);
    return test::newton_step(tangent, block.free, no_load, scale, u);
  };
  double p_top = 0.0, stress_top = 0.0, lateral_top = 0.0;
  for (double eps : {0.003, 0.006, 0.01, 0.02, 0.05, 0.1, 0.2, 0.29}) {
    const test::NewtonLog log = solve(eps);
    ASSERT_TRUE(log.converged) << block.c.what << " at eps = " << eps;
    const Uniaxial exact = closed_form(block.c.law, eps);
    const double lateral = -kNu * exact.stress / kE - exact.p / 2.0;
    check_state(block, tangent, u, eps, exact, lateral);
    tangent.commit();
    p_top = exact.p;
    stress_top = exact.stress;
    lateral_top = lateral;
    if (exact.p == 0.0) continue;
    // Quadratic: r_{k+1} <= C r_k^2 with Newton's constant C of this problem, of order 1 (the
    // residual is relative to the yield force; here the ratios are below 6 at every step of the four
    // blocks). A linear rate rho gives r_{k+1} / r_k^2 = rho / r_k, which grows as r_k falls: over
    // 10 from r_k < 1e-2 on when rho > 0.1, and for a smaller rho as r_k falls further.
    const std::vector<double> ratios = quadratic_ratios(log.residuals);
    EXPECT_GE(ratios.size(), 1u) << block.c.what << " at eps = " << eps << ": no iteration to rate";
    for (double ratio : ratios) {
      std::printf("    r_k+1 / r_k^2 = %.3g\n", ratio);
      EXPECT_LE(ratio, 10.0) << block.c.what << " at eps = " << eps;
    }
  }
  // Elastic unloading by 0.005: sigma drops by 0.005 E, p is kept, the lateral strain grows back
  // by nu 0.005. Every point unloads from the first iterate on: the tangent is the elastic one
  // and the step is one linear solve.
  const test::NewtonLog log = solve(0.285);
  ASSERT_TRUE(log.converged);
  EXPECT_EQ(log.residuals.size(), 2u) << "an elastic unloading is one linear solve";
  check_state(block, tangent, u, 0.285, Uniaxial{stress_top - 0.005 * kE, p_top}, lateral_top + kNu * 0.005);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, VonMisesBlock,
    ::testing::Values(BlockCase{"HEXA8 3D linear", CellType::Hexa8, Modelisation::Solid3D, Law::Linear, 0},
                      BlockCase{"HEXA8 3D curve", CellType::Hexa8, Modelisation::Solid3D, Law::Curve, 0},
                      BlockCase{"QUAD4 axisymmetric curve", CellType::Quad4, Modelisation::Axisymmetric, Law::Curve, 1},
                      BlockCase{"QUAD4 plane stress linear", CellType::Quad4, Modelisation::PlaneStress, Law::Linear, 0}),
    [](const ::testing::TestParamInfo<BlockCase>& info) {
      std::string n = info.param.what;
      for (char& ch : n)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return n;
    });

}  // namespace lunaster::engine::von_mises_test::block

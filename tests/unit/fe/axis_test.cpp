// Axisymmetric (AXIS) kernels: the hoop row of B, the per-radian weight r |det J| w, a rigid
// axial translation (no force), a uniform u_r = c r (exact hoop strain at every integration point,
// also on cells touching the axis), the r-weighted pressure, and the 4x4 elastic matrix.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/assembly/assembly.hpp"
#include "engine/assembly/element_kernels.hpp"
#include "engine/material/elasticity.hpp"
#include "engine/core/error.hpp"
#include "axis_past_the_axis.hpp"
#include "fe_test_util.hpp"

namespace lunaster::engine {
namespace {

using test::BlockBuilder;
using test::expect_close;
using test::type_name;

const ElasticMaterial kAxisMat{2.0e6, 0.3, 0.0};
const CellType kTypes[] = {CellType::Tria3, CellType::Tria6, CellType::Quad4, CellType::Quad8};

/// A distorted block [x0, x0 + 1] x [0, 1] of `type` (x0 = 0 touches the axis).
Mesh axis_block(CellType type, double x0) {
  BlockBuilder b(type, 3, 0.25);
  b.fill();
  Mesh mesh = b.mesh();
  for (int n = 0; n < mesh.n_nodes(); ++n) mesh.coords[3 * static_cast<size_t>(n)] += x0;
  return mesh;
}

/// Calls f(q, weight, B, N, r) at every integration point of an AXIS cell.
template <int NN, class F>
void for_each_point(const Mesh& mesh, int cell, F&& f) {
  const ReferenceElement& re = reference_element(mesh.cell_types[cell]);
  const auto x = kernels::cell_coordinates<NN, 2>(mesh, cell);
  Eigen::Matrix<double, NN, 2> g;
  Eigen::Matrix<double, kernels::kVoigtAxis, 2 * NN> b;
  double sign = 0.0;
  for (int q = 0; q < re.n_qp; ++q) {
    const double w = kernels::axis_point<NN>(re, q, x, mesh, cell, sign, g, b);
    f(w, b, x);
  }
}

TEST(Axis, StrainMatrixHoopRowIsShapeOverRadius) {
  Eigen::Matrix<double, 3, 2> g;
  g << -1.0, -1.0, 1.0, 0.0, 0.0, 1.0;
  const double n[3] = {0.2, 0.3, 0.5};
  Eigen::Matrix<double, 4, 6> b;
  kernels::axis_strain_matrix<3>(g, n, 2.0, b);
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(b(2, 2 * a), n[a] / 2.0);   // eps_tt = u_r / r
    EXPECT_DOUBLE_EQ(b(2, 2 * a + 1), 0.0);      // u_z gives no hoop strain
    EXPECT_DOUBLE_EQ(b(0, 2 * a), g(a, 0));      // eps_rr
    EXPECT_DOUBLE_EQ(b(1, 2 * a + 1), g(a, 1));  // eps_zz (axis = y)
    EXPECT_DOUBLE_EQ(b(3, 2 * a), g(a, 1));      // gamma_rz
    EXPECT_DOUBLE_EQ(b(3, 2 * a + 1), g(a, 0));
  }
}

TEST(Axis, WeightIntegratesRadiusPerRadian) {
  // Sum of the weights = integral of r dA over [x0, x0 + 1] x [0, 1] = x0 + 1/2 (per radian).
  for (CellType t : kTypes)
    for (double x0 : {0.0, 1.0}) {
      const Mesh mesh = axis_block(t, x0);
      double sum = 0.0;
      for (int c = 0; c < mesh.n_cells(); ++c) {
        if (cell_dim(mesh.cell_types[c]) != 2) continue;
        kernels::dispatch_volume(mesh.cell_types[c], [&](auto nn, auto) {
          for_each_point<decltype(nn)::value>(mesh, c, [&](double w, const auto&, const auto&) { sum += w; });
        });
      }
      expect_close(sum, x0 + 0.5, 1e-13, 0, type_name(t) + " x0=" + std::to_string(x0));
    }
}

TEST(Axis, UniformRadialDisplacementGivesExactHoopStrain) {
  // u_r = c r, u_z = 0: eps_rr = eps_tt = c, eps_zz = gamma_rz = 0 at every point, on the axis too.
  const double c = 1.0e-3;
  for (CellType t : kTypes)
    for (double x0 : {0.0, 1.0}) {
      const Mesh mesh = axis_block(t, x0);
      for (int cell = 0; cell < mesh.n_cells(); ++cell) {
        if (cell_dim(mesh.cell_types[cell]) != 2) continue;
        kernels::dispatch_volume(mesh.cell_types[cell], [&](auto nn, auto) {
          constexpr int NN = decltype(nn)::value;
          for_each_point<NN>(mesh, cell, [&](double, const auto& b, const auto& x) {
            Eigen::Matrix<double, 2 * NN, 1> u = Eigen::Matrix<double, 2 * NN, 1>::Zero();
            for (int a = 0; a < NN; ++a) u(2 * a) = c * x(a, 0);
            const Eigen::Vector4d e = b * u;
            const std::string what = type_name(t) + " x0=" + std::to_string(x0);
            expect_close(e(0), c, 1e-12, 0, what);
            expect_close(e(2), c, 1e-12, 0, what);
            expect_close(e(1), 0.0, 0, 1e-15, what);
            expect_close(e(3), 0.0, 0, 1e-14, what);
          });
        });
      }
    }
}

TEST(Axis, RigidAxialTranslationGivesNoForceButRadialOneDoes) {
  for (CellType t : kTypes) {
    const Mesh mesh = axis_block(t, 1.0);
    const FeModel model = test::make_model(mesh, 2, Modelisation::Axisymmetric, kAxisMat);
    const DofMap dofs(mesh, model.volume_cells(), 2);
    Vector u = Vector::Zero(dofs.n_dofs()), f;
    for (int n = 0; n < mesh.n_nodes(); ++n) u(dofs.dof(n, DY)) = 1.0;
    assemble_internal_forces(model, dofs, u, f);
    EXPECT_LT(f.cwiseAbs().maxCoeff(), 1e-9 * kAxisMat.young) << type_name(t);
    const SparseMatrix k = test::assemble_matrix(model, dofs);
    EXPECT_LT((k * u).cwiseAbs().maxCoeff(), 1e-9 * kAxisMat.young) << type_name(t);
    // A uniform radial displacement stretches the hoops: not a rigid motion in AXIS.
    u.setZero();
    for (int n = 0; n < mesh.n_nodes(); ++n) u(dofs.dof(n, DX)) = 1.0;
    assemble_internal_forces(model, dofs, u, f);
    EXPECT_GT(f.cwiseAbs().maxCoeff(), 1e-3 * kAxisMat.young) << type_name(t);
  }
}

TEST(Axis, ElasticMatrixIsTheRestrictedThreeDimensionalOne) {
  const Eigen::Matrix4d d = elasticity_axis(kAxisMat);
  const double e = kAxisMat.young, nu = kAxisMat.poisson;
  const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) expect_close(d(i, j), i == j ? lambda + 2 * mu : lambda, 1e-14, 0);
  expect_close(d(3, 3), mu, 1e-14, 0);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(d(i, 3), 0.0);
}

TEST(Axis, PressureIsWeightedByRadiusAndVanishesOnTheAxis) {
  // SEG2 (2,0) -> (1,0) with the triangle below: normal +y; forces -p int N_a r dl:
  // node at r = 1: 1/3 + 2/6 = 2/3, node at r = 2: 1/6 + 2/3 = 5/6. A SEG2 on the axis
  // (x = 0) has no area: no force.
  Mesh mesh;
  mesh.dim = 2;
  mesh.coords = {2, 0, 0, 1, 0, 0, 1, -1, 0, 0, 0, 0, 0, -1, 0};
  mesh.node_names = {"N1", "N2", "N3", "N4", "N5"};
  mesh.cell_types = {CellType::Tria3, CellType::Tria3, CellType::Seg2, CellType::Seg2};
  mesh.cell_nodes = {1, 0, 2, 3, 4, 2, 0, 1, 4, 3};
  mesh.cell_offsets = {0, 3, 6, 8, 10};
  mesh.cell_names = {"M1", "M2", "M3", "M4"};
  const DofMap dofs(mesh, {0, 1}, 2);
  Vector f;
  assemble_pressure(mesh, 2, {2}, 10.0, dofs, f, true);
  expect_close(f(dofs.dof(1, DY)), -10.0 * 2.0 / 3.0, 1e-14, 0);
  expect_close(f(dofs.dof(0, DY)), -10.0 * 5.0 / 6.0, 1e-14, 0);
  expect_close(f(dofs.dof(0, DX)), 0.0, 0, 1e-14);
  Vector g;
  assemble_pressure(mesh, 2, {3}, 10.0, dofs, g, true);
  EXPECT_EQ(g.cwiseAbs().maxCoeff(), 0.0);
}

TEST(Axis, DistributedForceSharesThePressureQuadrature) {
  // The SEG2 of the test above, loaded by a force per unit length (0, -10): the same nodal forces
  // as the pressure 10 (its normal is +y), whatever the edge's direction; a volume force F on the
  // triangle (1,0) (2,0) (1,-1) sums to F int r dA = F (1/2) (1 + 2 + 1) / 3 = 2 F / 3 per radian.
  Mesh mesh;
  mesh.dim = 2;
  mesh.coords = {2, 0, 0, 1, 0, 0, 1, -1, 0};
  mesh.node_names = {"N1", "N2", "N3"};
  mesh.cell_types = {CellType::Tria3, CellType::Seg2, CellType::Seg2};
  mesh.cell_nodes = {1, 0, 2, 0, 1, 1, 0};
  mesh.cell_offsets = {0, 3, 5, 7};
  mesh.cell_names = {"M1", "M2", "M3"};
  const DofMap dofs(mesh, {0}, 2);
  Vector p, f, g, v;
  assemble_pressure(mesh, 2, {1}, 10.0, dofs, p, true);
  assemble_distributed_force(mesh, 2, {1}, 1, {0.0, -10.0, 0.0}, dofs, f, true);
  assemble_distributed_force(mesh, 2, {2}, 1, {0.0, -10.0, 0.0}, dofs, g, true);
  EXPECT_LT((f - p).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((g - p).cwiseAbs().maxCoeff(), 1e-14);
  assemble_distributed_force(mesh, 2, {0}, 2, {3.0, -6.0, 0.0}, dofs, v, true);
  double fx = 0, fy = 0;
  for (int n = 0; n < 3; ++n) fx += v(dofs.dof(n, DX)), fy += v(dofs.dof(n, DY));
  expect_close(fx, 3.0 * 2.0 / 3.0, 1e-14, 0);
  expect_close(fy, -6.0 * 2.0 / 3.0, 1e-14, 0);
  // A cell of another dimension than the one given is refused.
  Vector w;
  EXPECT_THROW(assemble_distributed_force(mesh, 2, {0}, 1, {1.0, 0.0, 0.0}, dofs, w, true), DeckError);
}

TEST(Axis, IntegrationPointOnTheAxisIsADeckError) {
  // A triangle with every node on x = 0 would be degenerate; one curved past the axis is not:
  // a TRIA6 whose mid-side node pulls an edge to x < 0 puts a point at r <= 0.
  const Mesh mesh = test::tria6_past_the_axis();
  const FeModel model = test::make_model(mesh, 2, Modelisation::Axisymmetric, kAxisMat);
  const DofMap dofs(mesh, {0}, 2);
  std::vector<Triplet> t;
  try {
    assemble_stiffness(model, dofs, t);
    FAIL() << "expected a DeckError";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("cell M1 (axisymmetric): integration point at radius"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace lunaster::engine

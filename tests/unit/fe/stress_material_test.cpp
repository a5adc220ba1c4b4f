// Equivalent stresses, nodal averaging and the Hooke matrices.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "engine/assembly/stress.hpp"
#include "engine/core/error.hpp"
#include "engine/material/elasticity.hpp"
#include "fe_test_util.hpp"

namespace lunaster::engine {
namespace {

using test::expect_close;

TEST(Sieq, KnownTensor) {
  ElnoField s;
  s.components = {"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"};
  s.cell_offsets = {0, 2};
  // row 0: principal stresses 1, 2, 4 on the axes; row 1: pure shear 3 in xy -> -3, 0, 3
  s.values = {4, 1, 2, 0, 0, 0, 0, 0, 0, 3, 0, 0};
  const ElnoField q = compute_sieq_elno(s);
  ASSERT_EQ(q.components, (std::vector<std::string>{"VMIS", "TRESCA", "PRIN_1", "PRIN_2", "PRIN_3", "VMIS_SG", "TRSIG"}));
  const double vm0 = std::sqrt(0.5 * ((4 - 1) * (4 - 1) + (1 - 2) * (1 - 2) + (2 - 4) * (2 - 4)));
  expect_close(q.value(0, 0, 0), vm0, 1e-14, 0);
  expect_close(q.value(0, 0, 1), 3.0, 1e-14, 0);
  expect_close(q.value(0, 0, 2), 1.0, 1e-14, 0);
  expect_close(q.value(0, 0, 3), 2.0, 1e-14, 0);
  expect_close(q.value(0, 0, 4), 4.0, 1e-14, 0);
  expect_close(q.value(0, 0, 5), vm0, 1e-14, 0);
  expect_close(q.value(0, 0, 6), 7.0, 1e-14, 0);
  expect_close(q.value(0, 1, 0), 3.0 * std::sqrt(3.0), 1e-14, 0);
  expect_close(q.value(0, 1, 2), -3.0, 1e-14, 1e-14);
  expect_close(q.value(0, 1, 3), 0.0, 0, 1e-14);
  expect_close(q.value(0, 1, 4), 3.0, 1e-14, 0);
  expect_close(q.value(0, 1, 1), 6.0, 1e-14, 0);
}

TEST(Sieq, SignedVonMisesFollowsTrace2D) {
  ElnoField s;
  s.components = {"SIXX", "SIYY", "SIZZ", "SIXY"};
  s.cell_offsets = {0, 1};
  s.values = {-100, -20, -36, 0};
  const ElnoField q = compute_sieq_elno(s);
  EXPECT_LT(q.value(0, 0, 5), 0.0);
  expect_close(q.value(0, 0, 5), -q.value(0, 0, 0), 1e-14, 0);
  expect_close(q.value(0, 0, 6), -156, 1e-14, 0);
}

TEST(ElnoToNoeu, ArithmeticMeanOverCells) {
  Mesh mesh;
  mesh.dim = 2;
  mesh.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 5, 5, 0};
  mesh.node_names = {"N1", "N2", "N3", "N4", "N5"};
  mesh.cell_types = {CellType::Tria3, CellType::Tria3};
  mesh.cell_nodes = {0, 1, 2, 1, 3, 2};
  mesh.cell_offsets = {0, 3, 6};
  ElnoField e;
  e.components = {"A"};
  e.cell_offsets = {0, 3, 6};
  e.values = {1, 2, 3, 10, 20, 30};
  const NodalField n = elno_to_noeu(mesh, e);
  expect_close(n.value(0, 0), 1.0, 1e-15, 0);
  expect_close(n.value(1, 0), 6.0, 1e-15, 0);   // (2 + 10) / 2
  expect_close(n.value(2, 0), 16.5, 1e-15, 0);  // (3 + 30) / 2
  expect_close(n.value(3, 0), 20.0, 1e-15, 0);
  EXPECT_FALSE(n.has(4, 0));
}

TEST(Elasticity, MatricesInvertTheCompliance) {
  const ElasticMaterial m{2.0e6, 0.3, 0.0};
  const double e = m.young, nu = m.poisson, g = e / (2 * (1 + nu));
  Eigen::Matrix<double, 6, 6> c = Eigen::Matrix<double, 6, 6>::Zero();  // compliance
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) c(i, j) = -nu / e;
    c(i, i) = 1 / e;
    c(3 + i, 3 + i) = 1 / g;
  }
  const Eigen::Matrix<double, 6, 6> d = elasticity_3d(m);
  EXPECT_LT((d * c - Eigen::Matrix<double, 6, 6>::Identity()).norm(), 1e-12);
  // plane stress: the in-plane block of the compliance
  Eigen::Matrix3d cs;
  cs << c(0, 0), c(0, 1), 0, c(1, 0), c(1, 1), 0, 0, 0, c(3, 3);
  EXPECT_LT((elasticity_2d(m, Modelisation::PlaneStress) * cs - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  // plane strain: the 3D matrix restricted to eps_zz = 0
  const Eigen::Matrix3d dp = elasticity_2d(m, Modelisation::PlaneStrain);
  expect_close(dp(0, 0), d(0, 0), 1e-14, 0);
  expect_close(dp(0, 1), d(0, 1), 1e-14, 0);
  expect_close(dp(2, 2), d(3, 3), 1e-14, 0);
  expect_close(sigma_zz_2d(m, Modelisation::PlaneStrain, 3.0, 5.0), d(2, 0) * (1 / (d(0, 0) + d(0, 1))) * 8.0, 1e-12, 0);
  expect_close(sigma_zz_2d(m, Modelisation::PlaneStress, 3.0, 5.0), 0.0, 0, 0);
  const Eigen::Matrix4d full = elasticity_2d_full(m, Modelisation::PlaneStrain);
  expect_close(full(2, 0), d(2, 0), 1e-14, 0);
  EXPECT_THROW(elasticity_3d(ElasticMaterial{-1.0, 0.3, 0.0}), lunaster::InternalError);
}

}  // namespace
}  // namespace lunaster::engine

// Patch tests: on a distorted block of every volume element type, an exact
// linear displacement imposed on the boundary is reproduced inside, with the
// exact constant stress at every ELNO point; rigid-body modes of every element
// stiffness; pressure patch tests (uniform -p stress, resultant p * area).
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "engine/assembly/assembly.hpp"
#include "engine/assembly/stress.hpp"
#include "engine/core/error.hpp"
#include "engine/material/elasticity.hpp"
#include "fe_test_util.hpp"

namespace lunaster::engine {
namespace {

using test::BlockBuilder;
using test::expect_close;
using test::type_name;

const ElasticMaterial kPatchMat{1000.0, 0.3, 0.0};

bool on_boundary(const double* x, int dim) {
  for (int d = 0; d < dim; ++d)
    if (std::abs(x[d]) < 1e-12 || std::abs(x[d] - 1) < 1e-12) return true;
  return false;
}

/// Exact field u = A x + b and its stress (SIXX SIYY SIZZ SIXY [SIXZ SIYZ]).
struct LinearField {
  Eigen::Matrix3d a;
  Eigen::Vector3d b;
  Eigen::Vector3d at(const double* x) const { return a * Eigen::Vector3d(x[0], x[1], x[2]) + b; }
  std::vector<double> stress(int dim, Modelisation mod) const {
    const Eigen::Matrix3d e = 0.5 * (a + a.transpose());
    if (dim == 2) {
      const Eigen::Vector3d s = elasticity_2d(kPatchMat, mod) * Eigen::Vector3d(e(0, 0), e(1, 1), 2 * e(0, 1));
      return {s(0), s(1), sigma_zz_2d(kPatchMat, mod, s(0), s(1)), s(2)};
    }
    Eigen::Matrix<double, 6, 1> v;
    v << e(0, 0), e(1, 1), e(2, 2), 2 * e(0, 1), 2 * e(0, 2), 2 * e(1, 2);
    const Eigen::Matrix<double, 6, 1> s = elasticity_3d(kPatchMat) * v;
    return {s(0), s(1), s(2), s(3), s(4), s(5)};
  }
};

LinearField patch_field(int dim) {
  LinearField f;
  f.a << 1.0e-3, -2.0e-3, 0.5e-3, 3.0e-3, -1.5e-3, 2.5e-3, -0.7e-3, 1.2e-3, 2.0e-3;
  f.b << 0.01, -0.02, 0.03;
  if (dim == 2) {
    f.a.row(2).setZero();
    f.a.col(2).setZero();
    f.b(2) = 0;
  }
  return f;
}

void run_patch(CellType type, Modelisation mod) {
  const std::string name = type_name(type);
  BlockBuilder block(type, 3, 0.5);
  const int dim = block.dim();
  block.fill();
  const Mesh& mesh = block.mesh();
  const FeModel model = test::make_model(mesh, dim, mod, kPatchMat);
  const DofMap dofs(mesh, model.volume_cells(), dim);
  const SparseMatrix k = test::assemble_matrix(model, dofs);
  const LinearField field = patch_field(dim);
  std::map<int, double> fixed;
  Vector exact(dofs.n_dofs());
  int n_interior = 0;
  for (int node = 0; node < mesh.n_nodes(); ++node) {
    const Eigen::Vector3d u = field.at(mesh.node(node));
    const bool boundary = on_boundary(mesh.node(node), dim);
    n_interior += !boundary;
    for (int c = 0; c < dim; ++c) {
      exact(dofs.dof(node, c)) = u(c);
      if (boundary) fixed[dofs.dof(node, c)] = u(c);
    }
  }
  ASSERT_GT(n_interior, 0) << name;
  const Vector u = test::solve_with_dirichlet(k, Vector::Zero(dofs.n_dofs()), fixed);
  const double scale = exact.cwiseAbs().maxCoeff();
  for (int i = 0; i < dofs.n_dofs(); ++i) expect_close(u(i), exact(i), 0, 1e-10 * scale, name + " u");

  // internal forces of the exact field vanish at interior nodes and equal K u
  Vector f_int;
  assemble_internal_forces(model, dofs, exact, f_int);
  const Vector ku = k * exact;
  for (int i = 0; i < dofs.n_dofs(); ++i) {
    expect_close(f_int(i), ku(i), 1e-10, 1e-10, name + " f_int = K u");
    if (!fixed.count(i)) expect_close(f_int(i), 0.0, 0, 1e-10, name + " interior equilibrium");
  }

  const std::vector<double> sigma = field.stress(dim, mod);
  const ElnoField elno = compute_sigm_elno(model, dofs, u);
  ASSERT_EQ(elno.n_components(), static_cast<int>(sigma.size()));
  double smax = 0;
  for (double s : sigma) smax = std::max(smax, std::abs(s));
  int checked = 0;
  for (int c = 0; c < elno.n_cells(); ++c)
    for (int a = 0; a < elno.n_rows(c); ++a)
      for (int k2 = 0; k2 < elno.n_components(); ++k2, ++checked)
        expect_close(elno.value(c, a, k2), sigma[k2], 1e-10, 1e-10 * smax, name + " " + elno.components[k2]);
  EXPECT_GT(checked, 0);
  const NodalField noeu = elno_to_noeu(mesh, elno);
  for (int node = 0; node < mesh.n_nodes(); ++node)
    for (int k2 = 0; k2 < noeu.n_components(); ++k2) {
      ASSERT_TRUE(noeu.has(node, k2));
      expect_close(noeu.value(node, k2), sigma[k2], 1e-10, 1e-10 * smax, name + " NOEU");
    }
}

TEST(Patch, EveryVolumeElementPlaneStrainOr3D) {
  for (CellType t : test::volume_types())
    run_patch(t, cell_dim(t) == 2 ? Modelisation::PlaneStrain : Modelisation::Solid3D);
}

TEST(Patch, PlaneStressElements) {
  for (CellType t : {CellType::Tria3, CellType::Tria6, CellType::Quad4, CellType::Quad8})
    run_patch(t, Modelisation::PlaneStress);
}

TEST(Patch, RigidBodyModesHaveNoEnergy) {
  for (CellType t : test::volume_types()) {
    BlockBuilder block(t, 1, 0.0);
    const int dim = block.dim();
    // move the vertices of the single-cell block to a skewed shape
    Mesh& m = block.mesh();
    for (int node = 0; node < m.n_nodes(); ++node) {
      double* x = &m.coords[3 * node];
      const double x0 = x[0], x1 = x[1], x2 = x[2];
      x[0] = 1.3 * x0 + 0.2 * x1 + 0.1 * x2 * x1;
      x[1] = 0.9 * x1 - 0.15 * x0 + 0.05 * x0 * x1;
      if (dim == 3) x[2] = 1.1 * x2 + 0.1 * x0 - 0.05 * x1;
    }
    block.fill();  // mid-side nodes are created from the moved vertices
    const FeModel model = test::make_model(m, dim, dim == 2 ? Modelisation::PlaneStrain : Modelisation::Solid3D, kPatchMat);
    const DofMap dofs(m, model.volume_cells(), dim);
    const Eigen::MatrixXd k = Eigen::MatrixXd(test::assemble_matrix(model, dofs));
    const double knorm = k.norm();
    std::vector<Vector> modes;
    for (int c = 0; c < dim; ++c) {
      Vector v = Vector::Zero(dofs.n_dofs());
      for (int node = 0; node < m.n_nodes(); ++node)
        if (dofs.dof(node, 0) >= 0) v(dofs.dof(node, c)) = 1.0;
      modes.push_back(v);
    }
    const int n_rot = dim == 2 ? 1 : 3;
    for (int r = 0; r < n_rot; ++r) {  // rotation about axis z (2D) or x, y, z
      const int axis = dim == 2 ? 2 : r;
      Vector v = Vector::Zero(dofs.n_dofs());
      for (int node = 0; node < m.n_nodes(); ++node) {
        if (dofs.dof(node, 0) < 0) continue;
        Eigen::Vector3d w = Eigen::Vector3d::Zero();
        w(axis) = 1.0;
        const Eigen::Vector3d x(m.node(node)[0], m.node(node)[1], m.node(node)[2]);
        const Eigen::Vector3d u = w.cross(x);
        for (int c = 0; c < dim; ++c) v(dofs.dof(node, c)) = u(c);
      }
      modes.push_back(v);
    }
    for (const Vector& v : modes) EXPECT_LT((k * v).norm(), 1e-12 * knorm * v.norm()) << type_name(t);
    // ... and the stiffness has exactly that many zero eigenvalues
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k).eigenvalues();
    int zeros = 0;
    for (int i = 0; i < ev.size(); ++i) zeros += std::abs(ev(i)) < 1e-10 * ev.maxCoeff();
    EXPECT_EQ(zeros, static_cast<int>(modes.size())) << type_name(t);
  }
}

/// Block under pressure p on its top face, bottom face held with minimal
/// constraints: uniform stress -p along the load direction, zero elsewhere.
void run_pressure_patch(CellType type) {
  const std::string name = type_name(type);
  const double p = 250.0;
  BlockBuilder block(type, 2, 0.4);
  const int dim = block.dim();
  block.fill();
  const std::vector<int> top = block.top_faces();
  const Mesh& mesh = block.mesh();
  const FeModel model = test::make_model(mesh, dim, dim == 2 ? Modelisation::PlaneStrain : Modelisation::Solid3D, kPatchMat);
  const DofMap dofs(mesh, model.volume_cells(), dim);
  Vector f = Vector::Zero(dofs.n_dofs());
  assemble_pressure(mesh, dim, top, p, dofs, f);
  double resultant[3] = {0, 0, 0};
  for (int i = 0; i < dofs.n_dofs(); ++i) resultant[dofs.component_of(i)] += f(i);
  for (int c = 0; c < dim; ++c) expect_close(resultant[c], c == dim - 1 ? -p * 1.0 : 0.0, 1e-12, 1e-10, name + " resultant");

  std::map<int, double> fixed;
  for (int node = 0; node < mesh.n_nodes(); ++node) {
    const double* x = mesh.node(node);
    if (std::abs(x[dim - 1]) > 1e-12) continue;
    fixed[dofs.dof(node, dim - 1)] = 0.0;  // bottom: normal displacement
    const bool origin = std::abs(x[0]) < 1e-12 && (dim == 2 || std::abs(x[1]) < 1e-12);
    const bool x_axis = dim == 3 && std::abs(x[0] - 1) < 1e-12 && std::abs(x[1]) < 1e-12;
    if (origin)
      for (int c = 0; c < dim - 1; ++c) fixed[dofs.dof(node, c)] = 0.0;
    if (x_axis) fixed[dofs.dof(node, 1)] = 0.0;
  }
  const SparseMatrix k = test::assemble_matrix(model, dofs);
  const Vector u = test::solve_with_dirichlet(k, f, fixed);
  const ElnoField elno = compute_sigm_elno(model, dofs, u);
  std::vector<double> sigma(elno.n_components(), 0.0);
  sigma[dim - 1] = -p;
  if (dim == 2) sigma[2] = kPatchMat.poisson * -p;  // plane strain SIZZ
  for (int c = 0; c < elno.n_cells(); ++c)
    for (int a = 0; a < elno.n_rows(c); ++a)
      for (int k2 = 0; k2 < elno.n_components(); ++k2)
        expect_close(elno.value(c, a, k2), sigma[k2], 1e-9, 1e-9 * p, name + " " + elno.components[k2]);
}

TEST(Pressure, PatchTestUniformStressAndResultant) {
  for (CellType t : test::volume_types()) run_pressure_patch(t);
}

TEST(Pressure, PositivePressurePushesAgainstTheCellNormal) {
  // One SEG2 from (1,0) to (0,0): t = -x, normal (t_y, -t_x) = (0, 1); p > 0 pushes along -y.
  Mesh mesh;
  mesh.dim = 2;
  mesh.coords = {1, 0, 0, 0, 0, 0, 0, -1, 0};
  mesh.node_names = {"N1", "N2", "N3"};
  mesh.cell_types = {CellType::Tria3, CellType::Seg2};
  mesh.cell_nodes = {1, 0, 2, 0, 1};  // triangle below the edge, then the edge
  mesh.cell_offsets = {0, 3, 5};
  mesh.cell_names = {"M1", "M2"};
  const DofMap dofs(mesh, {0}, 2);
  Vector f;
  assemble_pressure(mesh, 2, {1}, 10.0, dofs, f);
  expect_close(f(dofs.dof(0, DY)), -5.0, 1e-14, 0);
  expect_close(f(dofs.dof(1, DY)), -5.0, 1e-14, 0);
  expect_close(f(dofs.dof(0, DX)), 0.0, 0, 1e-14);
  EXPECT_THROW(assemble_pressure(mesh, 2, {0}, 10.0, dofs, f), lunaster::DeckError);
}

}  // namespace
}  // namespace lunaster::engine

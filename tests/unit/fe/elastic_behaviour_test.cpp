// Linear elasticity through the behaviour interface against the element formula it replaced,
// K_e = sum_q B^T D B |det J| w_q with D the Hooke matrix of the cell's hypothesis, written here
// from the reference element's tables and the Hooke matrices: the stiffness of both assembly paths
// (the linear column split and the element loop over states) to 1e-14 of the matrix's scale,
// the internal force K u and the stresses, for every volume type and every 2D hypothesis.
#include <gtest/gtest.h>

#include <random>

#include "engine/assembly/assembly.hpp"
#include "engine/assembly/stress.hpp"
#include "engine/assembly/tangent.hpp"
#include "engine/core/error.hpp"
#include "engine/fe/reference_element.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "engine/material/elasticity.hpp"
#include "fe_test_util.hpp"

namespace lunaster::engine {
namespace {

using test::BlockBuilder;
using test::type_name;

const ElasticMaterial kBehaviourMat{2.0e11, 0.3, 7800.0};

/// The formula: sum_q B^T D B w_q per cell, scattered as triplets. Written with dynamic sizes
/// from the reference element's tables (x, J = x^T dN, g = dN J^-1, B from g), so that it
/// shares no code with the kernels it checks (and costs no fixed-size instantiations).
SparseMatrix formula_stiffness(const FeModel& model, const DofMap& dofs) {
  std::vector<Triplet> t;
  const Mesh& mesh = *model.mesh;
  for (int cell : model.volume_cells()) {
    const ReferenceElement& re = reference_element(mesh.cell_types[cell]);
    const int nn = re.n_nodes, dim = re.dim, nd = nn * dim;
    const int* nodes = mesh.cell(cell);
    Eigen::MatrixXd x(nn, dim);
    for (int a = 0; a < nn; ++a)
      for (int k = 0; k < dim; ++k) x(a, k) = mesh.coords[3 * static_cast<size_t>(nodes[a]) + k];
    const bool axis = model.modelisation[cell] == Modelisation::Axisymmetric;
    Eigen::MatrixXd d;
    if (dim == 3)
      d = elasticity_3d(kBehaviourMat);
    else if (axis)
      d = elasticity_axis(kBehaviourMat);
    else
      d = elasticity_2d(kBehaviourMat, model.modelisation[cell]);
    Eigen::MatrixXd ke = Eigen::MatrixXd::Zero(nd, nd);
    for (int q = 0; q < re.n_qp; ++q) {
      Eigen::MatrixXd dref(nn, dim);
      for (int a = 0; a < nn; ++a)
        for (int k = 0; k < dim; ++k) dref(a, k) = re.dn[(static_cast<size_t>(q) * nn + a) * dim + k];
      const Eigen::MatrixXd jac = x.transpose() * dref;
      const Eigen::MatrixXd g = dref * jac.inverse();
      const double* n = &re.n[static_cast<size_t>(q) * nn];
      double r = 0.0;  // AXIS: the radius of the point, the hoop strain u_r / r and the measure r dA
      for (int a = 0; a < nn; ++a) r += n[a] * x(a, 0);
      const double w = std::abs(jac.determinant()) * re.weight[q] * (axis ? r : 1.0);
      Eigen::MatrixXd b = Eigen::MatrixXd::Zero(d.rows(), nd);
      for (int a = 0; a < nn; ++a) {
        const int c = dim * a;
        b(0, c) = g(a, 0);
        b(1, c + 1) = g(a, 1);
        if (dim == 3) {
          b(2, c + 2) = g(a, 2);
          b(3, c) = g(a, 1);
          b(3, c + 1) = g(a, 0);
          b(4, c) = g(a, 2);
          b(4, c + 2) = g(a, 0);
          b(5, c + 1) = g(a, 2);
          b(5, c + 2) = g(a, 1);
        } else if (axis) {  // rows rr, zz, tt, rz
          b(2, c) = n[a] / r;
          b(3, c) = g(a, 1);
          b(3, c + 1) = g(a, 0);
        } else {
          b(2, c) = g(a, 1);
          b(2, c + 1) = g(a, 0);
        }
      }
      ke.noalias() += w * b.transpose() * d * b;
    }
    for (int i = 0; i < nd; ++i)
      for (int j = 0; j < nd; ++j) t.emplace_back(dofs.dof(nodes[i / dim], i % dim), dofs.dof(nodes[j / dim], j % dim), ke(i, j));
  }
  SparseMatrix k(dofs.n_dofs(), dofs.n_dofs());
  k.setFromTriplets(t.begin(), t.end());
  return k;
}

double max_abs_difference(const SparseMatrix& a, const SparseMatrix& b) {
  const SparseMatrix d = a - b;
  double m = 0.0;
  for (Eigen::Index p = 0; p < d.nonZeros(); ++p) m = std::max(m, std::abs(d.valuePtr()[p]));
  return m;
}

struct Case {
  CellType type;
  Modelisation hypothesis;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (CellType type : test::volume_types()) {
    if (cell_dim(type) == 3) {
      out.push_back({type, Modelisation::Solid3D});
      continue;
    }
    for (Modelisation m : {Modelisation::PlaneStrain, Modelisation::PlaneStress, Modelisation::Axisymmetric})
      out.push_back({type, m});
  }
  return out;
}

std::string label(const Case& c) {
  const char* h[] = {"none", "plane strain", "plane stress", "3D", "axisymmetric"};
  return type_name(c.type) + std::string(", ") + h[static_cast<int>(c.hypothesis)];
}

TEST(ElasticBehaviour, IsLinearWithoutInternalVariables) {
  const Elasticity elasticity(kBehaviourMat);
  EXPECT_TRUE(elasticity.is_linear());
  EXPECT_EQ(elasticity.n_variables(), 0);
}

TEST(ElasticBehaviour, StiffnessForceAndStressesAreTheFormulas) {
  for (const Case& c : cases()) {
    BlockBuilder block(c.type, cell_dim(c.type) == 2 ? 4 : 2, 0.2);
    block.fill();
    const int dim = block.dim();
    // x in [0.5, 1.5]: an axisymmetric cell needs r > 0 at its points.
    for (size_t v = 0; v < block.mesh().coords.size(); v += 3) block.mesh().coords[v] += 0.5;
    const FeModel model = test::make_model(block.mesh(), dim, c.hypothesis, kBehaviourMat);
    const DofMap dofs(block.mesh(), model.volume_cells(), dim);
    const CellBehaviours behaviours(model);
    const SparseMatrix ref = formula_stiffness(model, dofs);
    double scale = 0.0;
    for (Eigen::Index p = 0; p < ref.nonZeros(); ++p) scale = std::max(scale, std::abs(ref.valuePtr()[p]));
    ASSERT_GT(scale, 0.0) << label(c);

    // The linear path (the matrix of every linear solve) and the element loop over states.
    const SparseMatrix k_linear = assemble_stiffness_matrix(model, dofs);
    Tangent tangent(behaviours, dofs);
    EXPECT_TRUE(tangent.constant()) << label(c);
    MaterialStates states = make_material_states(behaviours);
    SparseMatrix k_loop;
    Vector f_loop;
    std::mt19937 random(3);
    std::uniform_real_distribution<double> uniform(-1e-3, 1e-3);
    Vector u(dofs.n_dofs());
    for (Eigen::Index i = 0; i < u.size(); ++i) u(i) = uniform(random);
    ASSERT_TRUE(assemble_internal_force(behaviours, dofs, u, states, &f_loop, &k_loop)) << label(c);
    EXPECT_LE(max_abs_difference(k_linear, ref), 1e-14 * scale) << label(c) << ": linear path";
    EXPECT_LE(max_abs_difference(k_loop, ref), 1e-14 * scale) << label(c) << ": element loop";
    // The patterns are the same: the loop's matrix goes where the linear one went.
    EXPECT_EQ(k_loop.nonZeros(), k_linear.nonZeros()) << label(c);

    // f_int = K u, by the loop and by the linear internal forces.
    const Vector ku = ref * u;
    Vector f_linear;
    assemble_internal_forces(model, dofs, u, f_linear);
    EXPECT_LE((f_loop - ku).lpNorm<Eigen::Infinity>(), 1e-13 * ku.lpNorm<Eigen::Infinity>()) << label(c);
    EXPECT_LE((f_linear - ku).lpNorm<Eigen::Infinity>(), 1e-13 * ku.lpNorm<Eigen::Infinity>()) << label(c);

    // The stresses stored at the points are those the recovery extrapolates (SIGM_ELNO) and
    // the force of a constant tangent comes from the same loop.
    Vector f_tangent;
    SparseMatrix k_tangent;
    ASSERT_TRUE(tangent.assemble(u, &k_tangent, &f_tangent));
    EXPECT_EQ(max_abs_difference(k_tangent, k_linear), 0.0) << label(c);
    EXPECT_EQ((f_tangent - f_loop).lpNorm<Eigen::Infinity>(), 0.0) << label(c);
    const ElnoField sigm = compute_sigm_elno(model, dofs, u);
    const int nt = tensor_size(dim);
    double worst = 0.0, smax = 0.0;
    for (int cell : model.volume_cells()) {
      const ReferenceElement& re = reference_element(block.mesh().cell_types[cell]);
      for (int a = 0; a < re.n_nodes; ++a)
        for (int k = 0; k < nt; ++k) {
          double extrapolated = 0.0;
          for (int q = 0; q < re.n_qp; ++q)
            extrapolated += re.extrapolation[static_cast<size_t>(a) * re.n_qp + q] *
                            tangent.states().stress(MaterialStates::Slot::End, cell, q)[k];
          worst = std::max(worst, std::abs(extrapolated - sigm.value(cell, a, k)));
          smax = std::max(smax, std::abs(sigm.value(cell, a, k)));
        }
    }
    EXPECT_LE(worst, 1e-12 * smax) << label(c) << ": stored stresses against SIGM_ELNO";
  }
}

TEST(ElasticBehaviour, ACellWithoutMaterialIsNamed) {
  BlockBuilder block(CellType::Quad4, 2, 0.0);
  block.fill();
  FeModel model = test::make_model(block.mesh(), 2, Modelisation::PlaneStrain, kBehaviourMat);
  model.material[2] = -1;
  const DofMap dofs(block.mesh(), model.volume_cells(), 2);
  try {
    assemble_stiffness_matrix(model, dofs);
    FAIL() << "no error";
  } catch (const DeckError& e) {
    EXPECT_EQ(e.message(), "cell " + block.mesh().cell_names[2] + " carries an element but no material");
  }
}

}  // namespace
}  // namespace lunaster::engine

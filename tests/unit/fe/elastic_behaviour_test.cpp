// Linear elasticity through the behaviour interface against the element formula it replaced,
// K_e = sum_q B^T D B |det J| w_q with D the Hooke matrix of the cell's hypothesis, written here
// from the kernel pieces (B, Jacobian, Hooke matrices): the stiffness of both assembly paths
// (the linear column split and the element loop over states) to 1e-14 of the matrix's scale,
// the internal force K u and the stresses, for every volume type and every 2D hypothesis.
#include <gtest/gtest.h>

#include <random>

#include "engine/assembly/assembly.hpp"
#include "engine/assembly/element_kernels.hpp"
#include "engine/assembly/tangent.hpp"
#include "engine/assembly/stress.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "engine/material/elasticity.hpp"
#include "fe_test_util.hpp"

namespace lunaster::engine {
namespace {

using test::BlockBuilder;
using test::type_name;

const ElasticMaterial kBehaviourMat{2.0e11, 0.3, 7800.0};

template <int DIM>
Eigen::Matrix<double, DIM == 2 ? 3 : 6, DIM == 2 ? 3 : 6> hooke(Modelisation m) {
  if constexpr (DIM == 2) {
    return elasticity_2d(kBehaviourMat, m);
  } else {
    return elasticity_3d(kBehaviourMat);
  }
}

/// The formula: sum_q B^T D B w_q per cell, scattered as triplets.
SparseMatrix formula_stiffness(const FeModel& model, const DofMap& dofs) {
  std::vector<Triplet> t;
  for (int cell : model.volume_cells()) {
    kernels::dispatch_volume(model.mesh->cell_types[cell], [&](auto nn, auto dim) {
      constexpr int NN = decltype(nn)::value, DIM = decltype(dim)::value, ND = NN * DIM;
      const Mesh& mesh = *model.mesh;
      const ReferenceElement& re = reference_element(mesh.cell_types[cell]);
      const auto x = kernels::cell_coordinates<NN, DIM>(mesh, cell);
      Eigen::Matrix<double, ND, ND> ke = Eigen::Matrix<double, ND, ND>::Zero();
      Eigen::Matrix<double, NN, DIM> g;
      double sign = 0.0;
      const bool axis = model.modelisation[cell] == Modelisation::Axisymmetric;
      for (int q = 0; q < re.n_qp; ++q) {
        if constexpr (DIM == 2) {
          if (axis) {
            Eigen::Matrix<double, 4, ND> b;
            const double w = kernels::axis_point<NN>(re, q, x, mesh, cell, sign, g, b);
            ke += w * b.transpose() * elasticity_axis(kBehaviourMat) * b;
            continue;
          }
        }
        Eigen::Matrix<double, kernels::kVoigt<DIM>, ND> b;
        const double det = kernels::physical_gradients<NN, DIM>(re, q, x, g);
        kernels::strain_matrix<NN, DIM>(g, b);
        ke += std::abs(det) * re.weight[q] * b.transpose() * hooke<DIM>(model.modelisation[cell]) * b;
      }
      const int* nodes = mesh.cell(cell);
      for (int i = 0; i < ND; ++i)
        for (int j = 0; j < ND; ++j) t.emplace_back(dofs.dof(nodes[i / DIM], i % DIM), dofs.dof(nodes[j / DIM], j % DIM), ke(i, j));
    });
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

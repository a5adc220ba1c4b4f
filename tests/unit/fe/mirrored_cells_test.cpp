// Cells listed as the mirror image of a valid cell (clockwise 2D cells, 3D cells
// in a mirrored node order): orient_cells reorients them, and the reoriented
// block has the same isoparametric volume and the same stiffness as the block
// meshed in MED order, for every element type with shape functions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/mesh/orientation.hpp"
#include "fe_test_util.hpp"
#include "tests/unit/mesh/test_helpers.hpp"

namespace lunaster::engine {
namespace {

using test::BlockBuilder;
using test::type_name;

/// Signed isoparametric measure of a cell: sum over the full-integration
/// points of w det(dx/dxi) (negative for a cell listed in mirrored order).
double signed_measure(const Mesh& mesh, int cell) {
  const ReferenceElement& re = reference_element(mesh.cell_types[cell]);
  const int nn = re.n_nodes, rd = re.dim;
  double total = 0.0;
  for (int q = 0; q < re.n_qp; ++q) {
    double j[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (int a = 0; a < nn; ++a) {
      const double* x = mesh.node(mesh.cell(cell)[a]);
      for (int i = 0; i < rd; ++i)
        for (int k = 0; k < rd; ++k) j[i][k] += x[i] * re.dn[(static_cast<size_t>(q) * nn + a) * rd + k];
    }
    const double det = rd == 2 ? j[0][0] * j[1][1] - j[0][1] * j[1][0]
                               : j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
                                     j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
                                     j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
    total += re.weight[q] * det;
  }
  return total;
}

/// Largest |K_a(n,c; m,d) - K_b(n,c; m,d)| over node/component pairs, with the
/// equations of each matrix found through its own DofMap.
double stiffness_difference(const Mesh& mesh, const SparseMatrix& ka, const DofMap& da, const SparseMatrix& kb,
                            const DofMap& db, int dim) {
  const Eigen::MatrixXd a(ka), b(kb);
  double worst = 0.0;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    for (int m = 0; m < mesh.n_nodes(); ++m)
      for (int c = 0; c < dim; ++c)
        for (int d = 0; d < dim; ++d) {
          const int ia = da.dof(n, c), ja = da.dof(m, d), ib = db.dof(n, c), jb = db.dof(m, d);
          EXPECT_EQ(ia < 0, ib < 0);
          if (ia < 0 || ja < 0 || ib < 0 || jb < 0) continue;
          worst = std::max(worst, std::abs(a(ia, ja) - b(ib, jb)));
        }
  return worst;
}

TEST(MirroredCells, ReorientedBlockHasTheSameVolumeAndStiffness) {
  const ElasticMaterial mat{1000.0, 0.3, 0.0};
  for (CellType type : test::volume_types()) {
    const std::string name = type_name(type);
    BlockBuilder block(type, 2, 0.4);
    const std::vector<int> cells = block.fill();
    const int dim = block.dim();
    const Mesh reference = block.mesh();
    const Modelisation mod = dim == 2 ? Modelisation::PlaneStrain : Modelisation::Solid3D;
    const FeModel model_ref = test::make_model(reference, dim, mod, mat);
    const DofMap dofs_ref(reference, model_ref.volume_cells(), dim);
    const SparseMatrix k_ref = test::assemble_matrix(model_ref, dofs_ref);
    const double k_scale = Eigen::MatrixXd(k_ref).cwiseAbs().maxCoeff();

    // Every cell listed as its mirror image (a hand-written reflection, not the
    // permutation orient_cells applies), as a careless exporter would write it.
    Mesh mesh = reference;
    for (int c : cells) engine::testing::permute_cell(mesh, c, engine::testing::hand_written_reflection(type));
    ASSERT_EQ(find_inverted_cells(mesh), cells) << name;
    for (int c : cells) ASSERT_NEAR(signed_measure(mesh, c), -signed_measure(reference, c), 1e-14) << name;

    EXPECT_EQ(orient_cells(mesh, "block.med"), cells) << name;
    EXPECT_TRUE(find_inverted_cells(mesh).empty()) << name;
    double volume = 0.0;
    for (int c : cells) {
      const double v = signed_measure(mesh, c);
      EXPECT_GT(v, 0.0) << name;
      EXPECT_NEAR(v, signed_measure(reference, c), 1e-14) << name;
      EXPECT_LT(engine::testing::mid_side_offset(mesh, c), 1e-15) << name;
      volume += v;
    }
    EXPECT_NEAR(volume, 1.0, 1e-13) << name << ": the block is the unit square / cube";

    const FeModel model = test::make_model(mesh, dim, mod, mat);
    const DofMap dofs(mesh, model.volume_cells(), dim);
    const SparseMatrix k = test::assemble_matrix(model, dofs);
    EXPECT_LE(stiffness_difference(mesh, k_ref, dofs_ref, k, dofs, dim), 1e-12 * k_scale) << name;
  }
}

}  // namespace
}  // namespace lunaster::engine

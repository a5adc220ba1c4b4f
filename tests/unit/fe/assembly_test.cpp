// Assembly straight into the compressed pattern against the triplet assembly: the same
// pattern and the same values, bit for bit, for every volume type, a mixed mesh, a node
// numbering unrelated to the cells, multiplier unknowns without stiffness, and the same
// error as a single pass in cell order for a tangled cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "engine/assembly/assembly.hpp"
#include "engine/core/error.hpp"
#include "fe_test_util.hpp"

namespace lunaster::engine {
namespace {

using test::BlockBuilder;
using test::type_name;

const ElasticMaterial kMat{2.0e6, 0.3, 0.0};

/// The compressed matrix must be exactly the triplets' setFromTriplets.
void expect_same_matrix(const FeModel& model, const DofMap& dofs, const std::string& what) {
  const SparseMatrix ref = test::assemble_matrix(model, dofs);
  const SparseMatrix k = assemble_stiffness_matrix(model, dofs);
  ASSERT_TRUE(k.isCompressed()) << what;
  ASSERT_EQ(k.rows(), ref.rows()) << what;
  ASSERT_EQ(k.cols(), ref.cols()) << what;
  ASSERT_EQ(k.nonZeros(), ref.nonZeros()) << what;
  EXPECT_TRUE(std::equal(k.outerIndexPtr(), k.outerIndexPtr() + k.cols() + 1, ref.outerIndexPtr())) << what;
  EXPECT_TRUE(std::equal(k.innerIndexPtr(), k.innerIndexPtr() + k.nonZeros(), ref.innerIndexPtr())) << what;
  long differ = 0;
  for (Eigen::Index p = 0; p < k.nonZeros(); ++p) differ += k.valuePtr()[p] != ref.valuePtr()[p];
  EXPECT_EQ(differ, 0) << what << ": entries whose value differs from the triplet assembly";
  EXPECT_GT(ref.nonZeros(), 0) << what;
}

TEST(CompressedAssembly, EqualsTheTripletAssemblyForEveryVolumeType) {
  for (CellType type : test::volume_types()) {
    BlockBuilder block(type, cell_dim(type) == 2 ? 7 : 3, 0.25);
    block.fill();
    const int dim = block.dim();
    const FeModel model = test::make_model(block.mesh(), dim,
                                           dim == 2 ? Modelisation::PlaneStrain : Modelisation::Solid3D, kMat);
    const DofMap dofs(block.mesh(), model.volume_cells(), dim);
    expect_same_matrix(model, dofs, type_name(type));
  }
}

TEST(CompressedAssembly, MixedCellsShuffledNodesAndMultipliers) {
  // QUAD4 and QUAD8 cells with TRIA3/TRIA6 cells on top of them (assembly does not need a
  // conforming mesh), then the nodes renumbered at random: the coupled nodes of a node are
  // no longer in cell order, and the two workers' column ranges cut through many cells.
  BlockBuilder block(CellType::Quad4, 8, 0.2);
  block.fill();
  block.add_cell(CellType::Quad8, {block.vertex(0, 0), block.vertex(2, 0), block.vertex(2, 2), block.vertex(0, 2)});
  block.add_cell(CellType::Tria3, {block.vertex(3, 3), block.vertex(5, 3), block.vertex(5, 6)});
  block.add_cell(CellType::Tria6, {block.vertex(8, 0), block.vertex(8, 8), block.vertex(0, 8)});
  Mesh mesh = block.mesh();
  std::vector<int> perm(mesh.n_nodes());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937(42));
  Mesh shuffled = mesh;
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    std::copy(mesh.coords.begin() + 3 * v, mesh.coords.begin() + 3 * v + 3, shuffled.coords.begin() + 3 * perm[v]);
    shuffled.node_names[perm[v]] = mesh.node_names[v];
  }
  for (int& v : shuffled.cell_nodes) v = perm[v];
  for (const Mesh* m : {&mesh, &shuffled}) {
    const FeModel model = test::make_model(*m, 2, Modelisation::PlaneStrain, kMat);
    DofMap dofs(*m, model.volume_cells(), 2);
    expect_same_matrix(model, dofs, m == &mesh ? "mixed" : "mixed, shuffled nodes");
    // Multipliers on some nodes: numbered after the displacements, empty columns.
    for (int v = 0; v < m->n_nodes(); v += 5) dofs.add(v, LAGS_C);
    expect_same_matrix(model, dofs, m == &mesh ? "mixed, with LAGS_C" : "mixed, shuffled nodes, with LAGS_C");
  }
}

TEST(CompressedAssembly, OwnedNodesGetTheirWholeColumnsAndTheSharesSumToK) {
  // A model shared among MPI ranks: each rank's matrix holds the columns of its own nodes,
  // complete (cells shared with another rank included), bit for bit those of K.
  for (CellType type : test::volume_types()) {
    BlockBuilder block(type, cell_dim(type) == 2 ? 6 : 3, 0.25);
    block.fill();
    const int dim = block.dim();
    const FeModel model = test::make_model(block.mesh(), dim,
                                           dim == 2 ? Modelisation::PlaneStrain : Modelisation::Solid3D, kMat);
    const DofMap dofs(block.mesh(), model.volume_cells(), dim);
    const SparseMatrix k = assemble_stiffness_matrix(model, dofs);
    constexpr int kParts = 3;
    std::mt19937 random(7);
    std::vector<int> owner(block.mesh().n_nodes());
    for (int& o : owner) o = static_cast<int>(random() % kParts);
    SparseMatrix sum(k.rows(), k.cols());
    for (int part = 0; part < kParts; ++part) {
      std::vector<char> owned(owner.size());
      for (size_t v = 0; v < owner.size(); ++v) owned[v] = owner[v] == part;
      const SparseMatrix share = assemble_stiffness_matrix(model, dofs, &owned);
      long wrong = 0;
      for (int eq = 0; eq < k.cols(); ++eq) {
        const bool mine = owned[dofs.node_of(eq)];
        const int n_share = share.outerIndexPtr()[eq + 1] - share.outerIndexPtr()[eq];
        const int n_k = k.outerIndexPtr()[eq + 1] - k.outerIndexPtr()[eq];
        if (!mine) {
          wrong += n_share != 0;
          continue;
        }
        if (n_share != n_k) {
          ++wrong;
          continue;
        }
        for (int p = 0; p < n_k; ++p)
          wrong += share.innerIndexPtr()[share.outerIndexPtr()[eq] + p] != k.innerIndexPtr()[k.outerIndexPtr()[eq] + p] ||
                   share.valuePtr()[share.outerIndexPtr()[eq] + p] != k.valuePtr()[k.outerIndexPtr()[eq] + p];
      }
      EXPECT_EQ(wrong, 0) << type_name(type) << ", part " << part << ": columns that are not K's (or not empty)";
      sum += share;
    }
    EXPECT_EQ((SparseMatrix(sum - k)).norm(), 0.0) << type_name(type) << ": the shares do not sum to K";
  }
}

TEST(CompressedAssembly, TangledCellRaisesTheErrorOfTheFirstBadCell) {
  // Two tangled cells, one in each worker's columns: the error names the first in cell
  // order, as a single pass would.
  BlockBuilder block(CellType::Quad4, 10, 0.0);
  const std::vector<int> cells = block.fill();
  Mesh& mesh = block.mesh();
  const int first = cells[12], last = cells[cells.size() - 3];
  for (int c : {first, last}) {  // swap two vertices: a bow-tie cell
    int* nodes = &mesh.cell_nodes[mesh.cell_offsets[c]];
    std::swap(nodes[1], nodes[2]);
  }
  const FeModel model = test::make_model(mesh, 2, Modelisation::PlaneStrain, kMat);
  const DofMap dofs(mesh, model.volume_cells(), 2);
  const std::string expected = "cell " + mesh.cell_names[first] + ": degenerate or tangled cell";
  std::vector<Triplet> t;
  try {
    assemble_stiffness(model, dofs, t);
    FAIL() << "the triplet assembly accepted a tangled cell";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
  try {
    (void)assemble_stiffness_matrix(model, dofs);
    FAIL() << "the compressed assembly accepted a tangled cell";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lunaster::engine

// A mesh distributed among the ranks (MeshPart) and the exchanges of its node vectors
// (NodeHalo), run on 1, 2 and 3 ranks (CTest mpi.mesh_part_np*). Every rank builds the whole
// mesh itself to check its part against it; distribute_mesh gets it on rank 0 only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "engine/assembly/assembly.hpp"
#include "engine/assembly/global_dofs.hpp"
#include "engine/assembly/halo.hpp"
#include "engine/assembly/mesh_part.hpp"
#include "engine/assembly/part_fields.hpp"
#include "engine/assembly/stress.hpp"
#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/nonlinear/nodal_forces.hpp"
#include "engine/nonlinear/relations_hook.hpp"
#include "engine/nonlinear/static_solver.hpp"
#include "engine/parallel/mpi_runtime.hpp"
#include "engine/solver/backends.hpp"

#include <Eigen/SparseCholesky>
#include "tools/ssnp121_mesh.hpp"

namespace lunaster::engine {
namespace {

struct Scene {
  std::string name;
  Mesh whole;
};

std::vector<Scene> scenes() {
  std::vector<Scene> out;
  tools::BlockOptions block;
  block.cells = {CellType::Hexa8, {5, 4, 3}};
  out.push_back({"hexa8 block", tools::make_block(block)});
  tools::Ssnp121Options3d three;  // HEXA20 over HEXA8, their own interface nodes, faces and node groups
  three.v1 = {CellType::Hexa20, {3, 3, 3}};
  three.v2 = {CellType::Hexa8, {4, 4, 4}};
  out.push_back({"ssnp121 3D", tools::make_ssnp121_3d(three)});
  out.push_back({"ssnp121 2D", tools::make_ssnp121_2d({})});
  return out;
}

MeshPart part_of(const Mesh& whole) { return distribute_mesh(parallel::rank() == 0 ? &whole : nullptr); }

/// Per global node: how many ranks hold it (owned or ghost).
std::vector<int> holders(const MeshPart& part) {
  std::vector<int> count(part.n_global_nodes, 0);
  for (int g : parallel::gather_all(part.global_node)) ++count[g];
  return count;
}

TEST(MeshPart, IsTheWholeMeshRestrictedToItsCells) {
  for (const Scene& scene : scenes()) {
    SCOPED_TRACE(scene.name);
    const Mesh& whole = scene.whole;
    const MeshPart part = part_of(whole);
    const Mesh& mesh = part.mesh;
    EXPECT_EQ(part.parts, parallel::size());
    EXPECT_EQ(part.rank, parallel::rank());
    EXPECT_EQ(part.n_global_nodes, whole.n_nodes());
    EXPECT_EQ(part.n_global_cells, whole.n_cells());
    EXPECT_EQ(mesh.dim, whole.dim);
    ASSERT_EQ(mesh.n_nodes(), static_cast<int>(part.global_node.size()));
    ASSERT_EQ(mesh.n_cells(), static_cast<int>(part.global_cell.size()));
    // Owned nodes first, then the ghosts, each in the whole mesh's order.
    for (int i = 0; i < mesh.n_nodes(); ++i) {
      EXPECT_EQ(part.node_owner[i] == part.rank, i < part.n_owned_nodes) << "local node " << i;
      if (i + 1 != part.n_owned_nodes && i + 1 < mesh.n_nodes()) {
        EXPECT_LT(part.global_node[i], part.global_node[i + 1]);
      }
      const int g = part.global_node[i];
      EXPECT_EQ(mesh.node_names[i], whole.node_names[g]);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh.node(i)[k], whole.node(g)[k]);
    }
    for (int c = 0; c < mesh.n_cells(); ++c) {
      const int g = part.global_cell[c];
      if (c > 0) {
        EXPECT_LT(part.global_cell[c - 1], g);
      }
      EXPECT_EQ(mesh.cell_types[c], whole.cell_types[g]);
      EXPECT_EQ(mesh.cell_names[c], whole.cell_names[g]);
      ASSERT_EQ(mesh.cell_n_nodes(c), whole.cell_n_nodes(g));
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a) EXPECT_EQ(part.global_node[mesh.cell(c)[a]], whole.cell(g)[a]);
      EXPECT_EQ(part.cell_part[c] >= 0, cell_info(mesh.cell_types[c]).dim == whole.dim);
    }
    // Every group, restricted to the part.
    std::vector<int> local(whole.n_nodes(), -1), local_cell(whole.n_cells(), -1);
    for (int i = 0; i < mesh.n_nodes(); ++i) local[part.global_node[i]] = i;
    for (int c = 0; c < mesh.n_cells(); ++c) local_cell[part.global_cell[c]] = c;
    ASSERT_EQ(mesh.node_groups.size(), whole.node_groups.size());
    for (const auto& [name, members] : whole.node_groups) {
      std::vector<int> expected;
      for (int v : members)
        if (local[v] >= 0) expected.push_back(local[v]);
      std::sort(expected.begin(), expected.end());
      ASSERT_TRUE(mesh.node_groups.count(name)) << name;
      EXPECT_EQ(mesh.node_groups.at(name), expected) << name;
    }
    ASSERT_EQ(mesh.cell_groups.size(), whole.cell_groups.size());
    for (const auto& [name, members] : whole.cell_groups) {
      std::vector<int> expected;
      for (int c : members)
        if (local_cell[c] >= 0) expected.push_back(local_cell[c]);
      ASSERT_TRUE(mesh.cell_groups.count(name)) << name;
      EXPECT_EQ(mesh.cell_groups.at(name), expected) << name;
    }
    // Every cell touching an owned node is here (the rows of the owned nodes are complete).
    std::vector<int> all(whole.n_cells());
    for (int c = 0; c < whole.n_cells(); ++c) all[c] = c;
    const Mesh::NodeCells around = whole.node_cells(all);
    for (int i = 0; i < part.n_owned_nodes; ++i) {
      const int g = part.global_node[i];
      for (int p = around.start[g]; p < around.start[g + 1]; ++p)
        EXPECT_GE(local_cell[around.positions[p]], 0) << "a cell around owned node " << g;
    }
  }
}

TEST(MeshPart, EveryNodeAndVolumeCellHasOneRank) {
  for (const Scene& scene : scenes()) {
    SCOPED_TRACE(scene.name);
    const Mesh& whole = scene.whole;
    const MeshPart part = part_of(whole);
    std::vector<int> owned(part.global_node.begin(), part.global_node.begin() + part.n_owned_nodes), own_cells;
    for (int c = 0; c < part.mesh.n_cells(); ++c)
      if (part.cell_part[c] == part.rank) own_cells.push_back(part.global_cell[c]);
    std::vector<int> nodes = parallel::gather_all(owned), cells = parallel::gather_all(own_cells);
    std::sort(nodes.begin(), nodes.end());
    std::sort(cells.begin(), cells.end());
    std::vector<int> every_node(whole.n_nodes()), volume;
    for (int v = 0; v < whole.n_nodes(); ++v) every_node[v] = v;
    for (int c = 0; c < whole.n_cells(); ++c)
      if (cell_info(whole.cell_types[c]).dim == whole.dim) volume.push_back(c);
    EXPECT_EQ(nodes, every_node);
    EXPECT_EQ(cells, volume);
    // The cut is partition_cells' on the volume cells: more than one rank gets cells.
    if (parallel::size() > 1) {
      std::vector<int> counts = parallel::gather_all(std::vector<int>{static_cast<int>(own_cells.size())});
      EXPECT_EQ(std::count(counts.begin(), counts.end(), 0), 0);
    }
  }
}

TEST(SurfacePart, EveryRankHoldsTheWholeSurfacesBesideItsPart) {
  for (const Scene& scene : scenes()) {
    const Mesh& whole = scene.whole;
    // Every group of boundary cells of the whole mesh, as contact zones name them.
    std::vector<std::string> names;
    for (const auto& [name, cells] : whole.cell_groups)
      if (!cells.empty() && std::all_of(cells.begin(), cells.end(), [&](int c) {
            return cell_info(whole.cell_types[c]).dim == whole.dim - 1;
          }))
        names.push_back(name);
    ASSERT_GE(names.size(), 2u) << scene.name;
    const MeshPart part = part_of(whole);
    std::vector<std::vector<int>> lists;
    for (const std::string& name : names) lists.push_back(part.mesh.cell_groups.at(name));
    for (const bool layer : {false, true}) {
      // Layered: the first list brings every volume cell around its nodes (mortar's slave side).
      const std::vector<char> layered = {static_cast<char>(layer)};
      const SurfacePart s = with_whole_surfaces(part, lists, layered);
      const Mesh& m = s.part.mesh;
      // The part's nodes keep their numbers, owners and coordinates; the others follow.
      ASSERT_GE(m.n_nodes(), part.mesh.n_nodes()) << scene.name;
      EXPECT_EQ(s.part.n_owned_nodes, part.n_owned_nodes);
      for (int v = 0; v < part.mesh.n_nodes(); ++v) {
        EXPECT_EQ(s.part.global_node[v], part.global_node[v]);
        EXPECT_EQ(s.part.node_owner[v], part.node_owner[v]);
      }
      // Every node where the whole mesh has it, owned by the rank owning it there.
      std::map<int, int> owner;
      const std::vector<int> owned(part.global_node.begin(), part.global_node.begin() + part.n_owned_nodes);
      const std::vector<int> counts = parallel::gather_all(std::vector<int>{part.n_owned_nodes});
      const std::vector<int> all_owned = parallel::gather_all(owned);
      for (int r = 0, at = 0; r < static_cast<int>(counts.size()); at += counts[r++])
        for (int k = 0; k < counts[r]; ++k) owner[all_owned[at + k]] = r;
      for (int v = 0; v < m.n_nodes(); ++v) {
        const int g = s.part.global_node[v];
        for (int i = 0; i < 3; ++i) EXPECT_EQ(m.node(v)[i], whole.node(g)[i]) << scene.name << " node " << g;
        EXPECT_EQ(s.part.node_owner[v], owner.at(g)) << scene.name << " node " << g;
        EXPECT_EQ(v < part.n_owned_nodes, owner.at(g) == parallel::rank());
      }
      // Every cell is the whole mesh's, in its order.
      for (int c = 0; c < m.n_cells(); ++c) {
        const int g = s.part.global_cell[c];
        if (c > 0) {
          EXPECT_LT(s.part.global_cell[c - 1], g);
        }
        ASSERT_EQ(m.cell_types[c], whole.cell_types[g]);
        ASSERT_EQ(m.cell_n_nodes(c), whole.cell_n_nodes(g));
        for (int a = 0; a < m.cell_n_nodes(c); ++a) EXPECT_EQ(s.part.global_node[m.cell(c)[a]], whole.cell(g)[a]);
        EXPECT_EQ(m.cell_names[c], whole.cell_names[g]);
      }
      // Each list is its whole group, and each of its cells comes with the volume cells bounded by it.
      std::vector<int> volumes_expected;
      for (size_t i = 0; i < names.size(); ++i) {
        std::vector<int> globals;
        for (int c : s.lists[i]) globals.push_back(s.part.global_cell[c]);
        EXPECT_EQ(globals, whole.cell_groups.at(names[i])) << scene.name << " " << names[i];
        for (int f : whole.cell_groups.at(names[i]))
          for (int c = 0; c < whole.n_cells(); ++c) {
            if (cell_info(whole.cell_types[c]).dim != whole.dim) continue;
            const int* cn = whole.cell(c);
            bool all = true;
            for (int a = 0; a < whole.cell_n_nodes(f) && all; ++a)
              all = std::find(cn, cn + whole.cell_n_nodes(c), whole.cell(f)[a]) != cn + whole.cell_n_nodes(c);
            if (all) volumes_expected.push_back(c);
          }
      }
      if (layer) {
        std::vector<char> around(whole.n_nodes(), 0);
        for (int f : whole.cell_groups.at(names[0]))
          for (int a = 0; a < whole.cell_n_nodes(f); ++a) around[whole.cell(f)[a]] = 1;
        for (int c = 0; c < whole.n_cells(); ++c) {
          if (cell_info(whole.cell_types[c]).dim != whole.dim) continue;
          for (int a = 0; a < whole.cell_n_nodes(c); ++a)
            if (around[whole.cell(c)[a]]) {
              volumes_expected.push_back(c);
              break;
            }
        }
      }
      std::sort(volumes_expected.begin(), volumes_expected.end());
      volumes_expected.erase(std::unique(volumes_expected.begin(), volumes_expected.end()), volumes_expected.end());
      std::vector<int> volumes;
      for (int c = 0; c < m.n_cells(); ++c)
        if (cell_info(m.cell_types[c]).dim == whole.dim) volumes.push_back(s.part.global_cell[c]);
      EXPECT_EQ(volumes, volumes_expected) << scene.name << (layer ? ", layered" : "");
    }
  }
}

TEST(GhostNodes, EveryRankHoldsTheListedNodesAndWithAroundTheirNeighbours) {
  for (const Scene& scene : scenes()) {
    const Mesh& whole = scene.whole;
    const MeshPart part = part_of(whole);
    // Nodes spread over the whole mesh (a relation's, every rank passing the same list).
    std::vector<int> listed;
    for (int g = 0; g < whole.n_nodes(); g += 7) listed.push_back(g);
    listed.push_back(whole.n_nodes() - 1);
    for (const bool around : {false, true}) {
      MeshPart numbered = nodes_only(part);
      EXPECT_EQ(numbered.mesh.n_cells(), 0) << scene.name;
      add_ghost_nodes(numbered, listed, around ? &part : nullptr);
      const Mesh& m = numbered.mesh;
      // The part's nodes keep their numbers; the others follow once each, in the whole mesh's order.
      ASSERT_GE(m.n_nodes(), part.mesh.n_nodes());
      EXPECT_EQ(numbered.n_owned_nodes, part.n_owned_nodes);
      for (int v = 0; v < part.mesh.n_nodes(); ++v) EXPECT_EQ(numbered.global_node[v], part.global_node[v]);
      for (int v = part.mesh.n_nodes() + 1; v < m.n_nodes(); ++v)
        EXPECT_LT(numbered.global_node[v - 1], numbered.global_node[v]) << scene.name;
      // Each node where the whole mesh has it, named as there, owned by the rank whose part owns it.
      const std::vector<int> counts = parallel::gather_all(std::vector<int>{part.n_owned_nodes});
      const std::vector<int> owned(part.global_node.begin(), part.global_node.begin() + part.n_owned_nodes);
      const std::vector<int> all_owned = parallel::gather_all(owned);
      std::map<int, int> owner;
      for (int r = 0, at = 0; r < static_cast<int>(counts.size()); at += counts[r++])
        for (int k = 0; k < counts[r]; ++k) owner[all_owned[at + k]] = r;
      std::vector<int> held;
      for (int v = 0; v < m.n_nodes(); ++v) {
        const int g = numbered.global_node[v];
        held.push_back(g);
        for (int i = 0; i < 3; ++i) EXPECT_EQ(m.node(v)[i], whole.node(g)[i]) << scene.name << " node " << g;
        EXPECT_EQ(m.node_names[v], whole.node_names[g]);
        EXPECT_EQ(numbered.node_owner[v], owner.at(g)) << scene.name << " node " << g;
      }
      std::sort(held.begin(), held.end());
      // What must be held: the part's nodes, the listed ones and, around, every node of a volume
      // cell holding a listed node; nothing else is added.
      std::vector<char> expected(whole.n_nodes(), 0);
      for (int g : part.global_node) expected[g] = 1;
      for (int g : listed) expected[g] = 1;
      if (around)
        for (int c = 0; c < whole.n_cells(); ++c) {
          if (cell_info(whole.cell_types[c]).dim != whole.dim) continue;
          const int* cn = whole.cell(c);
          const int nn = whole.cell_n_nodes(c);
          if (std::any_of(cn, cn + nn, [&](int g) { return std::binary_search(listed.begin(), listed.end(), g); }))
            for (int a = 0; a < nn; ++a) expected[cn[a]] = 1;
        }
      std::vector<int> expected_list;
      for (int g = 0; g < whole.n_nodes(); ++g)
        if (expected[g]) expected_list.push_back(g);
      EXPECT_EQ(held, expected_list) << scene.name << (around ? ", around" : "");
    }
  }
}

TEST(NodeHalo, GhostsGetTheirOwnersValues) {
  for (const Scene& scene : scenes()) {
    SCOPED_TRACE(scene.name);
    const MeshPart part = part_of(scene.whole);
    const NodeHalo halo(part);
    const int block = 3;
    std::vector<double> v(part.global_node.size() * block, -1.0);
    for (int i = 0; i < part.n_owned_nodes; ++i)
      for (int b = 0; b < block; ++b) v[i * block + b] = 10.0 * part.global_node[i] + b;
    halo.copy_to_ghosts(v, block);
    for (size_t i = 0; i < part.global_node.size(); ++i)
      for (int b = 0; b < block; ++b) EXPECT_EQ(v[i * block + b], 10.0 * part.global_node[i] + b) << "node " << i;
    EXPECT_EQ(halo.neighbours().empty(), parallel::size() == 1);
  }
}

TEST(NodeHalo, OwnersGetTheSumOfEveryRanksValues) {
  for (const Scene& scene : scenes()) {
    SCOPED_TRACE(scene.name);
    const MeshPart part = part_of(scene.whole);
    const NodeHalo halo(part);
    const std::vector<int> count = holders(part);
    std::vector<double> v(part.global_node.size(), 1.0);
    halo.add_to_owners(v, 1);
    for (int i = 0; i < part.n_owned_nodes; ++i) EXPECT_EQ(v[i], count[part.global_node[i]]) << "node " << i;
  }
}

/// A vector assembled cell by cell: each volume cell adds its measure-like weight (its number
/// plus one, over its node count) to each of its nodes, in component 0, and its position in
/// component 1.
void add_cell(const Mesh& mesh, int c, int global_c, std::vector<double>& v) {
  const int nn = mesh.cell_n_nodes(c);
  for (int a = 0; a < nn; ++a) {
    const int i = mesh.cell(c)[a];
    v[2 * i] += (global_c + 1.0) / nn;
    v[2 * i + 1] += mesh.node(i)[0] * (global_c % 7);
  }
}

TEST(NodeHalo, AssemblyOfOwnCellsIsTheWholeOnes) {
  for (const Scene& scene : scenes()) {
    SCOPED_TRACE(scene.name);
    const Mesh& whole = scene.whole;
    const MeshPart part = part_of(whole);
    std::vector<double> serial(2 * static_cast<size_t>(whole.n_nodes()), 0.0);
    for (int c = 0; c < whole.n_cells(); ++c)
      if (cell_info(whole.cell_types[c]).dim == whole.dim) add_cell(whole, c, c, serial);
    // Own cells, then the ghosts' contributions summed into their owners, then copied back.
    const NodeHalo halo(part);
    std::vector<double> own(2 * part.global_node.size(), 0.0), layer(own.size(), 0.0);
    for (int c = 0; c < part.mesh.n_cells(); ++c) {
      if (part.cell_part[c] == part.rank) add_cell(part.mesh, c, part.global_cell[c], own);
      if (part.cell_part[c] >= 0) add_cell(part.mesh, c, part.global_cell[c], layer);
    }
    halo.add_to_owners(own, 2);
    halo.copy_to_ghosts(own, 2);
    for (size_t i = 0; i < part.global_node.size(); ++i)
      for (int b = 0; b < 2; ++b) {
        const double expected = serial[2 * part.global_node[i] + b];
        EXPECT_NEAR(own[2 * i + b], expected, 1e-12 * std::max(1.0, std::abs(expected))) << "node " << i;
        // Without any exchange, own and ghost cells together give the owned nodes' whole value.
        if (static_cast<int>(i) < part.n_owned_nodes) {
          EXPECT_NEAR(layer[2 * i + b], expected, 1e-12 * std::max(1.0, std::abs(expected))) << "node " << i;
        }
      }
  }
}

/// A value of (global entry, component).
double field_value(int global, int k) { return 0.5 * global - 3.0 * k + 1.0; }

TEST(PartFields, NodeAndCellFieldsComeBackWholeOnRankZero) {
  for (const Scene& scene : scenes()) {
    SCOPED_TRACE(scene.name);
    const MeshPart part = part_of(scene.whole);
    const int block = 2;
    // Ghosts hold something else than their owners: what rank 0 gets must be the owners'.
    std::vector<double> nodes(part.global_node.size() * block), cells(part.global_cell.size() * block);
    for (size_t i = 0; i < part.global_node.size(); ++i)
      for (int k = 0; k < block; ++k)
        nodes[i * block + k] = part.owns(static_cast<int>(i)) ? field_value(part.global_node[i], k) : -7.0;
    for (size_t c = 0; c < part.global_cell.size(); ++c)
      for (int k = 0; k < block; ++k)
        cells[c * block + k] = cell_giver(part, static_cast<int>(c)) == part.rank ? field_value(part.global_cell[c], k) : -7.0;
    const std::vector<double> whole_nodes = gather_nodes_to_root(part, nodes, block);
    const std::vector<double> whole_cells = gather_cells_to_root(part, cells, block);
    if (parallel::rank() != 0) {
      EXPECT_TRUE(whole_nodes.empty());
      EXPECT_TRUE(whole_cells.empty());
      continue;
    }
    ASSERT_EQ(whole_nodes.size(), static_cast<size_t>(scene.whole.n_nodes()) * block);
    ASSERT_EQ(whole_cells.size(), static_cast<size_t>(scene.whole.n_cells()) * block);
    for (int v = 0; v < scene.whole.n_nodes(); ++v)
      for (int k = 0; k < block; ++k) EXPECT_EQ(whole_nodes[v * block + k], field_value(v, k)) << "node " << v;
    for (int c = 0; c < scene.whole.n_cells(); ++c)
      for (int k = 0; k < block; ++k) EXPECT_EQ(whole_cells[c * block + k], field_value(c, k)) << "cell " << c;
  }
}

TEST(PartFields, ANodesValuesReachEveryRankFromItsOwner) {
  for (const Scene& scene : scenes()) {
    SCOPED_TRACE(scene.name);
    const MeshPart part = part_of(scene.whole);
    std::vector<double> nodes(part.global_node.size() * 3, -7.0);
    for (int i = 0; i < part.n_owned_nodes; ++i)
      for (int k = 0; k < 3; ++k) nodes[i * 3 + k] = field_value(part.global_node[i], k);
    for (int g : {0, scene.whole.n_nodes() / 2, scene.whole.n_nodes() - 1}) {
      const std::vector<double> got = node_values_everywhere(part, nodes, 3, g);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(got[k], field_value(g, k)) << "node " << g;
    }
  }
}

/// An elastic model of every volume cell of `mesh` (3D solid, or plane strain in 2D).
FeModel elastic_model(const Mesh& mesh) {
  FeModel model;
  model.mesh = &mesh;
  model.dim = mesh.dim;
  model.materials = {{2.0e11, 0.3, 0.0}};
  model.modelisation.assign(mesh.n_cells(), Modelisation::None);
  model.material.assign(mesh.n_cells(), -1);
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (cell_info(mesh.cell_types[c]).dim == mesh.dim) {
      model.modelisation[c] = mesh.dim == 3 ? Modelisation::Solid3D : Modelisation::PlaneStrain;
      model.material[c] = 0;
    }
  return model;
}

/// A displacement that is no rigid motion: component k at x.
double displacement(const double* x, int k) { return 1e-3 * (x[0] * x[1] + (k + 1) * x[2] - 0.5 * k * x[0] * x[0]); }

/// The elastic model of a mesh, its unknowns, and displacement() at them.
struct Displaced {
  FeModel model;
  DofMap dofs;
  Vector u;
};

Displaced displaced(const Mesh& mesh) {
  Displaced out{elastic_model(mesh), {}, {}};
  out.dofs = DofMap(mesh, out.model.volume_cells(), out.model.dim);
  out.u.resize(out.dofs.n_dofs());
  for (int eq = 0; eq < out.dofs.n_dofs(); ++eq) out.u[eq] = displacement(mesh.node(out.dofs.node_of(eq)), out.dofs.component_of(eq));
  return out;
}

TEST(GlobalDofs, EveryUnknownHasOneNumberOnEveryRank) {
  for (const Scene& scene : scenes()) {
    SCOPED_TRACE(scene.name);
    const MeshPart part = part_of(scene.whole);
    const FeModel model = elastic_model(part.mesh);
    const DofMap dofs(part.mesh, model.volume_cells(), model.dim);
    const GlobalDofs numbers = number_across_ranks(part, dofs, NodeHalo(part));
    const FeModel whole_model = elastic_model(scene.whole);
    EXPECT_EQ(numbers.n_global, DofMap(scene.whole, whole_model.volume_cells(), whole_model.dim).n_dofs());
    // (global node, component, number) of every local unknown of every rank.
    std::vector<int> mine;
    for (int eq = 0; eq < dofs.n_dofs(); ++eq) {
      if (eq < numbers.n_owned) {
        EXPECT_EQ(numbers.global[eq], numbers.first + eq);
      }
      mine.insert(mine.end(), {part.global_node[dofs.node_of(eq)], dofs.component_of(eq),
                               static_cast<int>(numbers.global[eq])});
    }
    const std::vector<int> all = parallel::gather_all(mine);
    std::vector<long long> of_unknown(static_cast<size_t>(part.n_global_nodes) * N_COMPONENTS, -1);
    std::vector<int> unknown_of(numbers.n_global, -1);
    for (size_t k = 0; k < all.size(); k += 3) {
      const size_t unknown = static_cast<size_t>(all[k]) * N_COMPONENTS + all[k + 1];
      const int g = all[k + 2];
      ASSERT_TRUE(g >= 0 && g < numbers.n_global);
      if (of_unknown[unknown] < 0) of_unknown[unknown] = g;
      EXPECT_EQ(of_unknown[unknown], g) << "node " << all[k] << " component " << all[k + 1];
      if (unknown_of[g] < 0) unknown_of[g] = static_cast<int>(unknown);
      EXPECT_EQ(unknown_of[g], static_cast<int>(unknown)) << "number " << g;
    }
    EXPECT_EQ(std::count(unknown_of.begin(), unknown_of.end(), -1), 0);
  }
}

TEST(PartAssembly, StiffnessAndForcesOnPartsAreTheWholeModels) {
  for (const Scene& scene : scenes()) {
    SCOPED_TRACE(scene.name);
    // The whole model, on every rank: K u and the internal forces.
    const Displaced whole = displaced(scene.whole);
    const DofMap& whole_dofs = whole.dofs;
    const Vector ku_whole = assemble_stiffness_matrix(whole.model, whole_dofs) * whole.u;
    // The part: its owned columns (complete: the ghost layer), its own cells' forces.
    const MeshPart part = part_of(scene.whole);
    const Displaced local = displaced(part.mesh);
    const FeModel& model = local.model;
    const DofMap& dofs = local.dofs;
    const Vector& u = local.u;
    std::vector<char> owned(part.mesh.n_nodes(), 0);
    for (int i = 0; i < part.n_owned_nodes; ++i) owned[i] = 1;
    const SparseMatrix k = assemble_stiffness_matrix(model, dofs, &owned);
    const Vector ku = k.transpose() * u;  // K symmetric: an owned column is the owned row
    Vector f_int;
    assemble_internal_forces(model, dofs, u, f_int, &part.cell_part);
    const int block = model.dim;
    std::vector<double> forces(static_cast<size_t>(part.mesh.n_nodes()) * block, 0.0);
    for (int eq = 0; eq < dofs.n_dofs(); ++eq) forces[dofs.node_of(eq) * block + dofs.component_of(eq)] = f_int[eq];
    NodeHalo(part).add_to_owners(forces, block);
    const double scale = ku_whole.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 0.0);
    int compared = 0;
    for (int eq = 0; eq < dofs.n_dofs(); ++eq) {
      const int node = dofs.node_of(eq);
      if (!part.owns(node)) continue;
      const double expected = ku_whole[whole_dofs.dof(part.global_node[node], dofs.component_of(eq))];
      EXPECT_NEAR(ku[eq], expected, 1e-12 * scale) << "K u, equation " << eq;
      EXPECT_NEAR(forces[node * block + dofs.component_of(eq)], expected, 1e-12 * scale) << "f_int, equation " << eq;
      ++compared;
    }
    const std::vector<int> counts = parallel::gather_all(std::vector<int>{compared});
    int total = 0;
    for (int c : counts) total += c;
    EXPECT_EQ(total, whole_dofs.n_dofs());
  }
}

/// A boundary group of each scene: pressed faces (3D) or edges (2D).
std::string pressed_group(const Scene& scene) {
  return scene.name == "hexa8 block" ? "TOP" : scene.name == "ssnp121 3D" ? "SURCHA" : "CD";
}

TEST(PartAssembly, PressuresAndOwnedColumnsSumThroughTheEquationHalo) {
  for (const Scene& scene : scenes()) {
    SCOPED_TRACE(scene.name);
    const std::string group = pressed_group(scene);
    ASSERT_TRUE(scene.whole.cell_groups.count(group)) << group;
    const Displaced whole = displaced(scene.whole);
    const DofMap& whole_dofs = whole.dofs;
    const Vector ku_whole = assemble_stiffness_matrix(whole.model, whole_dofs) * whole.u;
    Vector pressure_whole = Vector::Zero(whole_dofs.n_dofs());
    assemble_pressure(scene.whole, whole.model.dim, scene.whole.cell_groups.at(group), 3.0e7, whole_dofs, pressure_whole);

    const MeshPart part = part_of(scene.whole);
    const Displaced local = displaced(part.mesh);
    const FeModel& model = local.model;
    const DofMap& dofs = local.dofs;
    const Vector& u = local.u;
    const GlobalDofs numbers = number_across_ranks(part, dofs, NodeHalo(part));
    const Halo halo = equation_halo(part, dofs, numbers);
    // The owned columns' contributions to every local row, summed into the owners.
    std::vector<char> owned(part.mesh.n_nodes(), 0);
    for (int i = 0; i < part.n_owned_nodes; ++i) owned[i] = 1;
    const Vector ku_columns = assemble_stiffness_matrix(model, dofs, &owned) * u;
    std::vector<double> ku(ku_columns.data(), ku_columns.data() + ku_columns.size());
    halo.add_to_owners(ku, 1);
    // The faces whose first node this rank owns, summed into the owners, then given to the ghosts.
    Vector pressure_local = Vector::Zero(dofs.n_dofs());
    assemble_pressure(part.mesh, model.dim, part.mesh.cell_groups.at(group), 3.0e7, dofs, pressure_local, false,
                      &part.node_owner);
    std::vector<double> pressure(pressure_local.data(), pressure_local.data() + pressure_local.size());
    halo.add_to_owners(pressure, 1);
    halo.copy_to_ghosts(pressure, 1);
    const double scale = ku_whole.cwiseAbs().maxCoeff(), force = pressure_whole.cwiseAbs().maxCoeff();
    ASSERT_GT(force, 0.0);
    for (int eq = 0; eq < dofs.n_dofs(); ++eq) {
      const int whole_eq = whole_dofs.dof(part.global_node[dofs.node_of(eq)], dofs.component_of(eq));
      EXPECT_NEAR(pressure[eq], pressure_whole[whole_eq], 1e-12 * force) << "pressure, equation " << eq;
      if (eq < numbers.n_owned) {
        EXPECT_NEAR(ku[eq], ku_whole[whole_eq], 1e-12 * scale) << "K u, equation " << eq;
      }
    }
  }
}

/// Blocks clamped on BOTTOM and pressed on TOP: 3D HEXA8, 3D HEXA20, plane strain QUAD8.
std::vector<Scene> clamped_blocks() {
  std::vector<Scene> out;
  tools::BlockOptions block;
  block.cells = {CellType::Hexa8, {4, 5, 3}};
  out.push_back({"hexa8 block", tools::make_block(block)});
  block.cells = {CellType::Hexa20, {2, 3, 2}};
  out.push_back({"hexa20 block", tools::make_block(block)});
  block.cells = {CellType::Quad8, {6, 5, 1}};
  out.push_back({"quad8 block", tools::make_block(block)});
  return out;
}

/// Per local equation: whether its node is on a cell of `group` (the part's own view: right for
/// the nodes it owns, whose every cell it holds).
std::vector<char> on_group(const Mesh& mesh, const DofMap& dofs, const std::string& group) {
  std::vector<char> node_on(mesh.n_nodes(), 0);
  for (int c : mesh.cell_groups.at(group))
    for (int a = 0; a < mesh.cell_n_nodes(c); ++a) node_on[mesh.cell(c)[a]] = 1;
  std::vector<char> out(dofs.n_dofs());
  for (int eq = 0; eq < dofs.n_dofs(); ++eq) out[eq] = node_on[dofs.node_of(eq)];
  return out;
}

/// K restricted to the equations kept (their order), and a vector likewise.
SparseMatrix restricted(const SparseMatrix& k, const std::vector<int>& index, int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < k.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(k, c); it; ++it)
      if (index[it.row()] >= 0 && index[c] >= 0) t.emplace_back(index[it.row()], index[c], it.value());
  SparseMatrix out(n, n);
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

TEST(PartSolve, MumpsSolvesASystemInPartsAsTheWholeOne) {
  for (const Scene& scene : clamped_blocks()) {
    SCOPED_TRACE(scene.name);
    const double pressure = 1.0e8;
    // The whole system, solved by a Cholesky factorisation on every rank.
    const FeModel whole_model = elastic_model(scene.whole);
    const DofMap whole_dofs(scene.whole, whole_model.volume_cells(), whole_model.dim);
    const std::vector<char> whole_fixed = on_group(scene.whole, whole_dofs, "BOTTOM");
    std::vector<int> whole_free(whole_dofs.n_dofs(), -1);
    int n_free = 0;
    for (int eq = 0; eq < whole_dofs.n_dofs(); ++eq)
      if (!whole_fixed[eq]) whole_free[eq] = n_free++;
    Vector f_whole = Vector::Zero(whole_dofs.n_dofs());
    assemble_pressure(scene.whole, whole_model.dim, scene.whole.cell_groups.at("TOP"), pressure, whole_dofs, f_whole);
    Vector b_whole(n_free);
    for (int eq = 0; eq < whole_dofs.n_dofs(); ++eq)
      if (whole_free[eq] >= 0) b_whole[whole_free[eq]] = f_whole[eq];
    const Eigen::SimplicialLDLT<SparseMatrix> whole_factor(
        restricted(assemble_stiffness_matrix(whole_model, whole_dofs), whole_free, n_free));
    ASSERT_EQ(whole_factor.info(), Eigen::Success);
    const Vector u_whole = whole_factor.solve(b_whole);

    // The parts: Dirichlet conditions decided by the owners, the free unknowns numbered across
    // the ranks, each rank's owned columns and owned right-hand side, MUMPS on the ranks.
    const MeshPart part = part_of(scene.whole);
    const FeModel model = elastic_model(part.mesh);
    const DofMap dofs(part.mesh, model.volume_cells(), model.dim);
    const NodeHalo node_halo(part);
    std::vector<char> free(dofs.n_dofs());
    const std::vector<char> fixed = on_group(part.mesh, dofs, "BOTTOM");
    for (int eq = 0; eq < dofs.n_dofs(); ++eq) free[eq] = !fixed[eq];
    const GlobalDofs numbers = number_across_ranks(part, dofs, node_halo, &free);
    EXPECT_EQ(numbers.n_global, n_free);
    // The system's local numbering: the numbered (free) local equations in their order, the
    // owned ones first.
    std::vector<int> local_free(dofs.n_dofs(), -1);
    SystemLayout layout;
    for (int eq = 0; eq < dofs.n_dofs(); ++eq)
      if (numbers.global[eq] >= 0) local_free[eq] = static_cast<int>(layout.global.size()), layout.global.push_back(numbers.global[eq]);
    layout.first = numbers.first, layout.n_global = numbers.n_global, layout.n_owned = numbers.n_owned;
    for (int k = 0; k < layout.n_owned; ++k) ASSERT_EQ(layout.global[k], numbers.first + k);
    std::vector<char> owned(part.mesh.n_nodes(), 0);
    for (int i = 0; i < part.n_owned_nodes; ++i) owned[i] = 1;
    const int n_local = static_cast<int>(layout.global.size());
    const SparseMatrix k_local = restricted(assemble_stiffness_matrix(model, dofs, &owned), local_free, n_local);
    Vector f_local = Vector::Zero(dofs.n_dofs());
    assemble_pressure(part.mesh, model.dim, part.mesh.cell_groups.at("TOP"), pressure, dofs, f_local, false,
                      &part.node_owner);
    std::vector<double> f(f_local.data(), f_local.data() + f_local.size());
    equation_halo(part, dofs, number_across_ranks(part, dofs, node_halo)).add_to_owners(f, 1);
    Vector b = Vector::Zero(n_local);
    for (int eq = 0; eq < dofs.n_dofs(); ++eq)
      if (local_free[eq] >= 0) b[local_free[eq]] = f[eq];
    std::unique_ptr<LinearSolver> mumps = make_mumps_solver();
    ASSERT_TRUE(mumps->takes_parts());
    mumps->set_layout(layout);
    mumps->factorize(k_local, MatrixKind::SymmetricPositiveDefinite);
    const Vector x = mumps->solve(b);
    ASSERT_EQ(x.size(), n_local);
    const double scale = u_whole.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 0.0);
    int compared = 0;
    for (int eq = 0; eq < dofs.n_dofs(); ++eq) {
      if (local_free[eq] < 0 || local_free[eq] >= layout.n_owned) continue;
      const int whole_eq = whole_dofs.dof(part.global_node[dofs.node_of(eq)], dofs.component_of(eq));
      ASSERT_GE(whole_free[whole_eq], 0);
      EXPECT_NEAR(x[local_free[eq]], u_whole[whole_free[whole_eq]], 1e-10 * scale) << "equation " << eq;
      ++compared;
    }
    EXPECT_EQ(compared, layout.n_owned);
    // What needs the whole matrix on one process is refused in parts, on every rank alike.
    FactorSettings filtered;
    filtered.filter = 1e-12;
    FactorSettings metis;
    metis.ordering = FactorOrdering::Metis;
    for (const FactorSettings& settings : {filtered, metis}) {
      std::unique_ptr<LinearSolver> refusing = make_mumps_solver();
      refusing->configure(settings);
      refusing->set_layout(layout);
      EXPECT_THROW(refusing->factorize(k_local, MatrixKind::SymmetricPositiveDefinite), DeckError);
    }
  }
}

/// The loads of a clamped block on `mesh` (the whole mesh or a part, from its groups): BOTTOM
/// clamped, LEFT pulled along x (DX imposed), TOP pressed, a force on the corner that is farthest
/// from the origin; every load but the clamping follows the instant.
MechanicalLoads block_loads(const Mesh& mesh) {
  MechanicalLoads loads;
  loads.multipliers = {[](double) { return 1.0; }, [](double t) { return t; }};
  std::vector<char> bottom(mesh.n_nodes(), 0), left(mesh.n_nodes(), 0);
  for (const auto& [group, on] : {std::pair<const char*, std::vector<char>*>{"BOTTOM", &bottom}, {"LEFT", &left}})
    for (int c : mesh.cell_groups.at(group))
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a) (*on)[mesh.cell(c)[a]] = 1;
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    if (bottom[v])
      for (int k = 0; k < mesh.dim; ++k) loads.dirichlet.push_back({v, k, 0.0, 0});
    else if (left[v])
      loads.dirichlet.push_back({v, DX, -2.0e-4, 1});
  }
  loads.pressures.push_back({mesh.cell_groups.at("TOP"), 1.0e8, 1});
  for (int v : mesh.node_groups.at(mesh.dim == 3 ? "C111" : "C11")) loads.forces.push_back({v, DY, -4.0e6, 1});
  return loads;
}

NewtonOptions mumps_options() {
  NewtonOptions options;
  options.solver = SolverKind::Mumps;
  options.resi_glob_rela = 1e-10;
  return options;
}

TEST(PartNewton, StaticSolverOnPartsGivesTheWholeModelsDisplacement) {
  std::ostringstream log_text;
  const Log quiet(log_text, 0);
  const std::vector<double> instants = {0.0, 0.5, 1.0};
  for (const Scene& scene : clamped_blocks()) {
    SCOPED_TRACE(scene.name);
    // The whole model on every rank, by CHOLMOD (a model shared among the ranks only with
    // MUMPS or PETSc named).
    const FeModel whole_model = elastic_model(scene.whole);
    const MechanicalLoads whole_loads = block_loads(scene.whole);
    NewtonOptions whole_options = mumps_options();
    whole_options.solver = SolverKind::Cholmod;
    StaticSolver whole(whole_model, whole_loads, whole_options, nullptr, quiet);
    const std::vector<ResultStep> whole_steps = whole.run(instants);

    const MeshPart part = part_of(scene.whole);
    const FeModel model = elastic_model(part.mesh);
    const MechanicalLoads loads = block_loads(part.mesh);
    StaticSolver solver(model, loads, mumps_options(), nullptr, quiet);
    solver.set_part(&part);
    const std::vector<ResultStep> steps = solver.run(instants);
    ASSERT_EQ(steps.size(), whole_steps.size());
    EXPECT_EQ(solver.stats().n_dofs, whole.stats().n_dofs);
    EXPECT_EQ(solver.stats().n_free, whole.stats().n_free);
    // Linear elasticity: one solve per instant, as the whole model's.
    EXPECT_EQ(solver.stats().newton_iterations, whole.stats().newton_iterations);
    for (size_t i = 1; i < steps.size(); ++i) {
      const NodalField& depl = steps[i].nodal.at("DEPL");
      const NodalField& expected = whole_steps[i].nodal.at("DEPL");
      ASSERT_EQ(depl.n_components(), scene.whole.dim);
      std::vector<double> values(static_cast<size_t>(part.mesh.n_nodes()) * scene.whole.dim);
      for (int v = 0; v < part.mesh.n_nodes(); ++v)
        for (int k = 0; k < scene.whole.dim; ++k) values[v * scene.whole.dim + k] = depl.value(v, k);
      // Every ghost holds its owner's value.
      std::vector<double> owners = values;
      NodeHalo(part).copy_to_ghosts(owners, scene.whole.dim);
      EXPECT_EQ(owners, values);
      const std::vector<double> gathered = gather_nodes_to_root(part, values, scene.whole.dim);
      if (parallel::rank() != 0) continue;
      double scale = 0.0;
      for (int v = 0; v < scene.whole.n_nodes(); ++v)
        for (int k = 0; k < scene.whole.dim; ++k) scale = std::max(scale, std::abs(expected.value(v, k)));
      ASSERT_GT(scale, 1e-5);
      for (int v = 0; v < scene.whole.n_nodes(); ++v)
        for (int k = 0; k < scene.whole.dim; ++k)
          EXPECT_NEAR(gathered[v * scene.whole.dim + k], expected.value(v, k), 1e-10 * scale)
              << "instant " << steps[i].inst << ", node " << v << ", component " << k;
    }
  }
}

TEST(PartNewton, PetscSolvesOnPartsToItsTolerance) {
  std::ostringstream log_text;
  const Log quiet(log_text, 0);
  const std::vector<double> instants = {0.0, 1.0};
  using P = IterativeSettings::Preconditioner;
  for (const Scene& scene : clamped_blocks()) {
    const FeModel whole_model = elastic_model(scene.whole);
    const MechanicalLoads whole_loads = block_loads(scene.whole);
    NewtonOptions whole_options = mumps_options();
    whole_options.solver = SolverKind::Cholmod;
    StaticSolver whole(whole_model, whole_loads, whole_options, nullptr, quiet);
    const NodalField expected = whole.run(instants).back().nodal.at("DEPL");
    const MeshPart part = part_of(scene.whole);
    const FeModel model = elastic_model(part.mesh);
    const MechanicalLoads loads = block_loads(part.mesh);
    using K = IterativeSettings::Krylov;
    for (const auto& [preconditioner, krylov] : std::vector<std::pair<P, K>>{
             {P::Gamg, K::CG}, {P::Boomer, K::CG}, {P::Ml, K::CG}, {P::Jacobi, K::CG}, {P::Sor, K::GMRES}}) {
      SCOPED_TRACE(scene.name + ", preconditioner " + std::to_string(static_cast<int>(preconditioner)) +
                   ", Krylov method " + std::to_string(static_cast<int>(krylov)));
      NewtonOptions options = mumps_options();
      options.solver = SolverKind::Petsc;
      options.iterative.krylov = krylov;
      options.iterative.preconditioner = preconditioner;
      options.iterative.relative_residual = 1e-12;
      options.iterative.max_iterations = 5000;
      StaticSolver solver(model, loads, options, nullptr, quiet);
      solver.set_part(&part);
      const NodalField depl = solver.run(instants).back().nodal.at("DEPL");
      EXPECT_GT(solver.stats().krylov_iterations, 0);
      const int dim = scene.whole.dim;
      std::vector<double> values(static_cast<size_t>(part.mesh.n_nodes()) * dim);
      for (int v = 0; v < part.mesh.n_nodes(); ++v)
        for (int k = 0; k < dim; ++k) values[v * dim + k] = depl.value(v, k);
      const std::vector<double> gathered = gather_nodes_to_root(part, values, dim);
      if (parallel::rank() != 0) continue;
      double scale = 0.0;
      for (int v = 0; v < scene.whole.n_nodes(); ++v)
        for (int k = 0; k < dim; ++k) scale = std::max(scale, std::abs(expected.value(v, k)));
      // CG to 1e-12 of the right-hand side; the displacement's error is the residual's times the
      // condition number: 1e-8 of the largest value leaves these small blocks room.
      for (int v = 0; v < scene.whole.n_nodes(); ++v)
        for (int k = 0; k < dim; ++k)
          EXPECT_NEAR(gathered[v * dim + k], expected.value(v, k), 1e-8 * scale) << "node " << v << ", component " << k;
    }
  }
}

/// `block` values per node of a nodal field, node after node (0 where undefined).
std::vector<double> node_values(const NodalField& f) {
  std::vector<double> out(static_cast<size_t>(f.n_nodes) * f.n_components(), 0.0);
  for (int v = 0; v < f.n_nodes; ++v)
    for (int k = 0; k < f.n_components(); ++k)
      if (f.has(v, k)) out[static_cast<size_t>(v) * f.n_components() + k] = f.value(v, k);
  return out;
}

TEST(PartFields, NodalForcesAndStressesOnPartsAreTheWholeModels) {
  const double t = 0.75;
  for (const Scene& scene : clamped_blocks()) {
    SCOPED_TRACE(scene.name);
    // One displacement, no rigid motion, on the whole mesh and on each part (by global node).
    const Displaced whole = displaced(scene.whole);
    const MechanicalLoads whole_loads = block_loads(scene.whole);
    const std::map<std::string, std::vector<double>> expected = {
        {"FORC_NODA", node_values(internal_nodal_forces(whole.model, whole.dofs, whole.u))},
        {"REAC_NODA", node_values(reaction_forces(whole.model, whole.dofs, whole.u, whole_loads, t))},
        {"SIGM_NOEU", node_values(elno_to_noeu(scene.whole, compute_sigm_elno(whole.model, whole.dofs, whole.u)))}};

    const MeshPart part = part_of(scene.whole);
    const Displaced local = displaced(part.mesh);
    const MechanicalLoads loads = block_loads(part.mesh);
    const Halo equations = equation_halo(part, local.dofs, number_across_ranks(part, local.dofs, NodeHalo(part)));
    const std::map<std::string, NodalField> fields = {
        {"FORC_NODA", internal_nodal_forces(local.model, local.dofs, local.u, part, equations)},
        {"REAC_NODA", reaction_forces(local.model, local.dofs, local.u, loads, t, part, equations)},
        {"SIGM_NOEU", elno_to_noeu(part, compute_sigm_elno(local.model, local.dofs, local.u))}};
    for (const auto& [name, field] : fields) {
      SCOPED_TRACE(name);
      const int block = field.n_components();
      const std::vector<double> values = node_values(field);
      // Every ghost holds its owner's value, every node the whole model's.
      std::vector<double> owners = values;
      NodeHalo(part).copy_to_ghosts(owners, block);
      EXPECT_EQ(owners, values);
      const std::vector<double>& whole_values = expected.at(name);
      double scale = 0.0;
      for (double x : whole_values) scale = std::max(scale, std::abs(x));
      ASSERT_GT(scale, 0.0);
      for (int v = 0; v < part.mesh.n_nodes(); ++v)
        for (int k = 0; k < block; ++k)
          EXPECT_NEAR(values[static_cast<size_t>(v) * block + k],
                      whole_values[static_cast<size_t>(part.global_node[v]) * block + k], 1e-12 * scale)
              << "local node " << v << ", component " << k;
    }
  }
}

TEST(PartNewton, WhatPartsDoNotDoYetIsRefusedOnEveryRank) {
  std::ostringstream log_text;
  const Log quiet(log_text, 0);
  const Scene scene = clamped_blocks().front();
  const MeshPart part = part_of(scene.whole);
  const FeModel model = elastic_model(part.mesh);
  const MechanicalLoads loads = block_loads(part.mesh);
  // A backend of one process, or lunaster's choice.
  for (SolverKind kind : {SolverKind::Cholmod, SolverKind::Umfpack}) {
    NewtonOptions options = mumps_options();
    options.solver = kind;
    StaticSolver solver(model, loads, options, nullptr, quiet);
    solver.set_part(&part);
    EXPECT_THROW(solver.run({0.0, 1.0}), DeckError);
  }
  NewtonOptions automatic = mumps_options();
  automatic.auto_solver = true;
  StaticSolver chosen(model, loads, automatic, nullptr, quiet);
  chosen.set_part(&part);
  EXPECT_THROW(chosen.run({0.0, 1.0}), DeckError);
  // PETSc preconditioned by a factorisation of the whole system on one rank.
  NewtonOptions single = mumps_options();
  single.solver = SolverKind::Petsc;
  single.iterative.preconditioner = IterativeSettings::Preconditioner::LdltSp;
  StaticSolver factorised(model, loads, single, nullptr, quiet);
  factorised.set_part(&part);
  EXPECT_THROW(factorised.run({0.0, 1.0}), DeckError);
  // PETSc with a linear relation's multiplier (a saddle system, MUMPS's to solve in parts).
  // DY of two top corners, free (every rank has the same relation, its nodes as ghosts where needed).
  MeshPart numbered = nodes_only(part);
  const std::vector<int> corners = {scene.whole.node_groups.at("C111")[0], scene.whole.node_groups.at("C011")[0]};
  add_ghost_nodes(numbered, corners);
  const std::unordered_map<int, int> local = local_nodes(numbered);
  LinearRelation tie;
  tie.terms = {{local.at(corners[0]), DY, 1.0}, {local.at(corners[1]), DY, -1.0}};
  std::unique_ptr<ContactHook> relations = make_relations_hook({tie}, loads.multipliers, nullptr);
  NewtonOptions krylov = mumps_options();
  krylov.solver = SolverKind::Petsc;
  StaticSolver with_multipliers(model, loads, krylov, relations.get(), quiet);
  with_multipliers.set_part(&part, &numbered);
  EXPECT_THROW(with_multipliers.run({0.0, 1.0}), DeckError);
  // The same solver on the part runs once told.
  StaticSolver solver(model, loads, mumps_options(), nullptr, quiet);
  solver.set_part(&part);
  EXPECT_EQ(solver.run({0.0, 1.0}).size(), 2u);
}

}  // namespace
}  // namespace lunaster::engine

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  lunaster::engine::parallel::ensure_initialised();
  int failed = RUN_ALL_TESTS() != 0 ? 1 : 0;
  // A failure on any rank fails every rank's exit status.
  failed = lunaster::engine::parallel::max_over_ranks(failed) > 0.0 ? 1 : 0;
  // MPI is finalised at exit, after PETSc (atexit, in reverse order of initialisation).
  return failed;
}

#pragma once
/// A model's volume cells shared among the ranks of an MPI run: which rank assembles
/// which cells, and which rank owns the equations of each node.
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

struct CellPartition {
  int parts = 1;
  std::vector<int> cell_part;   ///< per cell of the partitioned list (same order): its rank
  std::vector<int> node_owner;  ///< per mesh node: the rank owning its equations; -1 outside the cells
  int interface_nodes = 0;      ///< nodes whose cells lie on more than one rank
};

/// Partitions `cells` over the ranks of the run (parallel::size() parts) with Scotch, on
/// their dual graph: two cells are adjacent when they share `dim` nodes or more (a face, in
/// 3D also an edge of quadratic cells); each cell weighs the size of its element matrix
/// (nodes squared), so that a rank of quadratic cells gets fewer of them. Rank 0 partitions
/// and every rank gets the result. A node belongs to the rank holding most of its cells, on
/// a tie the one owning fewer nodes so far. The same cells give the same parts in every run.
/// Collective: every rank calls it with the same mesh and cells. With one rank, every cell
/// and node is rank 0's.
CellPartition partition_cells(const Mesh& mesh, const std::vector<int>& cells, int dim);

/// partition_cells' parts computed on this process alone (no MPI): per cell of `cells`, its
/// part among `parts` (a short list, under 4 cells per part, in blocks). `around`: the cells
/// around each node (mesh.node_cells(cells)). Throws SolveError when Scotch fails.
std::vector<int> scotch_cell_parts(const Mesh& mesh, const std::vector<int>& cells, int dim, int parts,
                                   const Mesh::NodeCells& around);

/// partition_cells' node owners from the cells' parts: per mesh node, the part holding most
/// of its cells (on a tie, the one owning fewer nodes so far), -1 for a node outside the
/// cells; `interface_nodes`, if given, counts the nodes whose cells lie in several parts.
std::vector<int> node_owners(int n_nodes, const std::vector<int>& cell_part, int parts, const Mesh::NodeCells& around,
                             int* interface_nodes = nullptr);

}  // namespace lunaster::engine

#include "engine/assembly/partition.hpp"

#include <cstdint>
#include <cstdio>
// Scotch's header uses these types without including their headers.
#include <scotch.h>

#include <algorithm>
#include <string>

#include "engine/core/error.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {
namespace {

/// Cell i of `cells` goes to rank i * parts / n: for a list too short to be worth a graph.
std::vector<int> block_parts(int n, int parts) {
  std::vector<int> part(n);
  for (int i = 0; i < n; ++i) part[i] = static_cast<int>(static_cast<long long>(i) * parts / n);
  return part;
}

}  // namespace

std::vector<int> scotch_cell_parts(const Mesh& mesh, const std::vector<int>& cells, int dim, int parts,
                                   const Mesh::NodeCells& around) {
  const int n = static_cast<int>(cells.size());
  if (parts == 1) return std::vector<int>(n, 0);
  if (n < 4 * parts) return block_parts(n, parts);
  const std::vector<int>& start = around.start;
  const std::vector<int>& node_cells = around.positions;
  // Scotch's sequential partitioner, from its generator's initial state: the same cells give
  // the same parts in every run (PT-Scotch's parallel partitioner gave run-to-run differences).
  // Vertex weights: the size of the cell's element matrix (nodes squared), what it adds to the
  // assembly and to its rank's rows. Counting cells alone gave the rank holding the HEXA20 half
  // of SSNP121 I four times the other's memory.
  std::vector<SCOTCH_Num> part(n, 0);
  std::vector<SCOTCH_Num> vert(static_cast<size_t>(n) + 1, 0), weight(n, 1), edge;
  std::vector<int> shared(n, 0), touched;
  for (int i = 0; i < n; ++i) {
    const int c = cells[i];
    weight[i] = mesh.cell_n_nodes(c) * mesh.cell_n_nodes(c);
    touched.clear();
    for (int a = 0, nn = mesh.cell_n_nodes(c); a < nn; ++a) {
      const int v = mesh.cell(c)[a];
      for (int p = start[v]; p < start[v + 1]; ++p) {
        const int j = node_cells[p];
        if (j == i) continue;
        if (shared[j]++ == 0) touched.push_back(j);
      }
    }
    std::sort(touched.begin(), touched.end());
    for (int j : touched) {
      if (shared[j] >= dim) edge.push_back(j);
      shared[j] = 0;
    }
    vert[i + 1] = static_cast<SCOTCH_Num>(edge.size());
  }
  SCOTCH_Graph graph, bound;
  SCOTCH_Strat strategy;
  SCOTCH_Context context;
  int status = SCOTCH_graphInit(&graph);
  SCOTCH_graphInit(&bound);
  SCOTCH_stratInit(&strategy);
  SCOTCH_contextInit(&context);
  if (status == 0)
    status = SCOTCH_graphBuild(&graph, 0, n, vert.data(), nullptr, weight.data(), nullptr,
                               static_cast<SCOTCH_Num>(edge.size()), edge.data(), nullptr);
  // The same cut on every run: Scotch's multi-threaded coarsening otherwise depends on its
  // threads' timing (seen: 20^3 HEXA8 cut 4410/4851 and 4431/4830 nodes in two runs), and with
  // the cut the order of every sum over the ranks.
  if (status == 0) status = SCOTCH_contextOptionSetNum(&context, SCOTCH_OPTIONNUMDETERMINISTIC, 1);
  if (status == 0) status = SCOTCH_contextBindGraph(&context, &graph, &bound);
  SCOTCH_randomReset();
  if (status == 0) status = SCOTCH_graphPart(&bound, parts, &strategy, part.data());
  SCOTCH_graphExit(&bound);
  SCOTCH_contextExit(&context);
  SCOTCH_stratExit(&strategy);
  SCOTCH_graphExit(&graph);
  if (status != 0)
    throw SolveError("Scotch could not partition the " + std::to_string(n) + " cells over " + std::to_string(parts) +
                     " ranks");
  return std::vector<int>(part.begin(), part.end());
}

std::vector<int> node_owners(int n_nodes, const std::vector<int>& cell_part, int parts, const Mesh::NodeCells& around,
                             int* interface_nodes) {
  // The rank with most of the node's cells; on a tie, the one owning fewer nodes so far (the
  // same order everywhere: the same owners).
  const std::vector<int>& start = around.start;
  const std::vector<int>& node_cells = around.positions;
  std::vector<int> owner(n_nodes, -1);
  std::vector<int> count(parts, 0), owned(parts, 0);
  int interfaces = 0;
  for (int v = 0; v < n_nodes; ++v) {
    if (start[v] == start[v + 1]) continue;
    std::fill(count.begin(), count.end(), 0);
    for (int p = start[v]; p < start[v + 1]; ++p) ++count[cell_part[node_cells[p]]];
    int best = -1, ranks = 0;
    for (int r = 0; r < parts; ++r) {
      if (count[r] == 0) continue;
      ++ranks;
      if (best < 0 || count[r] > count[best] || (count[r] == count[best] && owned[r] < owned[best])) best = r;
    }
    owner[v] = best;
    ++owned[best];
    interfaces += ranks > 1;
  }
  if (interface_nodes) *interface_nodes = interfaces;
  return owner;
}

CellPartition partition_cells(const Mesh& mesh, const std::vector<int>& cells, int dim) {
  CellPartition out;
  out.parts = parallel::size();
  const int n = static_cast<int>(cells.size());
  const Mesh::NodeCells around = mesh.node_cells(cells);
  if (out.parts == 1 || n < 4 * out.parts) {
    out.cell_part = scotch_cell_parts(mesh, cells, dim, out.parts, around);
  } else {
    // Rank 0 partitions and gives the parts to the others.
    out.cell_part.assign(n, 0);
    std::string failure;
    if (parallel::rank() == 0) {
      try {
        out.cell_part = scotch_cell_parts(mesh, cells, dim, out.parts, around);
      } catch (const SolveError& e) {
        failure = e.message();
      }
    }
    // Every rank learns rank 0's failure, if any: it stops them all, none waits.
    parallel::broadcast(failure);
    if (!failure.empty()) throw SolveError(failure);
    parallel::broadcast(out.cell_part.data(), n);
  }
  out.node_owner = node_owners(mesh.n_nodes(), out.cell_part, out.parts, around, &out.interface_nodes);
  return out;
}

}  // namespace lunaster::engine

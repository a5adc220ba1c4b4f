#include "engine/assembly/partition.hpp"

#include <mpi.h>
#include <cstdint>
#include <cstdio>
// PT-Scotch's header uses these types without including their headers.
#include <ptscotch.h>

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

CellPartition partition_cells(const Mesh& mesh, const std::vector<int>& cells, int dim) {
  CellPartition out;
  out.parts = parallel::size();
  const int n = static_cast<int>(cells.size());
  const int rank = parallel::rank();
  // Cells of each node (CSR, positions in `cells`).
  const int n_nodes = mesh.n_nodes();
  std::vector<int> start(static_cast<size_t>(n_nodes) + 1, 0), node_cells;
  for (int c : cells)
    for (int a = 0, nn = mesh.cell_n_nodes(c); a < nn; ++a) ++start[mesh.cell(c)[a] + 1];
  for (int v = 0; v < n_nodes; ++v) start[v + 1] += start[v];
  node_cells.resize(start[n_nodes]);
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int i = 0; i < n; ++i)
      for (int a = 0, nn = mesh.cell_n_nodes(cells[i]); a < nn; ++a) node_cells[fill[mesh.cell(cells[i])[a]]++] = i;
  }
  if (out.parts == 1) {
    out.cell_part.assign(n, 0);
  } else if (n < 4 * out.parts) {
    out.cell_part = block_parts(n, out.parts);
  } else {
    // This rank's vertices of the dual graph: cells [first, last).
    const int first = static_cast<int>(static_cast<long long>(n) * rank / out.parts);
    const int last = static_cast<int>(static_cast<long long>(n) * (rank + 1) / out.parts);
    std::vector<SCOTCH_Num> vert(static_cast<size_t>(last - first) + 1, 0), edge;
    std::vector<int> shared(n, 0), touched;
    for (int i = first; i < last; ++i) {
      const int c = cells[i];
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
      vert[i - first + 1] = static_cast<SCOTCH_Num>(edge.size());
    }
    std::vector<int>().swap(shared);
    const SCOTCH_Num local = last - first, arcs = static_cast<SCOTCH_Num>(edge.size());
    std::vector<SCOTCH_Num> part(static_cast<size_t>(std::max(local, 1)), 0);
    SCOTCH_Dgraph graph;
    SCOTCH_Strat strategy;
    if (SCOTCH_dgraphInit(&graph, MPI_COMM_WORLD) != 0)
      throw SolveError("PT-Scotch: the distributed graph of the cells could not be created");
    SCOTCH_stratInit(&strategy);
    int status = SCOTCH_dgraphBuild(&graph, 0, local, local, vert.data(), nullptr, nullptr, nullptr, arcs, arcs,
                                    edge.data(), nullptr, nullptr);
    // Scotch's pseudo-random generator from its initial state: the same cells, the same parts.
    SCOTCH_randomReset();
    if (status == 0) status = SCOTCH_dgraphPart(&graph, out.parts, &strategy, part.data());
    SCOTCH_stratExit(&strategy);
    SCOTCH_dgraphExit(&graph);
    // Every rank sees the others' status: a failure stops them all, none waits.
    double failed = status != 0 ? 1.0 : 0.0;
    if (parallel::max_over_ranks(failed) > 0.0)
      throw SolveError("PT-Scotch could not partition the " + std::to_string(n) + " cells over " +
                       std::to_string(out.parts) + " ranks");
    part.resize(static_cast<size_t>(local));
    out.cell_part = parallel::gather_all(std::vector<int>(part.begin(), part.end()));
  }
  // Node owners: the rank with most of the node's cells; on a tie, the one owning fewer
  // nodes so far (the same order on every rank: the same owners).
  out.node_owner.assign(n_nodes, -1);
  std::vector<int> count(out.parts, 0), owned(out.parts, 0);
  for (int v = 0; v < n_nodes; ++v) {
    if (start[v] == start[v + 1]) continue;
    std::fill(count.begin(), count.end(), 0);
    for (int p = start[v]; p < start[v + 1]; ++p) ++count[out.cell_part[node_cells[p]]];
    int best = -1, ranks = 0;
    for (int r = 0; r < out.parts; ++r) {
      if (count[r] == 0) continue;
      ++ranks;
      if (best < 0 || count[r] > count[best] || (count[r] == count[best] && owned[r] < owned[best])) best = r;
    }
    out.node_owner[v] = best;
    ++owned[best];
    out.interface_nodes += ranks > 1;
  }
  return out;
}

}  // namespace lunaster::engine

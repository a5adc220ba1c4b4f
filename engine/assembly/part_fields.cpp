#include "engine/assembly/part_fields.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {

namespace {

/// Rank 0's whole array of `n` entries of `block` values from every rank's (global number,
/// values) of the entries it gives.
std::vector<double> gather_given(const std::vector<int>& ids, const std::vector<double>& given, int n, int block) {
  const std::vector<int> all_ids = parallel::gather_to_root(ids);
  const std::vector<double> all_values = parallel::gather_to_root(given);
  if (parallel::rank() != 0) return {};
  LUNASTER_ASSERT(all_ids.size() == static_cast<size_t>(n) && all_values.size() == all_ids.size() * block,
                  "gather to rank 0: the parts do not give every entry once");
  std::vector<double> whole(static_cast<size_t>(n) * block);
  std::vector<char> seen(n, 0);
  for (size_t k = 0; k < all_ids.size(); ++k) {
    const int g = all_ids[k];
    LUNASTER_ASSERT(g >= 0 && g < n && !seen[g], "gather to rank 0: an entry given twice");
    seen[g] = 1;
    std::copy_n(all_values.begin() + static_cast<long>(k) * block, block, whole.begin() + static_cast<long>(g) * block);
  }
  return whole;
}

}  // namespace

std::vector<double> gather_nodes_to_root(const MeshPart& part, const std::vector<double>& values, int block) {
  LUNASTER_ASSERT(values.size() == part.global_node.size() * block, "gather_nodes_to_root: not the part's nodes");
  const std::vector<int> ids(part.global_node.begin(), part.global_node.begin() + part.n_owned_nodes);
  const std::vector<double> given(values.begin(), values.begin() + static_cast<long>(part.n_owned_nodes) * block);
  return gather_given(ids, given, part.n_global_nodes, block);
}

std::vector<double> gather_cells_to_root(const MeshPart& part, const std::vector<double>& values, int block) {
  LUNASTER_ASSERT(values.size() == part.global_cell.size() * block, "gather_cells_to_root: not the part's cells");
  std::vector<int> ids;
  std::vector<double> given;
  for (int c = 0; c < part.mesh.n_cells(); ++c) {
    if (cell_giver(part, c) != part.rank) continue;
    ids.push_back(part.global_cell[c]);
    given.insert(given.end(), values.begin() + static_cast<long>(c) * block,
                 values.begin() + static_cast<long>(c + 1) * block);
  }
  return gather_given(ids, given, part.n_global_cells, block);
}

std::vector<double> node_values_everywhere(const MeshPart& part, const std::vector<double>& values, int block,
                                           int global_node) {
  LUNASTER_ASSERT(global_node >= 0 && global_node < part.n_global_nodes, "node_values_everywhere: no such node");
  // The owner is the one rank that finds the node among its owned ones.
  const auto end = part.global_node.begin() + part.n_owned_nodes;
  const auto at = std::lower_bound(part.global_node.begin(), end, global_node);
  const bool mine = at != end && *at == global_node;
  std::vector<double> out(block, 0.0);
  if (mine) std::copy_n(values.begin() + (at - part.global_node.begin()) * block, block, out.begin());
  const int owner = static_cast<int>(parallel::max_over_ranks(mine ? part.rank : -1));
  parallel::broadcast_from(owner, out.data(), block);
  return out;
}

}  // namespace lunaster::engine

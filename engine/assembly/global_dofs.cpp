#include "engine/assembly/global_dofs.hpp"

#include "engine/core/error.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {

GlobalDofs number_across_ranks(const MeshPart& part, const DofMap& dofs, const NodeHalo& halo) {
  GlobalDofs out;
  const int n = dofs.n_dofs();
  while (out.n_owned < n && part.owns(dofs.node_of(out.n_owned))) ++out.n_owned;
  for (int eq = out.n_owned; eq < n; ++eq)
    LUNASTER_ASSERT(!part.owns(dofs.node_of(eq)), "number_across_ranks: owned equations after a ghost's");
  const std::vector<int> owned = parallel::gather_all(std::vector<int>{out.n_owned});
  for (int r = 0; r < static_cast<int>(owned.size()); ++r) {
    if (r < part.rank) out.first += owned[r];
    out.n_global += owned[r];
  }
  // Per local node, the global number of each component (-1: none); owners' to their ghosts.
  // (A double holds an integer exactly up to 2^53.)
  std::vector<double> numbers(static_cast<size_t>(part.mesh.n_nodes()) * N_COMPONENTS, -1.0);
  for (int eq = 0; eq < out.n_owned; ++eq)
    numbers[static_cast<size_t>(dofs.node_of(eq)) * N_COMPONENTS + dofs.component_of(eq)] =
        static_cast<double>(out.first + eq);
  halo.copy_to_ghosts(numbers, N_COMPONENTS);
  out.global.resize(n);
  for (int eq = 0; eq < n; ++eq) {
    const double g = numbers[static_cast<size_t>(dofs.node_of(eq)) * N_COMPONENTS + dofs.component_of(eq)];
    LUNASTER_ASSERT(g >= 0.0, "number_across_ranks: a ghost's unknown its owner does not have");
    out.global[eq] = static_cast<long long>(g);
  }
  return out;
}

}  // namespace lunaster::engine

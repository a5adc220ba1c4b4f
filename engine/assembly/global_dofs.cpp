#include "engine/assembly/global_dofs.hpp"

#include "engine/core/error.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {

GlobalDofs number_across_ranks(const MeshPart& part, const DofMap& dofs, const NodeHalo& halo,
                               const std::vector<char>* kept) {
  GlobalDofs out;
  const int n = dofs.n_dofs();
  LUNASTER_ASSERT(!kept || static_cast<int>(kept->size()) == n, "number_across_ranks: a mask of other equations");
  int owned_eqs = 0;
  while (owned_eqs < n && part.owns(dofs.node_of(owned_eqs))) ++owned_eqs;
  for (int eq = owned_eqs; eq < n; ++eq)
    LUNASTER_ASSERT(!part.owns(dofs.node_of(eq)), "number_across_ranks: owned equations after a ghost's");
  std::vector<long long> owned_number(owned_eqs, -1);
  for (int eq = 0; eq < owned_eqs; ++eq)
    if (!kept || (*kept)[eq]) owned_number[eq] = out.n_owned++;
  const std::vector<int> owned = parallel::gather_all(std::vector<int>{out.n_owned});
  for (int r = 0; r < static_cast<int>(owned.size()); ++r) {
    if (r < part.rank) out.first += owned[r];
    out.n_global += owned[r];
  }
  // Per local node, the global number of each component (-1: none or not kept, -2: no such
  // unknown); owners' to their ghosts. (A double holds an integer exactly up to 2^53.)
  std::vector<double> numbers(static_cast<size_t>(part.mesh.n_nodes()) * N_COMPONENTS, -2.0);
  for (int eq = 0; eq < owned_eqs; ++eq)
    numbers[static_cast<size_t>(dofs.node_of(eq)) * N_COMPONENTS + dofs.component_of(eq)] =
        owned_number[eq] < 0 ? -1.0 : static_cast<double>(out.first + owned_number[eq]);
  halo.copy_to_ghosts(numbers, N_COMPONENTS);
  out.global.resize(n);
  for (int eq = 0; eq < n; ++eq) {
    const double g = numbers[static_cast<size_t>(dofs.node_of(eq)) * N_COMPONENTS + dofs.component_of(eq)];
    LUNASTER_ASSERT(g >= -1.0, "number_across_ranks: a ghost's unknown its owner does not have");
    out.global[eq] = static_cast<long long>(g);
  }
  return out;
}

}  // namespace lunaster::engine

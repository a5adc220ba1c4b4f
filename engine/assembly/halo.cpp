#include "engine/assembly/halo.hpp"

#include <algorithm>

#include "engine/assembly/global_dofs.hpp"
#include "engine/core/error.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {

Halo::Halo(const std::vector<int>& global, const std::vector<int>& owner, int n_owned, int rank, int parts) {
  const int n_local = static_cast<int>(global.size());
  LUNASTER_ASSERT(owner.size() == global.size() && n_owned <= n_local, "Halo: owners and numbers of other entries");
  // Ghosts by owner (in local order within each: both sides list them in it).
  std::vector<std::vector<int>> by_owner(parts);
  for (int i = n_owned; i < n_local; ++i) by_owner[owner[i]].push_back(i);
  LUNASTER_ASSERT(by_owner[rank].empty(), "Halo: a ghost owned by its own rank");
  std::vector<int> counts(parts);
  for (int r = 0; r < parts; ++r) counts[r] = static_cast<int>(by_owner[r].size());
  // How many of this rank's entries each rank holds as ghosts.
  const std::vector<int> asked = parallel::all_to_all(counts);
  for (int r = 0; r < parts; ++r)
    if (counts[r] > 0 || asked[r] > 0) ranks_.push_back(r);
  std::vector<std::vector<int>> sends(ranks_.size()), receives(ranks_.size());
  ghosts_of_.resize(ranks_.size());
  for (size_t k = 0; k < ranks_.size(); ++k) {
    ghosts_of_[k] = by_owner[ranks_[k]];
    for (int i : ghosts_of_[k]) sends[k].push_back(global[i]);
    receives[k].resize(asked[ranks_[k]]);
  }
  parallel::exchange(ranks_, sends, receives);
  // The owned entries are in ascending global order: found by bisection.
  const auto owned_begin = global.begin(), owned_end = owned_begin + n_owned;
  shared_with_.resize(ranks_.size());
  for (size_t k = 0; k < ranks_.size(); ++k)
    for (int g : receives[k]) {
      const auto at = std::lower_bound(owned_begin, owned_end, g);
      LUNASTER_ASSERT(at != owned_end && *at == g, "Halo: a rank holds a ghost this rank does not own");
      shared_with_[k].push_back(static_cast<int>(at - owned_begin));
    }
}

void Halo::move(double* values, int block, const std::vector<std::vector<int>>& from,
                const std::vector<std::vector<int>>& to, bool add) const {
  std::vector<std::vector<double>> sends(ranks_.size()), receives(ranks_.size());
  for (size_t k = 0; k < ranks_.size(); ++k) {
    sends[k].reserve(from[k].size() * block);
    for (int i : from[k])
      for (int b = 0; b < block; ++b) sends[k].push_back(values[static_cast<size_t>(i) * block + b]);
    receives[k].resize(to[k].size() * block);
  }
  parallel::exchange(ranks_, sends, receives);
  // In neighbour order: the same sums in every run.
  for (size_t k = 0; k < ranks_.size(); ++k)
    for (size_t j = 0; j < to[k].size(); ++j)
      for (int b = 0; b < block; ++b) {
        double& v = values[static_cast<size_t>(to[k][j]) * block + b];
        v = add ? v + receives[k][j * block + b] : receives[k][j * block + b];
      }
}

void Halo::add_to_owners(double* values, int block) const {
  move(values, block, ghosts_of_, shared_with_, true);
}

void Halo::copy_to_ghosts(double* values, int block) const {
  move(values, block, shared_with_, ghosts_of_, false);
}

NodeHalo::NodeHalo(const MeshPart& part)
    : Halo(part.global_node, part.node_owner, part.n_owned_nodes, part.rank, part.parts) {}

Halo equation_halo(const MeshPart& part, const DofMap& dofs, const GlobalDofs& numbers) {
  std::vector<int> global, owner;
  LUNASTER_ASSERT(numbers.n_global < (1LL << 31), "equation_halo: more unknowns than an int numbers");
  for (size_t eq = 0; eq < numbers.global.size(); ++eq)
    if (numbers.global[eq] >= 0) {
      global.push_back(static_cast<int>(numbers.global[eq]));
      owner.push_back(part.node_owner[dofs.node_of(static_cast<int>(eq))]);
    }
  return Halo(global, owner, numbers.n_owned, part.rank, part.parts);
}

}  // namespace lunaster::engine

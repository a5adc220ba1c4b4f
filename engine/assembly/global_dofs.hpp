#pragma once
/// The unknowns of a mesh part numbered across the ranks (docs/distributed-model.md, step 2):
/// each rank numbers its owned nodes' unknowns, after those of the ranks before it; a ghost's
/// unknowns take the numbers its owner gave them. These are the rows a rank gives PETSc (its
/// contiguous range) and the indices of MUMPS's distributed entries.
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/assembly/halo.hpp"
#include "engine/assembly/mesh_part.hpp"

namespace lunaster::engine {

struct GlobalDofs {
  long long first = 0;            ///< global number of this rank's first unknown
  /// This rank's numbered unknowns, first .. first + n_owned - 1: without a mask, its local
  /// equations [0, n_owned); with one, its kept owned equations in their order.
  int n_owned = 0;
  long long n_global = 0;         ///< unknowns of the whole model
  std::vector<long long> global;  ///< per local equation of the DofMap, its global number (-1: not kept)
};

/// Collective. `dofs` numbers the part's local nodes in their order (DofMap's constructor), so
/// that the owned nodes' equations come first; throws InternalError otherwise, or when a ghost's
/// owner has no such unknown. With `kept` (per local equation), only the kept unknowns are
/// numbered, the others get -1: the owners' say decides for their ghosts (a ghost's own entry
/// of `kept` is not read), so that the free unknowns of a system are numbered by the ranks that
/// know their Dirichlet conditions; n_owned then counts the kept owned ones.
GlobalDofs number_across_ranks(const MeshPart& part, const DofMap& dofs, const NodeHalo& halo,
                               const std::vector<char>* kept = nullptr);

}  // namespace lunaster::engine

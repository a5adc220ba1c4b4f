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
  int n_owned = 0;                ///< this rank's unknowns: its local equations [0, n_owned)
  long long n_global = 0;         ///< unknowns of the whole model
  std::vector<long long> global;  ///< per local equation of the DofMap, its global number
};

/// Collective. `dofs` numbers the part's local nodes in their order (DofMap's constructor), so
/// that the owned nodes' equations come first; throws InternalError otherwise, or when a ghost's
/// owner has no such unknown.
GlobalDofs number_across_ranks(const MeshPart& part, const DofMap& dofs, const NodeHalo& halo);

}  // namespace lunaster::engine

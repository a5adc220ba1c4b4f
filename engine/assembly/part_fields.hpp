#pragma once
/// Fields of a mesh in parts brought back to the whole mesh's numbering, for what one rank
/// writes or prints (docs/distributed-model.md, step 4): IMPR_RESU's file and TEST_RESU's values.
#include <vector>

#include "engine/assembly/mesh_part.hpp"

namespace lunaster::engine {

/// `block` values per local node of `part`, node after node -> the same for every node of the
/// whole mesh, on rank 0 (empty elsewhere). Each node's values are its owner's. Collective.
std::vector<double> gather_nodes_to_root(const MeshPart& part, const std::vector<double>& values, int block);

/// `block` values per local cell -> the same for every cell of the whole mesh, on rank 0 (empty
/// elsewhere). A volume cell's values are the rank's assembling it; a cell below the mesh's
/// dimension is given by the owner of its first node (the rank that computes a pressure on it).
/// Collective.
std::vector<double> gather_cells_to_root(const MeshPart& part, const std::vector<double>& values, int block);

/// The `block` values of the whole mesh's node `global_node` on every rank, from its owner
/// (every rank asks for the same node). Collective.
std::vector<double> node_values_everywhere(const MeshPart& part, const std::vector<double>& values, int block,
                                           int global_node);

/// The rank giving local cell `cell`'s values (see gather_cells_to_root).
inline int cell_giver(const MeshPart& part, int cell) {
  return part.cell_part[cell] >= 0 ? part.cell_part[cell] : part.node_owner[part.mesh.cell(cell)[0]];
}

}  // namespace lunaster::engine

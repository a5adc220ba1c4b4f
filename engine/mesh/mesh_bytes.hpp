#pragma once
/// A mesh as one block of bytes and back: what rank 0 of an MPI run sends the other ranks
/// after reading a mesh file once.
#include <string>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Every member of `mesh` (dimension, name, coordinates, node and cell names, cells, groups)
/// in a byte string of this build's native layout (not a file format: the ranks of one run
/// read it back).
std::string mesh_to_bytes(const Mesh& mesh);

/// The mesh `mesh_to_bytes` wrote. Throws InternalError on a truncated or inconsistent block.
Mesh mesh_from_bytes(const std::string& bytes);

}  // namespace lunaster::engine

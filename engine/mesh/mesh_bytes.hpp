#pragma once
/// A mesh as one block of bytes and back: what rank 0 of an MPI run sends the other ranks
/// after reading a mesh file once.
#include <initializer_list>
#include <string>
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Every member of `mesh` (dimension, name, coordinates, node and cell names, cells, groups)
/// in a byte string of this build's native layout (not a file format: the ranks of one run
/// read it back), followed by the `extra` arrays (a distributed mesh's numbering).
std::string mesh_to_bytes(const Mesh& mesh, std::initializer_list<const std::vector<int>*> extra = {});

/// The mesh `mesh_to_bytes` wrote, and its extra arrays into `extra` (as many, in the same
/// order). Throws InternalError on a truncated or inconsistent block.
Mesh mesh_from_bytes(const std::string& bytes, std::initializer_list<std::vector<int>*> extra = {});

}  // namespace lunaster::engine

#pragma once
/// Names the unknown where a factorisation broke down, for rigid-body diagnosis.
#include <string>

#include "engine/assembly/dof_map.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// "node N12, component DY" for equation `eq` of `dofs` (node names from the
/// mesh, N<k> 1-based if the mesh has none); "equation <eq>" when `eq` is not
/// a valid equation (e.g. -1 for an unknown failed column).
std::string describe_equation(const Mesh& mesh, const DofMap& dofs, int eq);

}  // namespace lunaster::engine

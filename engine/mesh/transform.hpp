#pragma once
/// Rigid transformations of a mesh's coordinates (MODI_MAILLAGE ROTATION).
#include <array>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Rotates every node of `mesh` by `angle` radians about the axis through `point` with
/// direction `axis` (any non-zero length), counter-clockwise when looking against `axis`
/// (right-hand rule). Rodrigues' formula; cells, names and groups are unchanged, and so is the
/// orientation of every cell (a rotation keeps signed volumes and outward normals outward).
/// `axis` must be non-zero (InternalError otherwise: the command checks it first).
void rotate_mesh(Mesh& mesh, const std::array<double, 3>& point, const std::array<double, 3>& axis, double angle);

}  // namespace lunaster::engine

#pragma once
/// Writing Gmsh .msh ASCII files (formats 2.2 and 4.1) from an engine::Mesh,
/// for test meshes (lunaster-meshgen -o FILE.msh). The inverse of
/// engine/io/gmsh_reader: node and element tags are 1.. in mesh order (so the
/// reader names them N<k> / M<k> as the MED files do), node orders go from MED
/// to Gmsh, and each cell group becomes a physical group of that name. Node
/// groups become physical groups of point elements (one per node), written
/// after the cells, as Gmsh does for physical points.
#include <string>

#include "engine/mesh/mesh.hpp"

namespace lunaster::tools {

/// Writes `mesh` to `path` in Gmsh format `version` (2.2 or 4.1). Throws
/// DeckError for another version, a group mixing cell dimensions, a cell in two
/// groups in format 2.2 (one physical tag per element), or a write failure
/// (the file is replaced atomically).
void write_gmsh(const std::string& path, const engine::Mesh& mesh, const std::string& version);

}  // namespace lunaster::tools

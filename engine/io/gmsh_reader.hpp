#pragma once
/// Reading Gmsh .msh ASCII meshes (formats 2.2 and 4.1).
///
/// Supported elements (Gmsh type -> cell): 15 point -> POI1, 1 -> SEG2,
/// 8 -> SEG3, 2 -> TRIA3, 9 -> TRIA6, 3 -> QUAD4, 16 -> QUAD8, 4 -> TETRA4,
/// 11 -> TETRA10, 7 -> PYRAM5, 6 -> PENTA6, 18 (15-node prism) -> PENTA15,
/// 5 -> HEXA8, 17 -> HEXA20. Node orders are converted from Gmsh's to MED's
/// (they differ for every 3D cell). Nodes are named N<gmsh tag>, cells
/// M<gmsh tag>. Each physical group becomes a cell group named after its
/// $PhysicalNames entry (GM<tag> when unnamed); a physical group of point
/// elements also becomes a node group.
#include <string>
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Reads a Gmsh file and sets `Mesh::dim`; cells keep the orientation of the
/// file (LIRE_MAILLAGE then calls `orient_cells`). Throws DeckError for a
/// missing file, a binary file, an unsupported version or element type,
/// truncated or malformed input, unknown node tags.
Mesh read_gmsh(const std::string& path);

/// Same, from the text of a file; `source` names it in error messages.
Mesh read_gmsh_text(const std::string& text, const std::string& source);

/// Gmsh element type number of a cell type (5 for HEXA8 ...), for writers of
/// Gmsh files; InternalError for a type Gmsh files cannot hold here.
int gmsh_element_type(CellType type);

/// Node order of a Gmsh element relative to MED: med[order[k]] = gmsh[k]
/// (empty: the same order).
const std::vector<int>& gmsh_to_med_order(CellType type);

}  // namespace lunaster::engine

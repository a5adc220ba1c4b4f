#pragma once
/// Reading code_aster's own text meshes (`.mail`, LIRE_MAILLAGE FORMAT='ASTER').
///
/// The file is a sequence of blocks, each closed by FINSF, and ends at FIN:
/// TITRE (free text), COOR_1D / COOR_2D / COOR_3D (`name x [y [z]]` per node),
/// a cell type (`name n1 n2 ...` per cell, the nodes in code_aster's order),
/// GROUP_NO / GROUP_MA (the group's name, then its members' names; or the name
/// given in the header as `NOM=name`). A header may carry `KEY=value` items
/// (NOM, NBOBJ, AUTEUR, DATE ...), over several lines. `%` starts a comment.
/// Block keywords are read whatever their case; names are kept as written.
///
/// Supported cells: POI1, SEG2, SEG3, TRIA3, TRIA6, QUAD4, QUAD8, TETRA4,
/// TETRA10, PYRAM5, PENTA6, PENTA15, HEXA8, HEXA20. Node order is converted
/// from code_aster's to MED's (they differ for every 3D cell; the permutations
/// are those of code_aster's MED reader). Nodes and cells keep their names.
#include <string>
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Reads a .mail file and sets `Mesh::dim`; cells keep the orientation of the
/// file. Throws DeckError naming the file and line for a missing file, an
/// unknown block, a cell with the wrong number of nodes, an unknown or repeated
/// name, a block without FINSF, an unsupported cell type.
Mesh read_aster_mail(const std::string& path);

/// Same, from the text of a file; `source` names it in error messages.
Mesh read_aster_mail_text(const std::string& text, const std::string& source);

/// Node order of a code_aster cell relative to MED: med[order[k]] = aster[k]
/// (empty: the same order).
const std::vector<int>& aster_to_med_order(CellType type);

}  // namespace lunaster::engine

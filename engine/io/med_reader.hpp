#pragma once
/// Reading meshes (and nodal result fields) from MED files through the
/// MED-file C library.
///
/// Numbering: nodes keep the file order. Cells are read type by type in the
/// fixed order POINT1, SEG2, SEG3, TRIA3, QUAD4, TRIA6, QUAD8, TETRA4, PYRAM5,
/// PENTA6, HEXA8, TETRA10, PENTA15, HEXA20 (`med_type_rank`), each type in file
/// order. Names come from the file when it stores them, otherwise N1.. / M1..
/// (1-based, in that order). Groups come from the families (node families > 0,
/// cell families < 0; a family may list several groups). Node order inside a
/// cell is MED's, which is lunaster's: no conversion.
#include <string>
#include <vector>

#include "engine/fields/fields.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Reads mesh `mesh_name` (the first mesh of the file when empty) and sets
/// `Mesh::dim` by `detect_dimension`; cells keep the orientation of the file
/// (LIRE_MAILLAGE then calls `orient_cells`). Throws DeckError for a missing
/// file, a file that is not MED/HDF5, a truncated or corrupt file, an unknown
/// mesh name (listing the names available) or an unsupported cell type (named).
Mesh read_med(const std::string& path, const std::string& mesh_name = "");

/// Names of the meshes stored in a MED file (DeckError if it cannot be read).
std::vector<std::string> med_mesh_names(const std::string& path);

/// Names of the fields stored in a MED file.
std::vector<std::string> med_field_names(const std::string& path);

/// One stored step of a nodal field: values at all `n_nodes` nodes.
struct MedNodalStep {
  int numdt = 0;     ///< numéro d'ordre
  double time = 0;   ///< instant
  NodalField field;  ///< every value marked defined
};

/// Reads every step of a nodal (MED_NODE) field; DeckError if absent.
std::vector<MedNodalStep> read_med_nodal_field(const std::string& path, const std::string& field_name);

}  // namespace lunaster::engine

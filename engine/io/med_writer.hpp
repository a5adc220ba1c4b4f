#pragma once
/// Writing meshes and results to MED files through the MED-file C library.
///
/// The file is written to a temporary file in the same folder and renamed
/// over `path` only once complete, so a failed run never leaves a truncated
/// file in place of a good one.
///
/// Mesh: nodes (with their names), cells grouped by type in `med_type_rank`
/// order (with their names: a cell's index may change on a round trip, its
/// name does not), groups stored as families (node families 1, 2, ...; cell
/// families -1, -2, ...; family 0 "FAMILLE_ZERO" for entities in no group).
/// A 2D mesh (`Mesh::dim == 2`) is written with space dimension 2.
///
/// Results: one MED field per result field, named like code_aster's
/// `<result padded to 8 with '_'><FIELD>` ("RESU____DEPL"), one computing step
/// per ResultStep (numdt = numéro d'ordre, numit = none, dt = instant).
/// Nodal fields are written on all nodes (MED_NODE); a component undefined
/// at a node is written as 0. ELNO fields are written per cell type
/// (MED_NODE_ELEMENT), with a profile when only some cells of a type carry values. ELGA fields
/// likewise on the cells (MED_CELL), with one localization per cell type giving its points
/// ("QUAD4_4_POINTS": the reference nodes, the points and their weights).
#include <string>
#include <vector>

#include "engine/fields/fields.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// A named result (sequence of stored steps) to write with the mesh.
struct MedResult {
  std::string name;                         ///< concept name, e.g. "RESU"
  const std::vector<ResultStep>* steps = nullptr;  ///< not owned
};

/// MED field name of result field `field` of result `result` ("RESU____DEPL").
std::string med_field_name(const std::string& result, const std::string& field);

/// Writes the mesh and the results to `path` (replacing it atomically).
/// Throws DeckError if the folder cannot be written or a name does not fit
/// MED (node/cell names: 16 characters, group names: 80, field names: 64).
void write_med(const std::string& path, const Mesh& mesh, const std::vector<MedResult>& results = {});

}  // namespace lunaster::engine

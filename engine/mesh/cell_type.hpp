#pragma once
/// Cell types and their reference data. Node order inside a cell is MED's
/// (see shared/spec/med-facts.md); every reader converts to it.
#include <array>
#include <string_view>

namespace lunaster::engine {

enum class CellType { Point1, Seg2, Seg3, Tria3, Tria6, Quad4, Quad8, Tetra4, Tetra10, Pyram5, Penta6, Penta15, Hexa8, Hexa20 };
/// Number of cell types (the size of a table indexed by CellType).
inline constexpr int kCellTypeCount = static_cast<int>(CellType::Hexa20) + 1;

/// Static facts about a cell type.
struct CellInfo {
  CellType type;
  std::string_view name;  ///< MED/code_aster name, e.g. "QUAD8"
  int dim;                ///< topological dimension (0..3)
  int n_nodes;
  int n_vertices;         ///< corner nodes (order-1 nodes)
  int order;              ///< 1 linear, 2 quadratic
};

const CellInfo& cell_info(CellType type);
/// Lookup by name ("QUAD8"); returns false if unknown.
bool cell_type_from_name(std::string_view name, CellType& out);

/// Local node indices of each face (3D cells) or edge (2D cells) of a cell, in
/// an order such that the face normal computed from them points outward.
/// Quadratic faces list vertices first then mid-side nodes (MED order of the
/// face type). Returns the number of faces; `faces[i]` ends with -1 padding.
struct CellFaces {
  int n_faces = 0;
  std::array<CellType, 6> face_type{};
  std::array<std::array<int, 8>, 6> nodes{};
};
const CellFaces& cell_faces(CellType type);

}  // namespace lunaster::engine

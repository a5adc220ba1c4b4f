#pragma once
/// Lagrange/serendipity shape functions on MED reference cells.
/// Reference cells: SEG [-1,1]; TRIA (0,0),(1,0),(0,1); QUAD [-1,1]^2;
/// TETRA, PENTA, HEXA as in code_aster/MED (HEXA [-1,1]^3, PENTA = triangle x [-1,1]).
#include "engine/mesh/cell_type.hpp"

namespace lunaster::engine {

/// Maximum number of nodes of any cell.
constexpr int kMaxCellNodes = 20;

/// Evaluates the shape functions N[a] and their reference derivatives
/// dN[a*dim + k] = dN_a/dxi_k at the reference point xi (dim = cell dimension).
/// Either output may be null.
void shape_functions(CellType type, const double* xi, double* n, double* dn);

/// Reference coordinates of node `local_node` of a cell type (dim values).
void reference_node(CellType type, int local_node, double* xi);

}  // namespace lunaster::engine

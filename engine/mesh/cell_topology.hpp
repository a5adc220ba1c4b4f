#pragma once
/// Extra topology of the MED reference cells, beyond cell_type.hpp: the vertex
/// pairs carrying the mid-side nodes of quadratic cells, the permutation that
/// reverses a boundary cell, and the linear type of each cell.
///
/// MED reference cells used throughout (node i at the coordinates given; the
/// mid-side node list follows the vertices, in the order of `cell_mid_edges`):
/// - SEG2 0:(0) 1:(1); TRIA3 0:(0,0) 1:(1,0) 2:(0,1); QUAD4 counter-clockwise.
/// - TETRA4 0:(0,0,0) 1:(0,1,0) 2:(1,0,0) 3:(0,0,1)
/// - PYRAM5 0:(0,0,0) 1:(0,1,0) 2:(1,1,0) 3:(1,0,0) 4: apex above the base
/// - PENTA6 0:(0,0,0) 1:(0,1,0) 2:(1,0,0), 3..5 the same at z=1
/// - HEXA8  0:(0,0,0) 1:(0,1,0) 2:(1,1,0) 3:(1,0,0), 4..7 the same at z=1
/// i.e. for every 3D cell the right-hand normal of the first face (nodes 0,1,2)
/// points OUT of the cell (the opposite of VTK/Gmsh for tetra, pyramid, hexa).
#include <utility>
#include <vector>

#include "engine/mesh/cell_type.hpp"

namespace lunaster::engine {

/// Vertex pairs (local indices) of the mid-side nodes of a quadratic cell, in
/// MED order: mid-side node `n_vertices + k` sits on edge `cell_mid_edges(t)[k]`.
/// Empty for linear cells.
const std::vector<std::pair<int, int>>& cell_mid_edges(CellType type);

/// Local permutation that reverses the orientation of a 1D or 2D cell (SEG2/3,
/// TRIA3/6, QUAD4/8): `reversed[i] = nodes[perm[i]]`. Keeps node 0 first.
const std::vector<int>& cell_reverse_permutation(CellType type);

/// Local permutation that turns a cell of dimension 2 or 3 into its mirror
/// image: `mirrored[i] = nodes[perm[i]]`. A clockwise 2D cell becomes
/// counter-clockwise (TRIA/QUAD: the same as `cell_reverse_permutation`), a 3D
/// cell listed as the mirror of the MED reference cell (negative Jacobian
/// everywhere) becomes valid. Vertices: TRIA 0 2 1, QUAD 0 3 2 1, TETRA 0 2 1 3,
/// PYRAM 0 3 2 1 4, PENTA 0 2 1 3 5 4, HEXA 0 3 2 1 4 7 6 5 (a reflection of
/// the reference cell); every mid-side node follows its edge. Keeps node 0
/// first; applying it twice gives the original order back.
const std::vector<int>& cell_mirror_permutation(CellType type);

/// Linear type with the same vertices (QUAD8 -> QUAD4, HEXA20 -> HEXA8 ...).
CellType linear_type(CellType type);

/// Rank of a type in the fixed order used to number cells of a MED file:
/// POINT1, SEG2, SEG3, TRIA3, QUAD4, TRIA6, QUAD8, TETRA4, PYRAM5, PENTA6,
/// HEXA8, TETRA10, PENTA15, HEXA20.
int med_type_rank(CellType type);

/// All cell types in `med_type_rank` order.
const std::vector<CellType>& cell_types_in_med_order();

}  // namespace lunaster::engine

#pragma once
/// Mesh sanity checks that are warnings rather than errors: nodes that belong
/// to no cell, and distinct nodes sharing one position on a surface.
#include <utility>
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Nodes that appear in no cell, in increasing order.
std::vector<int> unreferenced_nodes(const Mesh& mesh);

/// Cells that list one node twice or more.
std::vector<int> cells_repeating_a_node(const Mesh& mesh);

/// Pairs (a, b), a < b, of cells of one type on the same set of nodes (code_aster's "double cells").
std::vector<std::pair<int, int>> duplicate_cells(const Mesh& mesh);

/// Flat cells: (cell, ratio) where the ratio of the shortest to the longest distance between two
/// of the cell's nodes is below `ratio` (code_aster's VERI_MAIL APLAT test); point cells and
/// cells whose nodes all coincide are left out.
std::vector<std::pair<int, double>> flat_cells(const Mesh& mesh, double ratio);

/// Pairs (a, b), a < b, of distinct nodes among `nodes` whose positions differ
/// by at most `tolerance` (metres) in every coordinate. Sort-and-sweep along x:
/// O(n log n) for meshes without many nodes on one x line.
std::vector<std::pair<int, int>> coincident_nodes(const Mesh& mesh, std::vector<int> nodes, double tolerance);

/// A tolerance for `coincident_nodes` relative to the size of the cells:
/// 1e-8 times the largest edge of the given cells (never zero).
double coincidence_tolerance(const Mesh& mesh, const std::vector<int>& cells);

}  // namespace lunaster::engine

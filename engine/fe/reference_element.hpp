#pragma once
/// Per-type tables the element kernels need, computed once: shape functions and
/// reference derivatives at the full-integration points, and the Gauss-to-node
/// extrapolation used for *_ELNO fields. Self-contained (does not need the mesh
/// library's cell_info) so that fe/ can be tested on its own.
#include <vector>

#include "engine/mesh/cell_type.hpp"

namespace lunaster::engine {

/// Topological dimension of the cell types fe/ supports (SEG..HEXA20); 0 otherwise.
int cell_dim(CellType type);
/// Number of nodes of a cell type (fe/ supported types).
int cell_n_nodes(CellType type);
/// Number of vertices (corner nodes).
int cell_n_vertices(CellType type);
/// True for the types that carry shape functions in fe/ (all but POINT1 and PYRAM5).
bool has_shape_functions(CellType type);

/// Shape data of a cell type at its full-integration points.
struct ReferenceElement {
  CellType type = CellType::Seg2;
  int dim = 0;
  int n_nodes = 0;
  int n_qp = 0;
  std::vector<double> weight;  ///< n_qp
  std::vector<double> n;       ///< n_qp * n_nodes
  std::vector<double> dn;      ///< n_qp * n_nodes * dim, dN_a/dxi_k at [(q*n_nodes + a)*dim + k]
  /// Gauss -> node extrapolation, n_nodes x n_qp row-major: least-squares fit of
  /// the vertex (linear) shape functions to the Gauss values, evaluated at the
  /// vertices, mid-side nodes taking the mean of their edge's vertices (the
  /// rule code_aster uses for *_ELNO).
  std::vector<double> extrapolation;
};

/// Tables for a type, built on first use (thread-safe). Throws InternalError for
/// types without shape functions.
const ReferenceElement& reference_element(CellType type);

}  // namespace lunaster::engine

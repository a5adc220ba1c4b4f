#pragma once
/// Mortar integration: the overlap of one slave cell with one master cell as integration
/// points carrying coordinates on both cells ("segmentation"), and the dual (biorthogonal)
/// multiplier basis of a slave cell on the part of it that is integrated.
/// Facts: Popp, Gee, Wall, IJNME 79 (2009) (2D segments); Puso, Laursen, CMAME 193 (2004)
/// (3D auxiliary plane and clipping); Wohlmuth, SIAM J. Numer. Anal. 38 (2000) (dual basis);
/// Popp, Wohlmuth, Gee, Wall, SIAM J. Sci. Comput. 34 (2012) sec. 4.4.1 (quadratic faces).
///
/// Reference cells and node order are those of surface_element.hpp (MED's).
///
/// - 2D (SEG2, SEG3): the end nodes of the master cell are projected on the slave cell along
///   the slave normal, the end nodes of the slave cell on the master cell; the overlap is an
///   interval [a, b] of the slave parameter; Gauss points are placed linearly on it, each is
///   projected on the master cell along the slave normal at the point.
/// - 3D (TRIA3, TRIA6, QUAD4, QUAD8, any pairing): the auxiliary plane passes through the slave
///   cell's centre (reference centroid) with the slave normal there; the VERTICES of both cells
///   are projected on it along that normal (quadratic cells by their vertex polygon), the two
///   convex polygons are clipped (Sutherland-Hodgman, slivers below 1e-12 of the slave area
///   dropped), the clip polygon is split into triangles by a fan from its vertex centroid (a
///   deterministic split: never Delaunay), and a triangle rule exact to `degree` is placed on
///   each triangle; every point is projected back along the auxiliary normal on both cells.
/// - Weights are in the measure of the slave surface in the given coordinates (m or m^2): a
///   point's weight is the rule's weight times the area (length) of its triangle (segment) in
///   the plane, divided by |n_s(xi_s) . n_aux| (1 on a flat slave cell).
/// Integration cells follow both meshes, so on flat cells products of slave and master shape
/// functions up to `degree` are integrated exactly.
#include <vector>

#include "engine/mesh/cell_type.hpp"

namespace lunaster::engine::contact::mortar {

/// One point of the overlap of a slave cell and a master cell.
struct OverlapPoint {
  double xi_s[2] = {0.0, 0.0};  ///< reference coordinates on the slave cell
  double xi_m[2] = {0.0, 0.0};  ///< reference coordinates on the master cell
  double w = 0.0;               ///< weight in slave surface measure (m in 2D, m^2 in 3D)
};

/// Appends the points of the overlap of the slave cell (`st`, 3 coordinates per node in `sx`)
/// and the master cell (`mt`, `mx`) to `out`; the rule integrates polynomials of degree
/// `degree` exactly on each integration cell (2D: Gauss with ceil((degree+1)/2) points; 3D:
/// the smallest tabulated triangle rule of that degree). Returns the overlap's measure (sum
/// of the appended weights); 0 and nothing appended when the cells do not overlap, or do not
/// face each other (master normal . slave normal >= 0 at the slave centre).
double overlap_points(CellType st, const double* sx, CellType mt, const double* mx, int degree,
                      std::vector<OverlapPoint>& out);

/// Vertex share of the quadratic basis transformation (Popp et al. 2012): on TRIA6 and QUAD8
/// slave cells, N~_v = N_v + alpha * (sum of the mid-edge functions of the edges at v) and
/// N~_m = (1 - 2 alpha) N_m. Displacements then read u_v = u~_v at vertices and
/// u_m = alpha (u~_v1 + u~_v2) + (1 - 2 alpha) u~_m at the mid-edge node of edge v1-v2.
constexpr double kQuadraticAlpha = 0.2;

/// True when the slave type uses the transformation (TRIA6, QUAD8; not SEG3, whose plain dual
/// basis is well defined, nor the linear types).
bool transformed_slave(CellType type);

/// The mortar slave shape functions at xi: N~ (transformed) for TRIA6/QUAD8, N otherwise.
void slave_shape(CellType type, const double* xi, double* n);

/// The two vertices (local node numbers) of the edge that carries mid-edge node `local_node`
/// of a quadratic type; false for a vertex.
bool edge_vertices(CellType type, int local_node, int* v1, int* v2);

/// Dual basis coefficients of a slave cell on the part of it that `points` integrate
/// (their xi_s and w; the cell's own Jacobian is already in w): with
/// Me_ij = sum_p w N~_i N~_j and De = diag(sum_p w N~_i), A = De Me^-1 (n x n, row-major, n
/// the cell's node count) and Phi_i = sum_j A_ij N~_j, so that sum_p w Phi_i N~_j = delta_ij
/// De_ii. A node with De_ii = 0 (to round-off: the axis vertex of an AXIS SEG3) gets Phi_i = 0.
/// Returns false (A untouched) when Me is singular to working precision or some De_ii is
/// negative: the covered part is too small to carry multipliers.
bool dual_coefficients(CellType type, const std::vector<OverlapPoint>& points, double* a);

}  // namespace lunaster::engine::contact::mortar

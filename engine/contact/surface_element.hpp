#pragma once
/// Contact surface cells (SEG2/SEG3 in 2D, TRIA3/TRIA6/QUAD4/QUAD8 in 3D):
/// shape functions with first and second reference derivatives, point, tangents,
/// normal and surface Jacobian. Kept inside engine/contact because the
/// projection needs second derivatives (Newton on curved masters), which the
/// volume-element shape functions of engine/fe do not provide.
///
/// Reference cells and node order are MED's (= VTK's for these types):
/// SEG [-1,1] (ends then middle); TRIA (0,0),(1,0),(0,1) then mid-edges
/// 01, 12, 20; QUAD [-1,1]^2 corners counter-clockwise from (-1,-1) then
/// mid-edges 01, 12, 23, 30.
#include <array>
#include <unordered_map>
#include <vector>

#include "engine/mesh/cell_type.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::engine::contact {

/// Largest number of nodes of a contact surface cell (QUAD8).
constexpr int kMaxSurfaceNodes = 8;

/// True for the cell types handled as contact surfaces.
bool is_surface_type(CellType type);
/// Number of nodes of a surface type (asserts is_surface_type).
int surface_n_nodes(CellType type);
/// Number of vertex (corner) nodes.
int surface_n_vertices(CellType type);
/// Reference dimension: 1 for segments, 2 for faces.
int surface_ref_dim(CellType type);
/// Linear type on the vertices (SEG3 -> SEG2, TRIA6 -> TRIA3, QUAD8 -> QUAD4).
CellType linear_type(CellType type);
/// Topological dimension of any cell type (0 point, 1 segment, 2 face, 3 volume).
int topological_dim(CellType type);
/// Short name used in messages ("SEG2", "QUAD8" ...).
const char* surface_type_name(CellType type);
/// True for triangles (TRIA3, TRIA6).
bool is_triangle(CellType type);

/// Shape values n[a], first derivatives dn[a*2+k] = dN_a/dxi_k and second
/// derivatives d2n[a*3+m] with m = 0 (xi xi), 1 (xi eta), 2 (eta eta).
/// For segments only k = 0 / m = 0 are meaningful (the rest is zero).
/// Any output may be null.
void surface_shape(CellType type, const double* xi, double* n, double* dn, double* d2n);

/// Reference coordinates of a node of a surface type (2 values, eta = 0 on segments).
void surface_reference_node(CellType type, int local_node, double* xi);

/// Geometry of a surface cell at one reference point.
struct SurfacePoint {
  double x[3] = {0, 0, 0};          ///< position, m
  double t[2][3] = {{0, 0, 0}, {0, 0, 0}};  ///< tangents dx/dxi_k (t[1] = 0 on segments)
  double n[3] = {0, 0, 0};          ///< unit normal: 2D (t_y, -t_x)/|t|; 3D t0 x t1 / |t0 x t1|
  double jacobian = 0.0;            ///< |t| (2D) or |t0 x t1| (3D): length/area per reference unit
};

/// Evaluates the geometry at xi; `xyz` holds 3 coordinates per cell node.
/// A degenerate cell gives jacobian 0 and a zero normal (never NaN).
SurfacePoint surface_point(CellType type, const double* xyz, const double* xi);

/// Unit normals at the nodes of surface cells (surface_point's normal at each node of each cell):
/// at each node the sum of its cells' normals there, each turned to agree with the first one
/// summed (a skin's cells may be oriented either way), then normalised. A node whose normals
/// cancel gets a zero vector.
std::unordered_map<int, std::array<double, 3>> node_normals(const Mesh& mesh, const std::vector<int>& cells);

/// How far a reference point lies outside the reference cell (0 inside):
/// segments max(0,|xi|-1); triangles max(0,-xi,-eta,xi+eta-1); quads max(0,|xi|-1,|eta|-1).
double outside_distance(CellType type, const double* xi);
/// Moves a reference point to the nearest point of the reference cell.
void clamp_to_cell(CellType type, double* xi);

}  // namespace lunaster::engine::contact

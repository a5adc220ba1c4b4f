#pragma once
/// Cell orientation: detection of inverted cells, reorientation of clockwise
/// (2D) and mirrored (3D) cells, and outward orientation of boundary (skin) cells.
///
/// Conventions (the FE pressure code relies on them):
/// - A SEG2/SEG3 (n1, n2, ...) in the xy-plane has the normal (t_y, -t_x, 0)
///   with t = x(n2) - x(n1): the normal is on the RIGHT of the direction of
///   travel, so a counter-clockwise traversal of a 2D body gives outward normals.
/// - A TRIA3/TRIA6/QUAD4/QUAD8 face has the normal (x2 - x1) x (x3 - x1) for its
///   first three nodes (right-hand rule on the node order).
/// - A valid 2D cell lists its vertices counter-clockwise in the xy-plane; a
///   valid 3D cell follows the MED reference cells (cell_topology.hpp), so that
///   every face listed by `cell_faces` has an outward normal. LIRE_MAILLAGE
///   brings every cell to this orientation (`orient_cells`), so that the rest of
///   the code (ORIE_PEAU, ...) may rely on it.
#include <array>
#include <string>
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Indices of the cells of dimension `mesh.dim` (the "volume" cells: surfaces
/// in 2D) whose corner Jacobian is negative (inverted) or near zero
/// (degenerate, |J| < 1e-10 h^d) at any vertex. Lower-dimensional cells are not checked.
std::vector<int> find_inverted_cells(const Mesh& mesh);

/// The cells of `find_inverted_cells` that no reordering of their nodes can
/// make valid: a corner Jacobian near zero (collapsed cell) or corner Jacobians
/// of both signs (tangled, self-intersecting cell).
std::vector<int> find_tangled_cells(const Mesh& mesh);

/// Names of the cells returned by `find_inverted_cells`.
std::vector<std::string> inverted_cell_names(const Mesh& mesh);

/// Throws a DeckError naming `source` (the file read) and the first inverted
/// cells if `find_inverted_cells` finds any (for meshes that must already be
/// oriented, e.g. generated ones).
void check_cell_orientation(const Mesh& mesh, const std::string& source);

/// Reorients, once after reading, every volume cell whose corner Jacobian is
/// negative at every vertex: a 2D cell listed clockwise, or a 3D cell listed as
/// the mirror image of the MED reference cell. Its nodes are reordered by
/// `cell_mirror_permutation` (mid-side nodes follow their edges); cell indices,
/// names and groups are unchanged, and boundary cells keep their own node
/// order. Returns the reoriented cells. Throws a DeckError naming `source` and
/// the first cells if any is tangled or degenerate (`find_tangled_cells`);
/// then the mesh is left unchanged.
std::vector<int> orient_cells(Mesh& mesh, const std::string& source);

/// Signed measure of a cell, exact for straight-sided cells: length (1D),
/// area in the xy-plane (2D, positive when counter-clockwise; for faces in 3D
/// the unsigned area), volume (3D, positive for a valid MED cell).
double cell_measure(const Mesh& mesh, int cell);

/// Normal of a boundary cell (SEG in 2D, TRIA/QUAD in 3D) by the convention
/// above, not normalised, evaluated from its first vertices.
std::array<double, 3> boundary_normal(const Mesh& mesh, int cell);

/// Which way a boundary cell faces the cells of the mesh's dimension that hold all its vertices
/// (its "owners"): Outward / Inward when one cell holds it (its normal, by the convention above,
/// points out of / into that cell: the cell's face with the same vertices lists them in the same /
/// the reverse cyclic order; every volume cell is valid, as LIRE_MAILLAGE leaves them); Inner
/// when two or more hold it (a face inside the body: no outside); Loose when none does.
enum class BoundarySide { Outward, Inward, Inner, Loose };
struct BoundaryFacing {
  BoundarySide side = BoundarySide::Loose;
  int owner = -1;  ///< the first cell holding it (-1 when Loose)
  int other = -1;  ///< a second one (Inner only)
};

/// True for a cell that bounds the cells of a `mesh_dim`-D mesh: SEG2/SEG3 in 2D,
/// TRIA3/TRIA6/QUAD4/QUAD8 in 3D.
bool is_boundary_type(CellType type, int mesh_dim);

/// The facing of each of `boundary_cells` (cells for which is_boundary_type holds in a
/// mesh.dim-D mesh; InternalError otherwise), in their order. The owner of a face is looked for
/// among the cells around its first vertex: the cost is one pass over the mesh's cells and the
/// cells around each face.
std::vector<BoundaryFacing> boundary_facing(const Mesh& mesh, const std::vector<int>& boundary_cells);

/// ORIE_PEAU_2D / ORIE_PEAU_3D: reorders the nodes of each boundary cell
/// (SEG2/SEG3 in a 2D mesh, TRIA3/TRIA6/QUAD4/QUAD8 in a 3D mesh) so that its
/// normal points out of the single volume cell it bounds (the one that holds
/// all its vertices). Returns the number of cells whose order was reversed.
/// Throws DeckError if a cell has the wrong dimension, bounds no volume cell,
/// or bounds two (then it is not on the skin).
int orient_boundary_outward(Mesh& mesh, const std::vector<int>& boundary_cells);

}  // namespace lunaster::engine

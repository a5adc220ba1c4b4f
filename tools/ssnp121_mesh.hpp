#pragma once
/// Structured mesh generation for the SSNP121 geometry and unit blocks used by
/// patch tests. Engine-free of keywords: it only fills an engine::Mesh.
#include <array>
#include <string>
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::tools {

/// Element type and cell counts of one structured block.
struct BlockCells {
  engine::CellType type = engine::CellType::Quad4;  ///< volume (2D: surface) cell type
  std::array<int, 3> n{1, 1, 1};                    ///< cells along x, y, z (z unused in 2D)
};

/// Parses "quad8:11", "quad4:12x6", "hexa20:4x4x4" or "penta6:4" (n in every
/// direction). Throws DeckError on a bad spec or an unsupported type.
BlockCells parse_block_cells(const std::string& spec, int dim);

/// SSNP121 2D: upper block PLAQUE1 = [-1,1]x[0,1], lower PLAQUE2 = [-1,1]x[-1,0].
struct Ssnp121Options2d {
  BlockCells upper{engine::CellType::Quad4, {12, 12, 1}};
  BlockCells lower{engine::CellType::Quad4, {11, 11, 1}};
  bool glued = false;  ///< share interface nodes (needs equal types and counts)
  /// A third block PLAQUE3 = [-1,1]x[1,2] on top of the upper one, meshed apart (n[0] = 0: none).
  BlockCells top{engine::CellType::Quad4, {0, 0, 1}};
  /// x extent of both blocks (default -1..1); e.g. 0..1 for an axisymmetric section on the axis.
  double x0 = -1.0, x1 = 1.0;
};

/// Renames the nodes of a 2D SSNP121 mesh (two blocks, no top block) in the order in which
/// code_aster's GIBI script of the case creates its points: the corners a, b, c, d of PLAQUE1
/// and e, f, g, h of PLAQUE2 (N1..N8), then the inner points of the lines ab, bc, cd, da, ef,
/// fg, gh, he, each from its first point to its second, then the remaining nodes of PLAQUE1 and
/// of PLAQUE2, row by row from the interface. So the first 8 + the lines' names are those of
/// code_aster's mesh (its test decks name node N14, the middle of AB, with 12 cells on AB); the
/// inner nodes' names are lunaster's. DeckError for a mesh without PLAQUE1 and PLAQUE2.
void name_nodes_as_gibi_script(engine::Mesh& mesh);

/// SSNP121 3D: V1 = [0,1]^3 (lower), V2 = [0,1]^2 x [1,2] (upper).
struct Ssnp121Options3d {
  BlockCells v1{engine::CellType::Hexa20, {4, 4, 4}};
  BlockCells v2{engine::CellType::Hexa20, {4, 4, 4}};
  /// A third block V3 = [0,1]^2 x [2,3] on top of V2, meshed apart (n[0] = 0: none).
  BlockCells v3{engine::CellType::Hexa8, {0, 0, 0}};
  bool glued = false;
  /// Adds the faces x = 0 and x = 1 of V1 and V2 as face groups X0_V1, X1_V1, X0_V2, X1_V2
  /// (a load on the sides: the frictional patch test's shear).
  bool x_faces = false;
};

/// Unit block [0,1]^d for patch tests.
struct BlockOptions {
  BlockCells cells{engine::CellType::Hexa8, {3, 3, 3}};
  double distort = 0.0;  ///< interior vertices moved by up to distort * cell size per direction
  /// 2D only: the rectangle [lo[0], hi[0]] x [lo[1], hi[1]] instead of the unit square
  /// (axisymmetric sections: x is the radius).
  std::array<double, 2> lo{0.0, 0.0}, hi{1.0, 1.0};
};

/// Quarter of a ring fitted in a sleeve (plane strain Lame verification): the ring
/// a <= r <= b and the sleeve b <= r <= c, 0 <= theta <= pi/2, meshed independently
/// (nodes duplicated on r = b, so different arc counts give a non-matching interface).
/// n[0] = cells along the arc, n[1] = cells through the thickness. Vertices sit on
/// circles r = const and rays theta = const; QUAD8 mid-side nodes are placed at the
/// middle of the polar parameters, so arc edges are curved with all three nodes on
/// their circle. Nodes on x = 0 have x exactly 0, on y = 0 y exactly 0.
struct RingOptions {
  BlockCells ring{engine::CellType::Quad4, {12, 4, 1}};
  BlockCells sleeve{engine::CellType::Quad4, {9, 4, 1}};
  double a = 0.5, b = 0.75, c = 1.0;  ///< inner radius, interface radius, outer radius (m)
};

/// Groups: cells RING, SLEEVE; outward boundary cells INNER (ring, r=a), RING_OUT
/// (ring, r=b), X0_RING / Y0_RING (ring, x=0 / y=0), SLEEVE_IN (sleeve, r=b), OUTER
/// (sleeve, r=c), X0_SLEEVE / Y0_SLEEVE; node groups of the ring A_X (a,0) A_Y (0,a)
/// P_X (b,0) P_Y (0,b) and of the sleeve Q_X (b,0) Q_Y (0,b) C_X (c,0) C_Y (0,c).
/// Throws DeckError for a cell type other than QUAD4/QUAD8 or radii not 0 < a < b < c.
engine::Mesh make_ring_sleeve(const RingOptions& options);

/// Groups: cells PLAQUE1, PLAQUE2; boundary cells AB BC CD DA (upper) and EF FG
/// GH HE (lower), oriented outward (counter-clockwise traversal of each
/// block); node groups A B C D O (upper block) and E F G H (lower block). With
/// x0, x1: A = (x0, 0), B = (x1, 0), O = ((x0 + x1) / 2, 0) and so on. With a top block:
/// cells PLAQUE3, boundary cells IJ (y=1) JK KL (y=2) LI, nodes I J K L (x0 or x1, 1 or 2) and
/// P = (xm, 1), all of the top block.
engine::Mesh make_ssnp121_2d(const Ssnp121Options2d& options);

/// Groups: cells V1, V2; outward faces ENCAST (V1 z=0), SURESC (V1 z=1),
/// SURMAI (V2 z=1), SURCHA (V2 z=2); node groups A21..A24 (corners of SURESC, V1 nodes).
/// With a third block: cells V3, faces SURBA3 (V3 z=2) and SURCH3 (V3 z=3), node groups
/// A31..A34 (corners of SURBA3, V3 nodes).
engine::Mesh make_ssnp121_3d(const Ssnp121Options3d& options);

/// Groups: cells BLOCK; outward boundary cells LEFT (x=0), RIGHT (x=1),
/// BOTTOM (2D: y=0; 3D: z=0), TOP (2D: y=1; 3D: z=1), FRONT (3D: y=0), BACK
/// (3D: y=1); corner node groups C00.. (2D) / C000.. (3D), digits = coordinates
/// (2D with lo/hi: LEFT is x = lo[0], RIGHT x = hi[0], C10 the corner (hi[0], lo[1]) ...).
engine::Mesh make_block(const BlockOptions& options);

/// Rewrites the volume cells of `groups` (PLAQUE2, BLOCK ...) in mirror order
/// (clockwise in 2D) and reverses every boundary cell lying on one of them, as
/// Gmsh writes a surface meshed from a clockwise curve loop: meshes of the
/// same scene in the other orientation, for the tests of LIRE_MAILLAGE's
/// reorientation. Node numbering, cell numbering and groups are unchanged.
/// Throws DeckError for an unknown group or one holding no volume cell.
void mirror_cell_groups(engine::Mesh& mesh, const std::vector<std::string>& groups);

}  // namespace lunaster::tools

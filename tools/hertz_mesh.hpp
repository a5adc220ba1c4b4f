#pragma once
/// Meshes of Hertz contact scenes (lunaster-meshgen --hertz): a ball (2D: quarter disc,
/// 3D: quarter of the lower half of a sphere) of radius R resting on a block, touching it
/// at the single point O = (0,0[,0]), meshed independently (non-matching at the contact).
///
/// Geometry. 2D (x = r >= 0, y = axis; also read as a plane-strain cylinder section):
/// BALL = {x >= 0, y <= R, x^2 + (y-R)^2 <= R^2}, BLOCK = [0,W] x [-H,0].
/// 3D (z = axis, symmetry planes x = 0 and y = 0): BALL = {x, y >= 0, z <= R,
/// x^2 + y^2 + (z-R)^2 <= R^2}, BLOCK = [0,W] x [0,W] x [-H,0].
///
/// Construction. Each body is the image of a structured lattice in reference coordinates
/// s in [0,1]^d: a uniform core [0,s0]^d of m^d cells (cell size h0 at O), then K layers
/// between the squares (cubes) of sides s_k and s_k+1 = g s_k, each layer one cell thick
/// with m cells along each leg of the L (each face of the octant shell), so the cells grow
/// by g per layer and keep their shape (m = round(1/(G-1)) makes them about square).
/// The block maps s to (W s_x, -H s_y) [(W s_x, W s_y, -H s_z)]. For the ball the layers
/// are rounded progressively (equiangular square/cube-to-sphere blend, 0 at the core, 1
/// at the last layer) into a quarter disc (octant of a ball) of radius 2, which the
/// conformal map X = (0, 2R) + 4R (u, -(w+2)) / (u^2 + (w+2)^2) (the inversion in
/// (0,-2) followed by a reflection, same formula in 3D) carries onto the ball: the
/// symmetry lines (planes) stay symmetry lines, the reference plane w = 0 goes onto the
/// sphere, the reference sphere of radius 2 onto the top y = R (z = R), and near O the
/// map is R times the identity. Mid-side nodes are images of lattice mid-points, so the
/// quadratic edges on the sphere have their three nodes on it.
/// Grading G = 1: no layers; the block is a uniform lattice, the ball a core of half its
/// reference radius and layers of constant thickness h0 (quasi-uniform cells).
#include <string>

#include "engine/mesh/mesh.hpp"

namespace lunaster::tools {

struct HertzOptions {
  engine::CellType type = engine::CellType::Quad4;  ///< QUAD4/QUAD8/TRIA3/TRIA6 (2D), HEXA8/HEXA20 (3D)
  int n = 20;            ///< cells per radius at the contact: h0 = R / (n * refine)
  int refine = 1;
  double radius = 1.0;   ///< R (m)
  double width = 1.0;    ///< W (m)
  double height = 1.0;   ///< H (m)
  double grading = 1.0;  ///< G >= 1: cell size growth per layer away from O (1: uniform)
};

/// What the generator chose (printed by lunaster-meshgen, checked by the tests).
struct HertzLayout {
  double h0 = 0.0;      ///< cell size at O (both bodies)
  int m_ball = 0;       ///< core cells per direction (ball)
  int layers_ball = 0;  ///< K (ball)
  double g_ball = 1.0;  ///< actual growth per layer (reference lattice) of the ball
  int m_block[3]{0, 0, 0};
  int layers_block = 0;
  double g_block[3]{1.0, 1.0, 1.0};  ///< per axis (x, [y,] depth)
};

/// Groups. Cells: BALL, BLOCK; boundary cells (outward): BALL_SURF (the whole curved
/// boundary of the ball, contact side), BALL_TOP (flat top y = R / z = R), BLOCK_TOP (y = 0 /
/// z = 0), BLOCK_BOTTOM (y = -H / z = -H), BLOCK_SIDE (x = W [and y = W]); 2D: AXIS_BALL,
/// AXIS_BLOCK (x = 0); 3D: SYMX_BALL, SYMX_BLOCK (x = 0), SYMY_BALL, SYMY_BLOCK (y = 0).
/// Nodes: O_BALL, O_BLOCK (the contact point in each body), C_BALL (top of the ball on the
/// axis), D_BLOCK (bottom of the block on the axis).
/// Throws DeckError for a bad type, size, or a grading whose core of m cells of size h0
/// would not fit in a body.
engine::Mesh make_hertz(const HertzOptions& options, HertzLayout* layout = nullptr);

/// A 2D mesh lying in x >= 0 mirrored about x = 0: the nodes on the axis (|x| <= tol) kept once,
/// the others given an image named on from the last node ("N<n+1>" ...), every cell given its
/// image in reversed order (counter-clockwise again, boundary cells facing out), every group its
/// images; the cells on the axis and the groups made of them alone are dropped (inside now).
engine::Mesh mirrored_about_x0(const engine::Mesh& mesh, double tol);

}  // namespace lunaster::tools

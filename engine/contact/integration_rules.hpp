#pragma once
/// Integration rules on slave contact cells (the "contact points" of the
/// continuous method), after code_aster's INTEGRATION / ORDRE_INT (mmgaus).
/// "Exact to degree d": every polynomial of total degree <= d on the reference
/// cell is integrated exactly and some monomial of degree d + 1 is not
/// (tests/unit/contact/integration_rules_test.cpp checks both, per order):
///
/// | scheme (ORDRE_INT)          | SEG2 / SEG3 [-1,1]                    | TRIA3 / TRIA6 (area 1/2)                  | QUAD4 / QUAD8 [-1,1]^2           |
/// |-----------------------------|---------------------------------------|-------------------------------------------|----------------------------------|
/// | Auto (unused)               | SEG2 ends w 1: degree 1; SEG3 nodes 1/3,4/3,1/3 (Simpson): 3 | TRIA3 vertices 1/6: 1; TRIA6 6-point Gauss: 4 | QUAD4 corners: 1; QUAD8 3x3 Simpson: 3 |
/// | Gauss n (1..6, default 3)   | n Gauss-Legendre points: 2n-1         | tabulated 1,3,4,6,7,12 points: n          | n x n: 2n-1 (and Q_{2n-1})        |
/// | Simpson m (1..4, default 1) | composite, 2m+1 points: 3             | m^2 sub-triangles, each with vertices 1/40, mid-edges 1/15, centroid 9/40 (/ m^2); 7, 19, 37, 61 points: 3 | (2m+1)^2 tensor: 3 (and Q_3) |
/// | NewtonCotes n (3..8, def. 3)| closed, n+1 points: n odd n, n even n+1 | interpolatory on the P_n lattice: n     | (n+1)^2 tensor: as the segment   |
/// | Nodes (unused)              | SEG2 trapezoid, SEG3 two trapezoids: 1 | vertices (TRIA6: 4 trapezoids): 1        | nodes, positive weights: 1 (Q_1) |
///
/// Simpson on a triangle deliberately differs from mmgaus, which weights the
/// same lattice without centroids (vertices 1/30, mid-edges 4/30 of each
/// sub-triangle, 6, 15, 28, 45 points): exact for degree 1 only, so a uniform
/// pressure on a TRIA6 slave does not give the consistent nodal forces
/// (SSNP121 E with SIMPSON: LAGS_C 16.5 % off with ORDRE_INT=4, 49 % with 2).
/// Degree 3 per sub-cell is what Simpson gives on a segment and on the
/// quadrangle tensor grid, and it covers the TRIA6 shape functions (degree 2);
/// it does not integrate the products of two TRIA6 functions (degree 4) exactly,
/// which Gauss >= 4, NewtonCotes >= 4 and Auto do. NOEUD (degree 1) does not
/// integrate the TRIA6 or QUAD8 shape functions exactly.
///
/// `sub_elements` s > 1 splits the reference cell into s (segment), s^2
/// (triangle, quadrangle) equal sub-cells, applies the rule on each and merges
/// coincident points (weights added); the exact degree stays the same. Mapping of the seed's legacy names
/// (AFFE_CHAR_MECA/CONTACT INTEGRATION) chosen for lunaster, to be applied by
/// commands/: 'SIMPSON' -> Simpson order 1; 'SIMPSON1' -> Simpson order 2;
/// 'SIMPSON2' -> Simpson order 3 (the seed text: "trois sous-éléments");
/// 'NCOTES' -> NewtonCotes order 3; 'NCOTES1' -> NewtonCotes order 3 with
/// sub_elements 2; 'NCOTES2' -> NewtonCotes order 3 with sub_elements 3;
/// 'GAUSS' -> Gauss default; 'NOEUD' -> Nodes. The current syntax of
/// SSNP121 A (SIMPSON, ORDRE_INT=4) and H (NCOTES, ORDRE_INT=8) is passed as is.
/// Weights are in reference measure: they sum to 2 (segment), 1/2
/// (triangle) or 4 (quadrangle).
#include <vector>

#include "engine/contact/contact_definition.hpp"
#include "engine/mesh/cell_type.hpp"

namespace lunaster::engine::contact {

/// One integration point on the reference slave cell.
struct ContactQuadPoint {
  double xi[2] = {0.0, 0.0};
  double weight = 0.0;
};

/// Valid ORDRE_INT range of a scheme ({0,0} when the order is unused).
struct OrderRange { int min, max, default_order; };
OrderRange integration_order_range(IntegrationScheme scheme);

/// The rule on a slave cell type (SEG2/3, TRIA3/6, QUAD4/8). `order` 0 takes
/// the scheme default. Throws DeckError for an order outside the scheme's range.
std::vector<ContactQuadPoint> contact_integration_rule(CellType type, IntegrationScheme scheme, int order,
                                                       int sub_elements = 1);

/// Closed Newton-Cotes weights of degree n (1..8) on [-1,1] (n+1 points,
/// exact rationals; degree 8 has negative weights).
std::vector<double> newton_cotes_weights(int degree);

/// Interpolatory weights on the triangle lattice (i/n, j/n), i+j <= n, in the
/// order j-major (j = 0 row first, i increasing); reference area 1/2.
std::vector<ContactQuadPoint> triangle_newton_cotes(int degree);

}  // namespace lunaster::engine::contact

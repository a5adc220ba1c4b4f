#pragma once
/// Integration rules on slave contact cells (the "contact points" of the
/// continuous method), after code_aster's INTEGRATION / ORDRE_INT (mmgaus):
///
/// | scheme      | order (ORDRE_INT)        | segment [-1,1]                       | triangle / quadrangle          |
/// |-------------|--------------------------|--------------------------------------|--------------------------------|
/// | Auto        | unused                   | SEG2 ends (w 1); SEG3 nodes 1/3,1/3,4/3 | TRIA3 vertices 1/6; TRIA6 6-pt Gauss; QUAD4 corners 1; QUAD8 3x3 Simpson |
/// | Gauss       | 1..6 (default 3) points  | Gauss-Legendre                       | tabulated 1,3,4,6,7,12 pts / n x n |
/// | Simpson     | 1..4 (default 1) subdivisions | composite Simpson, 2m+1 points  | composite (6,15,28,45) / tensor (2m+1)^2 |
/// | NewtonCotes | 3..8 (default 3) degree  | closed Newton-Cotes, n+1 points      | interpolatory on the P_n lattice / tensor |
/// | Nodes       | unused                   | nodes, trapezoid                     | nodes, positive weights        |
///
/// `sub_elements` s > 1 splits the reference cell into s (segment), s^2
/// (triangle, quadrangle) equal sub-cells, applies the rule on each and merges
/// coincident points (weights added). Mapping of the seed's legacy names
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

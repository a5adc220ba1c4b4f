#pragma once
/// Quadrature rules on reference cells.
#include <vector>

#include "engine/mesh/cell_type.hpp"

namespace lunaster::engine {

struct QuadraturePoint {
  double xi[3] = {0.0, 0.0, 0.0};
  double weight = 0.0;
};

/// Full-integration rule used for the stiffness of a cell type (e.g. 2x2 for
/// QUAD4, 3x3 for QUAD8, 3x3x3 for HEXA20, 8 points for PENTA15 ...), and for
/// pressure loads on boundary cells.
const std::vector<QuadraturePoint>& full_integration(CellType type);

/// Gauss-Legendre rule with n points on [-1,1] (n = 1..10).
std::vector<QuadraturePoint> gauss_legendre(int n);

}  // namespace lunaster::engine

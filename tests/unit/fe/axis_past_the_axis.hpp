#pragma once
// A TRIA6 whose mid-side node pulls an edge past the axis (x < 0): every node but one at x >= 0,
// and an integration point at r <= 0, which an axisymmetric model refuses (tests/unit/fe/axis_test.cpp,
// and tests/unit/commands/failures_test.cpp for the deck's words).
#include "engine/mesh/mesh.hpp"

namespace lunaster::engine::test {

inline Mesh tria6_past_the_axis() {
  Mesh mesh;
  mesh.dim = 2;
  mesh.coords = {0, 0, 0, 0.1, 0, 0, 0, 1, 0, 0.05, 0, 0, 0.05, 0.5, 0, -0.4, 0.5, 0};
  mesh.node_names = {"N1", "N2", "N3", "N4", "N5", "N6"};
  mesh.cell_types = {CellType::Tria6};
  mesh.cell_nodes = {0, 1, 2, 3, 4, 5};
  mesh.cell_offsets = {0, 6};
  mesh.cell_names = {"M1"};
  return mesh;
}

}  // namespace lunaster::engine::test

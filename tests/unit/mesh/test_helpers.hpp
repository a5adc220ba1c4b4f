#pragma once
// Shared helpers for the mesh unit tests: reference cells in MED order.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/mesh/cell_topology.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::engine::testing {

/// Vertex coordinates of the MED reference cell of a linear type.
inline std::vector<std::array<double, 3>> reference_vertices(CellType linear) {
  switch (linear) {
    case CellType::Point1: return {{0, 0, 0}};
    case CellType::Seg2: return {{0, 0, 0}, {1, 0, 0}};
    case CellType::Tria3: return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    case CellType::Quad4: return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    case CellType::Tetra4: return {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
    case CellType::Pyram5: return {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}, {0.5, 0.5, 1}};
    case CellType::Penta6: return {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 1}, {1, 0, 1}};
    case CellType::Hexa8:
      return {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}};
    default: return {};
  }
}

/// All node coordinates of the reference cell (mid-side nodes at edge midpoints).
inline std::vector<std::array<double, 3>> reference_nodes(CellType type) {
  auto nodes = reference_vertices(linear_type(type));
  const auto verts = nodes;
  for (const auto& [a, b] : cell_mid_edges(type))
    nodes.push_back({0.5 * (verts[a][0] + verts[b][0]), 0.5 * (verts[a][1] + verts[b][1]),
                     0.5 * (verts[a][2] + verts[b][2])});
  return nodes;
}

/// Adds the reference cell of `type`, shifted by `offset`, with fresh nodes; returns the cell.
inline int add_reference_cell(Mesh& mesh, CellType type, const std::array<double, 3>& offset = {0, 0, 0}) {
  std::vector<int> nodes;
  for (const auto& p : reference_nodes(type))
    nodes.push_back(mesh.add_node(p[0] + offset[0], p[1] + offset[1], p[2] + offset[2]));
  return mesh.add_cell(type, nodes);
}

/// A fresh scratch folder under the build tree.
inline std::string scratch_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(LUNASTER_BINARY_DIR) / "test-scratch" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline const std::vector<CellType>& all_cell_types() { return cell_types_in_med_order(); }

}  // namespace lunaster::engine::testing

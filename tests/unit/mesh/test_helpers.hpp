#pragma once
// Shared helpers for the mesh unit tests: reference cells in MED order.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/io/med_reader.hpp"
#include "engine/io/med_writer.hpp"
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

/// Writes `m` as `<scratch_dir(name)>/<name>.med` and reads it back: coordinates, cells and
/// groups must come back unchanged.
inline void expect_med_round_trip(const Mesh& m, const std::string& name) {
  const std::string path = scratch_dir(name) + "/" + name + ".med";
  write_med(path, m);
  const Mesh r = read_med(path);
  ASSERT_EQ(r.n_nodes(), m.n_nodes());
  EXPECT_EQ(r.coords, m.coords);
  EXPECT_EQ(r.cell_types, m.cell_types);
  EXPECT_EQ(r.cell_nodes, m.cell_nodes);
  EXPECT_EQ(r.cell_groups, m.cell_groups);
  EXPECT_EQ(r.node_groups, m.node_groups);
}

inline const std::vector<CellType>& all_cell_types() { return cell_types_in_med_order(); }

/// A reflection of each 2D/3D cell type written out by hand, independently of
/// `cell_mirror_permutation` (which it must differ from): `nodes[perm[i]]`
/// lists a valid cell as its mirror image, mid-side nodes on their edges.
/// TRIA/QUAD/TETRA/PYRAM swap vertices 0 and 1 (and 2, 3 for QUAD/PYRAM);
/// PENTA/HEXA swap their bottom and top faces.
inline const std::vector<int>& hand_written_reflection(CellType type) {
  static const std::vector<int> tria3{1, 0, 2}, tria6{1, 0, 2, 3, 5, 4}, quad4{1, 0, 3, 2},
      quad8{1, 0, 3, 2, 4, 7, 6, 5}, tetra4{1, 0, 2, 3}, tetra10{1, 0, 2, 3, 4, 6, 5, 8, 7, 9},
      pyram5{1, 0, 3, 2, 4}, penta6{3, 4, 5, 0, 1, 2}, penta15{3, 4, 5, 0, 1, 2, 9, 10, 11, 6, 7, 8, 12, 13, 14},
      hexa8{4, 5, 6, 7, 0, 1, 2, 3}, hexa20{4, 5, 6, 7, 0, 1, 2, 3, 12, 13, 14, 15, 8, 9, 10, 11, 16, 17, 18, 19},
      none;
  switch (type) {
    case CellType::Tria3: return tria3;
    case CellType::Tria6: return tria6;
    case CellType::Quad4: return quad4;
    case CellType::Quad8: return quad8;
    case CellType::Tetra4: return tetra4;
    case CellType::Tetra10: return tetra10;
    case CellType::Pyram5: return pyram5;
    case CellType::Penta6: return penta6;
    case CellType::Penta15: return penta15;
    case CellType::Hexa8: return hexa8;
    case CellType::Hexa20: return hexa20;
    default: return none;
  }
}

/// Reorders the nodes of `cell`: new[i] = old[perm[i]].
inline void permute_cell(Mesh& mesh, int cell, const std::vector<int>& perm) {
  int* target = &mesh.cell_nodes[mesh.cell_offsets[cell]];
  const std::vector<int> old(target, target + mesh.cell_n_nodes(cell));
  for (size_t k = 0; k < perm.size(); ++k) target[k] = old[perm[k]];
}

/// Largest distance between a mid-side node of `cell` and the midpoint of the
/// edge it belongs to (0 for a cell whose mid-side nodes follow their edges).
inline double mid_side_offset(const Mesh& mesh, int cell) {
  const CellType type = mesh.cell_types[cell];
  const int nv = cell_info(type).n_vertices;
  double worst = 0.0;
  for (size_t k = 0; k < cell_mid_edges(type).size(); ++k) {
    const auto [a, b] = cell_mid_edges(type)[k];
    const double* m = mesh.node(mesh.cell(cell)[nv + static_cast<int>(k)]);
    const double* pa = mesh.node(mesh.cell(cell)[a]);
    const double* pb = mesh.node(mesh.cell(cell)[b]);
    for (int d = 0; d < 3; ++d) worst = std::max(worst, std::abs(m[d] - 0.5 * (pa[d] + pb[d])));
  }
  return worst;
}

}  // namespace lunaster::engine::testing

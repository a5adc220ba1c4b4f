#pragma once
/// The mesh: nodes, cells, names and groups. Plain data with lookup helpers;
/// readers (engine/io) and the mesh generator fill it, everything else reads it.
#include <algorithm>
#include <string>
#include <unordered_map>
#include <map>
#include <vector>

#include "engine/mesh/cell_type.hpp"

namespace lunaster::engine {

class Mesh {
 public:
  /// Space dimension: 2 if every z coordinate is zero and no 3D cell exists, else 3.
  int dim = 3;
  std::string name = "MAIL";  ///< mesh name (MED mesh name)
  /// One rank's part of a mesh in parts (engine/assembly/mesh_part.hpp, LIRE_MAILLAGE's
  /// PARTITIONNEUR): what a command finds or misses in it is decided over the ranks.
  bool is_part = false;

  // ---- nodes ----
  std::vector<double> coords;            ///< 3 per node (z = 0 in 2D), metres
  std::vector<std::string> node_names;   ///< "N1".. unless the file names them

  // ---- cells (CSR connectivity, MED node order) ----
  std::vector<CellType> cell_types;
  std::vector<int> cell_offsets{0};      ///< size n_cells+1
  std::vector<int> cell_nodes;           ///< 0-based node indices
  std::vector<std::string> cell_names;   ///< "M1".. unless the file names them

  // ---- groups (sorted, unique, 0-based indices) ----
  std::map<std::string, std::vector<int>> node_groups;
  std::map<std::string, std::vector<int>> cell_groups;

  int n_nodes() const { return static_cast<int>(node_names.size()); }
  int n_cells() const { return static_cast<int>(cell_types.size()); }
  const double* node(int i) const { return &coords[3 * static_cast<size_t>(i)]; }
  int cell_n_nodes(int c) const { return cell_offsets[c + 1] - cell_offsets[c]; }
  const int* cell(int c) const { return &cell_nodes[cell_offsets[c]]; }

  /// Appends a node / cell; names default to N<k> / M<k> (1-based) when empty.
  int add_node(double x, double y, double z, std::string name = {});
  int add_cell(CellType type, const std::vector<int>& nodes, std::string name = {});

  /// Index by name, or -1. Name maps are built lazily by `index_names()`.
  int find_node(const std::string& name) const;
  int find_cell(const std::string& name) const;
  void index_names() const;

  /// Adds to (or creates) a group; keeps it sorted and unique.
  void add_to_node_group(const std::string& group, const std::vector<int>& nodes);
  void add_to_cell_group(const std::string& group, const std::vector<int>& cells);

  /// Nodes of the given cells, sorted and unique.
  std::vector<int> nodes_of_cells(const std::vector<int>& cells) const;
  /// True when `cell` has each of `nodes[0..n)` among its nodes (a volume cell a face bounds).
  bool cell_holds(int cell, const int* nodes, int n) const {
    const int* own = this->cell(cell);
    const int count = cell_n_nodes(cell);
    for (int a = 0; a < n; ++a)
      if (std::find(own, own + count, nodes[a]) == own + count) return false;
    return true;
  }

  /// The given cells around each node, as compressed rows: node v's are
  /// positions[start[v] .. start[v+1]) in `cells` (cell ids: cells[position]), in the order of `cells`.
  struct NodeCells {
    std::vector<int> start;      ///< n_nodes + 1
    std::vector<int> positions;  ///< positions in the cell list
  };
  NodeCells node_cells(const std::vector<int>& cells) const;

  /// Sets `dim` from the coordinates and cell types.
  void detect_dimension();

 private:
  mutable std::unordered_map<std::string, int> node_index_;
  mutable std::unordered_map<std::string, int> cell_index_;
};

}  // namespace lunaster::engine

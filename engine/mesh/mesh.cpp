#include "engine/mesh/mesh.hpp"

#include <algorithm>

#include "engine/core/error.hpp"

namespace lunaster::engine {

namespace {

void merge_sorted_unique(std::vector<int>& target, const std::vector<int>& added) {
  target.insert(target.end(), added.begin(), added.end());
  std::sort(target.begin(), target.end());
  target.erase(std::unique(target.begin(), target.end()), target.end());
}

}  // namespace

int Mesh::add_node(double x, double y, double z, std::string name) {
  const int index = n_nodes();
  coords.push_back(x);
  coords.push_back(y);
  coords.push_back(z);
  if (name.empty()) name = "N" + std::to_string(index + 1);
  if (!node_index_.empty()) node_index_.emplace(name, index);
  node_names.push_back(std::move(name));
  return index;
}

int Mesh::add_cell(CellType type, const std::vector<int>& nodes, std::string name) {
  const CellInfo& info = cell_info(type);
  LUNASTER_ASSERT(static_cast<int>(nodes.size()) == info.n_nodes,
                  std::string(info.name) + " needs " + std::to_string(info.n_nodes) + " nodes, got " +
                      std::to_string(nodes.size()));
  for (int n : nodes) LUNASTER_ASSERT(n >= 0 && n < n_nodes(), "cell node index out of range");
  const int index = n_cells();
  cell_types.push_back(type);
  cell_nodes.insert(cell_nodes.end(), nodes.begin(), nodes.end());
  cell_offsets.push_back(static_cast<int>(cell_nodes.size()));
  if (name.empty()) name = "M" + std::to_string(index + 1);
  if (!cell_index_.empty()) cell_index_.emplace(name, index);
  cell_names.push_back(std::move(name));
  return index;
}

void Mesh::index_names() const {
  node_index_.clear();
  cell_index_.clear();
  node_index_.reserve(node_names.size());
  cell_index_.reserve(cell_names.size());
  for (size_t i = 0; i < node_names.size(); ++i) node_index_.emplace(node_names[i], static_cast<int>(i));
  for (size_t i = 0; i < cell_names.size(); ++i) cell_index_.emplace(cell_names[i], static_cast<int>(i));
}

int Mesh::find_node(const std::string& name) const {
  if (node_index_.size() != node_names.size()) index_names();
  const auto it = node_index_.find(name);
  return it == node_index_.end() ? -1 : it->second;
}

int Mesh::find_cell(const std::string& name) const {
  if (cell_index_.size() != cell_names.size()) index_names();
  const auto it = cell_index_.find(name);
  return it == cell_index_.end() ? -1 : it->second;
}

void Mesh::add_to_node_group(const std::string& group, const std::vector<int>& nodes) {
  merge_sorted_unique(node_groups[group], nodes);
}

void Mesh::add_to_cell_group(const std::string& group, const std::vector<int>& cells) {
  merge_sorted_unique(cell_groups[group], cells);
}

std::vector<int> Mesh::nodes_of_cells(const std::vector<int>& cells) const {
  std::vector<int> nodes;
  for (int c : cells) nodes.insert(nodes.end(), cell(c), cell(c) + cell_n_nodes(c));
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

Mesh::NodeCells Mesh::node_cells(const std::vector<int>& cells) const {
  NodeCells out;
  const int nn = n_nodes();
  out.start.assign(static_cast<size_t>(nn) + 1, 0);
  for (int c : cells)
    for (int a = 0, k = cell_n_nodes(c); a < k; ++a) ++out.start[cell(c)[a] + 1];
  for (int v = 0; v < nn; ++v) out.start[v + 1] += out.start[v];
  out.positions.resize(out.start[nn]);
  std::vector<int> fill(out.start.begin(), out.start.end() - 1);
  for (size_t i = 0; i < cells.size(); ++i)
    for (int a = 0, k = cell_n_nodes(cells[i]); a < k; ++a) out.positions[fill[cell(cells[i])[a]]++] = static_cast<int>(i);
  return out;
}

void Mesh::detect_dimension() {
  for (CellType t : cell_types) {
    if (cell_info(t).dim == 3) {
      dim = 3;
      return;
    }
  }
  for (int i = 0; i < n_nodes(); ++i) {
    if (coords[3 * static_cast<size_t>(i) + 2] != 0.0) {
      dim = 3;
      return;
    }
  }
  dim = 2;
}

}  // namespace lunaster::engine

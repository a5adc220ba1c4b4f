#include "engine/mesh/mesh_checks.hpp"

#include <algorithm>
#include <cmath>

namespace lunaster::engine {

std::vector<int> unreferenced_nodes(const Mesh& mesh) {
  std::vector<char> used(mesh.n_nodes(), 0);
  for (int node : mesh.cell_nodes)
    if (node >= 0 && node < mesh.n_nodes()) used[node] = 1;
  std::vector<int> out;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (!used[n]) out.push_back(n);
  return out;
}

std::vector<std::pair<int, int>> coincident_nodes(const Mesh& mesh, std::vector<int> nodes, double tolerance) {
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  std::sort(nodes.begin(), nodes.end(), [&](int a, int b) { return mesh.node(a)[0] < mesh.node(b)[0]; });
  std::vector<std::pair<int, int>> pairs;
  for (size_t i = 0; i < nodes.size(); ++i) {
    const double* p = mesh.node(nodes[i]);
    for (size_t j = i + 1; j < nodes.size(); ++j) {
      const double* q = mesh.node(nodes[j]);
      if (q[0] - p[0] > tolerance) break;
      if (std::abs(q[1] - p[1]) <= tolerance && std::abs(q[2] - p[2]) <= tolerance)
        pairs.emplace_back(std::min(nodes[i], nodes[j]), std::max(nodes[i], nodes[j]));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

double coincidence_tolerance(const Mesh& mesh, const std::vector<int>& cells) {
  double longest = 0.0;
  for (int c : cells) {
    const int* nodes = mesh.cell(c);
    const int n = mesh.cell_n_nodes(c);
    for (int k = 0; k < n; ++k) {
      const double* a = mesh.node(nodes[k]);
      const double* b = mesh.node(nodes[(k + 1) % n]);
      longest = std::max(longest, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
    }
  }
  return longest > 0.0 ? 1e-8 * longest : 1e-12;
}

std::vector<int> cells_repeating_a_node(const Mesh& mesh) {
  std::vector<int> out;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    std::vector<int> nodes(mesh.cell(c), mesh.cell(c) + mesh.cell_n_nodes(c));
    std::sort(nodes.begin(), nodes.end());
    if (std::adjacent_find(nodes.begin(), nodes.end()) != nodes.end()) out.push_back(c);
  }
  return out;
}

std::vector<std::pair<int, int>> duplicate_cells(const Mesh& mesh) {
  std::vector<std::pair<std::vector<int>, int>> keys(static_cast<size_t>(mesh.n_cells()));
  for (int c = 0; c < mesh.n_cells(); ++c) {
    auto& [nodes, cell] = keys[c];
    nodes.assign(mesh.cell(c), mesh.cell(c) + mesh.cell_n_nodes(c));
    std::sort(nodes.begin(), nodes.end());
    nodes.push_back(static_cast<int>(mesh.cell_types[c]));  // one type only
    cell = c;
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::pair<int, int>> out;
  for (size_t i = 0; i < keys.size();) {
    size_t j = i + 1;
    while (j < keys.size() && keys[j].first == keys[i].first) {
      out.emplace_back(keys[i].second, keys[j].second);
      ++j;
    }
    i = j;
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::pair<int, double>> flat_cells(const Mesh& mesh, double ratio) {
  std::vector<std::pair<int, double>> out;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const int* nodes = mesh.cell(c);
    const int n = mesh.cell_n_nodes(c);
    double shortest = HUGE_VAL, longest = 0.0;
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) {
        const double* p = mesh.node(nodes[a]);
        const double* q = mesh.node(nodes[b]);
        const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
        shortest = std::min(shortest, d2);
        longest = std::max(longest, d2);
      }
    if (n < 2 || longest <= 0.0) continue;
    if (const double r = std::sqrt(shortest / longest); r < ratio) out.emplace_back(c, r);
  }
  return out;
}

}  // namespace lunaster::engine

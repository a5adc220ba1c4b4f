/// DofMap: node-by-node numbering of displacement unknowns plus extra DOFs.
#include "engine/assembly/dof_map.hpp"

#include "engine/core/error.hpp"

namespace lunaster::engine {

const char* component_name(int component) {
  switch (component) {
    case DX: return "DX";
    case DY: return "DY";
    case DZ: return "DZ";
    case LAGS_C: return "LAGS_C";
    case LAGR_DX: return "LAGR_DX";
    case LAGR_DY: return "LAGR_DY";
    case LAGR_DZ: return "LAGR_DZ";
    default: return "?";
  }
}

DofMap::DofMap(const Mesh& mesh, const std::vector<int>& cells, int dim) : dim_(dim) {
  LUNASTER_ASSERT(dim == 2 || dim == 3, "DofMap: dim must be 2 or 3");
  const int n_nodes = static_cast<int>(mesh.coords.size() / 3);
  std::vector<unsigned char> used(n_nodes, 0);
  for (int c : cells) {
    const int* nodes = mesh.cell(c);
    for (int k = 0, n = mesh.cell_n_nodes(c); k < n; ++k) used[nodes[k]] = 1;
  }
  index_.assign(static_cast<size_t>(n_nodes) * N_COMPONENTS, -1);
  for (int node = 0; node < n_nodes; ++node) {
    if (!used[node]) continue;
    for (int k = 0; k < dim; ++k) {
      index_[static_cast<size_t>(node) * N_COMPONENTS + k] = n_dofs_++;
      eq_node_.push_back(node);
      eq_cmp_.push_back(k);
    }
  }
}

int DofMap::add(int node, int component) {
  LUNASTER_ASSERT(node >= 0 && node < n_nodes() && component >= 0 && component < N_COMPONENTS,
                  "DofMap::add: node or component out of range");
  int& slot = index_[static_cast<size_t>(node) * N_COMPONENTS + component];
  if (slot < 0) {
    slot = n_dofs_++;
    eq_node_.push_back(node);
    eq_cmp_.push_back(component);
  }
  return slot;
}

}  // namespace lunaster::engine

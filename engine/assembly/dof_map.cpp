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

void DofMap::add_nodes(int n_nodes) {
  LUNASTER_ASSERT(n_nodes >= this->n_nodes(), "DofMap::add_nodes: fewer nodes than mapped");
  index_.resize(static_cast<size_t>(n_nodes) * N_COMPONENTS, -1);
}

DofMap DofMap::renumbered(const std::vector<int>& new_of_old) const {
  LUNASTER_ASSERT(static_cast<int>(new_of_old.size()) == n_dofs_, "DofMap::renumbered: not one number per DOF");
  DofMap out = *this;
  for (int& eq : out.index_)
    if (eq >= 0) eq = new_of_old[eq];
  for (int e = 0; e < n_dofs_; ++e) {
    out.eq_node_[new_of_old[e]] = eq_node_[e];
    out.eq_cmp_[new_of_old[e]] = eq_cmp_[e];
  }
  return out;
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

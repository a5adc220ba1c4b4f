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
    case LAGS_F1: return "LAGS_F1";
    case LAGS_F2: return "LAGS_F2";
    default: return "?";
  }
}

int component_of_name(std::string_view name) {
  for (int c = 0; c < N_COMPONENTS; ++c)
    if (name == component_name(c)) return c;
  return -1;
}

namespace {
/// The order in which results list components.
constexpr int kListOrder[N_COMPONENTS] = {DX, DY, DZ, LAGS_C, LAGS_F1, LAGS_F2, LAGR_DX, LAGR_DY, LAGR_DZ};
}  // namespace

int DofMap::dof_named(int node, std::string_view name) const {
  const int c = component_of_name(name);
  if (c < 0 || node < 0 || node >= n_nodes()) return -1;
  return dof(node, c);
}

std::vector<int> DofMap::components() const {
  bool present[N_COMPONENTS] = {};
  for (int c : eq_cmp_) present[c] = true;
  std::vector<int> out;
  for (int c : kListOrder)
    if (present[c]) out.push_back(c);
  return out;
}

std::vector<int> DofMap::result_components() const {
  std::vector<int> out;
  for (int c : components())
    if (is_displacement(c) || is_contact_multiplier(c)) out.push_back(c);
  return out;
}

std::vector<std::string> DofMap::result_component_names() const {
  std::vector<std::string> out;
  for (int c : result_components()) out.emplace_back(component_name(c));
  return out;
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

#pragma once
/// Numbering of the unknowns: displacement components on the nodes of the
/// modelled cells, plus extra unknowns (the contact multipliers on slave nodes, the
/// multipliers of linear relations) added only where a deck asked for them.
#include <string>
#include <string_view>
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Component ids used across the engine.
/// LAGS_C is the normal contact multiplier of a slave node, LAGS_F1 and LAGS_F2 its
/// tangential (friction) multipliers along the node's first and second tangent.
/// LAGR_DX.. are the multipliers of linear relations between displacement components
/// (the mid-side ties of discrete contact on QUAD8 faces), carried by the tied node.
enum Component : int {
  DX = 0, DY = 1, DZ = 2, LAGS_C = 3, LAGR_DX = 4, LAGR_DY = 5, LAGR_DZ = 6, LAGS_F1 = 7, LAGS_F2 = 8,
  N_COMPONENTS = 9
};
/// True for DX, DY, DZ; false for the multipliers.
inline bool is_displacement(int component) { return component >= DX && component <= DZ; }
/// True for the contact multipliers LAGS_C, LAGS_F1, LAGS_F2 (reported with the displacements).
inline bool is_contact_multiplier(int component) {
  return component == LAGS_C || component == LAGS_F1 || component == LAGS_F2;
}
/// The component's name ("DX", "LAGS_C", "LAGS_F1" ...), "?" out of range.
const char* component_name(int component);
/// The id of a component name, or -1 when no component has it.
int component_of_name(std::string_view name);

class DofMap {
 public:
  DofMap() = default;
  /// Displacement DOFs (DX, DY[, DZ]) on every node of `cells`, numbered node by node.
  DofMap(const Mesh& mesh, const std::vector<int>& cells, int dim);

  int dim() const { return dim_; }
  int n_dofs() const { return n_dofs_; }
  int n_nodes() const { return static_cast<int>(index_.size() / N_COMPONENTS); }
  /// Global equation of (node, component), or -1 if that node has no such DOF.
  int dof(int node, int component) const { return index_[static_cast<size_t>(node) * N_COMPONENTS + component]; }
  /// Nodes appended to the map's mesh, without DOFs yet (a part with whole contact surfaces,
  /// mesh_part.hpp's SurfacePart: its nodes beyond the part's). `n_nodes` >= n_nodes().
  void add_nodes(int n_nodes);
  /// The same DOFs numbered `new_of_old` (equation e becomes new_of_old[e], a permutation).
  DofMap renumbered(const std::vector<int>& new_of_old) const;
  /// Adds a DOF (e.g. LAGS_C) to a node if absent; returns its equation.
  int add(int node, int component);
  /// Inverse map: node and component of an equation.
  int node_of(int eq) const { return eq_node_[eq]; }
  int component_of(int eq) const { return eq_cmp_[eq]; }

  /// Equation of a node's unknown named `name` ("LAGS_C", "LAGS_F1", "DX" ...), or -1 when the
  /// node has none (or no component has that name).
  int dof_named(int node, std::string_view name) const;
  /// The components some node carries, in the order results list them: DX, DY[, DZ], LAGS_C,
  /// LAGS_F1, LAGS_F2, then the relations' LAGR_DX...
  std::vector<int> components() const;
  /// The components a displacement result reports (DEPL): the displacements and the contact
  /// multipliers present, in the order of `components()`.
  std::vector<int> result_components() const;
  /// Names of `result_components()`.
  std::vector<std::string> result_component_names() const;

 private:
  int dim_ = 0;
  int n_dofs_ = 0;
  std::vector<int> index_;  ///< n_nodes * N_COMPONENTS
  std::vector<int> eq_node_, eq_cmp_;
};

}  // namespace lunaster::engine

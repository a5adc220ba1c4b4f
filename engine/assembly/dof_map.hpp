#pragma once
/// Numbering of the unknowns: displacement components on the nodes of the
/// modelled cells, plus extra unknowns (LAGS_C on contact slave nodes) added
/// only where a deck asked for them.
#include <string>
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Component ids used across the engine.
/// LAGR_DX.. are the multipliers of linear relations between displacement components
/// (the mid-side ties of discrete contact on QUAD8 faces), carried by the tied node.
enum Component : int { DX = 0, DY = 1, DZ = 2, LAGS_C = 3, LAGR_DX = 4, LAGR_DY = 5, LAGR_DZ = 6, N_COMPONENTS = 7 };
/// True for DX, DY, DZ; false for the multipliers.
inline bool is_displacement(int component) { return component >= DX && component <= DZ; }
const char* component_name(int component);

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

 private:
  int dim_ = 0;
  int n_dofs_ = 0;
  std::vector<int> index_;  ///< n_nodes * N_COMPONENTS
  std::vector<int> eq_node_, eq_cmp_;
};

}  // namespace lunaster::engine

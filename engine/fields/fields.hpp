#pragma once
/// Result fields: nodal fields (DEPL, SIGM_NOEU, CONT_NOEU ...) and fields
/// given at the nodes of each cell (SIGM_ELNO ...). Component names are
/// code_aster's (DX, DY, DZ, LAGS_C, SIXX ...): they are data, not keywords.
#include <map>
#include <string>
#include <vector>

#include "engine/mesh/cell_type.hpp"

namespace lunaster::engine {

/// Values at mesh nodes, one column per component. A component may be
/// undefined at some nodes (LAGS_C exists only on slave nodes).
struct NodalField {
  std::vector<std::string> components;
  int n_nodes = 0;
  std::vector<double> values;          ///< n_nodes * n_components, node-major
  std::vector<unsigned char> defined;  ///< same layout; 1 where a value exists

  NodalField() = default;
  NodalField(std::vector<std::string> cmps, int nodes);
  int n_components() const { return static_cast<int>(components.size()); }
  /// Column of a component, or -1.
  int component_index(const std::string& cmp) const;
  double value(int node, int cmp) const { return values[static_cast<size_t>(node) * components.size() + cmp]; }
  bool has(int node, int cmp) const { return defined[static_cast<size_t>(node) * components.size() + cmp] != 0; }
  void set(int node, int cmp, double v) {
    const size_t k = static_cast<size_t>(node) * components.size() + cmp;
    values[k] = v;
    defined[k] = 1;
  }
};

/// Values at the nodes of each cell (ELNO), in the cell's node order. Cells
/// that carry no value have zero rows.
struct ElnoField {
  std::vector<std::string> components;
  std::vector<int> cell_offsets{0};  ///< size n_cells+1, in rows (one row per cell node)
  std::vector<double> values;        ///< rows * n_components

  int n_components() const { return static_cast<int>(components.size()); }
  int component_index(const std::string& cmp) const;
  int n_cells() const { return static_cast<int>(cell_offsets.size()) - 1; }
  int n_rows(int cell) const { return cell_offsets[cell + 1] - cell_offsets[cell]; }
  double value(int cell, int local_node, int cmp) const {
    return values[(static_cast<size_t>(cell_offsets[cell]) + local_node) * components.size() + cmp];
  }
};

/// Where the integration points of a cell type lie (a MED localization): the reference cell's
/// nodes and the points' reference coordinates and weights, `dim` coordinates each.
struct PointLayout {
  int dim = 0;
  std::vector<double> nodes;    ///< n_nodes * dim, the cell type's node order
  std::vector<double> points;   ///< n_points * dim
  std::vector<double> weights;  ///< n_points
};

/// Values at the integration points of each cell (ELGA): the rows of a cell are its points, in
/// the order of its type's layout. Cells that carry no value have zero rows.
struct ElgaField : ElnoField {
  std::map<CellType, PointLayout> layouts;  ///< one per cell type carrying rows
};

/// One stored instant of a nonlinear result (numéro d'ordre, instant).
struct ResultStep {
  int nume_ordre = 0;
  double inst = 0.0;
  std::map<std::string, NodalField> nodal;  ///< "DEPL", "SIGM_NOEU", "CONT_NOEU" ...
  std::map<std::string, ElnoField> elno;    ///< "SIGM_ELNO", "SIEQ_ELNO" ...
  std::map<std::string, ElgaField> elga;    ///< "SIEF_ELGA", "VARI_ELGA" ...
};

}  // namespace lunaster::engine

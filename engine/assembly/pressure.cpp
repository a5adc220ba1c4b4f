/// Consistent nodal forces of loads spread over cells: a pressure on boundary cells and a
/// force density (per unit length of edges, area of faces or volume of the model's cells),
/// f_a = integral N_a t dS with one quadrature, the cell's full-integration rule:
/// - pressure: t dS = -p n dS, with n dS from the cell's own parametrisation:
///   2D SEG (n1 -> n2): n dS = (t_y, -t_x) dxi, t = dx/dxi;
///   3D faces: n dS = (dx/dxi x dx/deta) dxi deta, i.e. along (x2-x1) x (x3-x1).
///   A positive pressure pushes against the normal (into the body when the
///   normal is outward, as ORIE_PEAU makes it).
/// - force density F: t dS = F |J| dxi, |J| the length of dx/dxi (edges), the area of
///   dx/dxi x dx/deta (faces) or the volume of the Jacobian (volume cells); the normal's sign
///   does not enter.
/// Axisymmetric models (x = r): every measure is multiplied by r, per radian like the AXIS
/// elements, so a pressure stays a pressure, a force per length of meridian or per volume
/// stays one, and the nodal forces are per radian. A segment on the axis (r = 0) receives none.
#include "engine/assembly/assembly.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/fe/reference_element.hpp"
#include "engine/mesh/orientation.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {
namespace {

std::string cell_label(const Mesh& mesh, int cell) {
  return cell < static_cast<int>(mesh.cell_names.size()) ? mesh.cell_names[cell] : "#" + std::to_string(cell + 1);
}

[[noreturn]] void unmodelled_node(const Mesh& mesh, int node, const char* what) {
  const std::string name =
      node < static_cast<int>(mesh.node_names.size()) ? mesh.node_names[node] : "#" + std::to_string(node + 1);
  throw DeckError(std::string(what) + " on node " + name + ", which belongs to no modelled cell");
}

/// What one cell carries: a pressure (`pressure`, on a boundary cell) or a force density.
struct CellLoad {
  bool is_pressure = false;
  double pressure = 0.0;
  const double* force = nullptr;  ///< 3 components (the model's first `dim` are used)
  const char* what = "load";      ///< for messages: "pressure", "distributed force"
};

/// Adds the nodal forces of `load` on one cell.
void cell_load(const Mesh& mesh, int dim, int cell, const CellLoad& load, bool axisymmetric, const DofMap& dofs,
               Vector& f_ext) {
  const ReferenceElement& re = reference_element(mesh.cell_types[cell]);
  const int* nodes = mesh.cell(cell);
  const int nn = re.n_nodes, rd = re.dim;
  for (int q = 0; q < re.n_qp; ++q) {
    const double* n = &re.n[static_cast<size_t>(q) * nn];
    const double* dn = &re.dn[static_cast<size_t>(q) * nn * rd];
    double a[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};  // a[i] = dx/dxi_i
    for (int b = 0; b < nn; ++b) {
      const double* x = mesh.node(nodes[b]);
      for (int i = 0; i < rd; ++i)
        for (int k = 0; k < 3; ++k) a[i][k] += dn[b * rd + i] * x[k];
    }
    const double cross[3] = {a[0][1] * a[1][2] - a[0][2] * a[1][1], a[0][2] * a[1][0] - a[0][0] * a[1][2],
                             a[0][0] * a[1][1] - a[0][1] * a[1][0]};
    double t[3] = {0, 0, 0};  // load per unit reference measure
    if (load.is_pressure) {
      // n dS: (t_y, -t_x) for a 2D segment, a1 x a2 for a 3D face.
      const double ns[3] = {dim == 2 ? a[0][1] : cross[0], dim == 2 ? -a[0][0] : cross[1], dim == 2 ? 0.0 : cross[2]};
      for (int k = 0; k < 3; ++k) t[k] = -load.pressure * ns[k];
    } else {
      double measure = 0.0;
      if (rd == 1) measure = std::sqrt(a[0][0] * a[0][0] + a[0][1] * a[0][1] + a[0][2] * a[0][2]);
      else if (rd == 2) measure = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
      else measure = std::abs(cross[0] * a[2][0] + cross[1] * a[2][1] + cross[2] * a[2][2]);
      for (int k = 0; k < 3; ++k) t[k] = load.force[k] * measure;
    }
    double radius = 1.0;
    if (axisymmetric) {
      radius = 0.0;
      for (int b = 0; b < nn; ++b) radius += n[b] * mesh.node(nodes[b])[0];
    }
    for (int b = 0; b < nn; ++b) {
      const double s = n[b] * re.weight[q] * radius;
      for (int k = 0; k < dim; ++k) {
        const int eq = dofs.dof(nodes[b], k);
        if (eq < 0) unmodelled_node(mesh, nodes[b], load.what);
        f_ext(eq) += s * t[k];
      }
    }
  }
}

/// The cells of one load: each checked by `accept`, then integrated on this rank (with
/// `node_owner`: by the rank owning the cell's first node, every rank checking every cell so
/// that an error stops them all alike).
template <class Accept>
void assemble_cells(const Mesh& mesh, int dim, const std::vector<int>& cells, const CellLoad& load, const DofMap& dofs,
                    Vector& f_ext, bool axisymmetric, const std::vector<int>* node_owner, Accept accept) {
  if (f_ext.size() != dofs.n_dofs()) f_ext = Vector::Zero(dofs.n_dofs());
  const int me = node_owner ? parallel::rank() : 0;
  for (int cell : cells) {
    accept(cell);
    if (node_owner) {
      const int* nodes = mesh.cell(cell);
      for (int a = 0; a < mesh.cell_n_nodes(cell); ++a)
        for (int k = 0; k < dim; ++k)
          if (dofs.dof(nodes[a], k) < 0) unmodelled_node(mesh, nodes[a], load.what);
      if (std::max(0, (*node_owner)[nodes[0]]) != me) continue;
    }
    cell_load(mesh, dim, cell, load, axisymmetric, dofs, f_ext);
  }
}

}  // namespace

void assemble_pressure(const Mesh& mesh, int dim, const std::vector<int>& cells, double pressure,
                       const DofMap& dofs, Vector& f_ext, bool axisymmetric, const std::vector<int>* node_owner) {
  CellLoad load;
  load.is_pressure = true, load.pressure = pressure, load.what = "pressure";
  assemble_cells(mesh, dim, cells, load, dofs, f_ext, axisymmetric, node_owner, [&](int cell) {
    if (!is_boundary_type(mesh.cell_types[cell], dim))
      throw DeckError("pressure on cell " + cell_label(mesh, cell) + ": expected a boundary cell (" +
                      std::string(dim == 2 ? "SEG2/SEG3" : "TRIA3/TRIA6/QUAD4/QUAD8") + ")");
  });
}

void assemble_distributed_force(const Mesh& mesh, int dim, const std::vector<int>& cells, int cells_dim,
                                const std::array<double, 3>& force, const DofMap& dofs, Vector& f_ext,
                                bool axisymmetric, const std::vector<int>* node_owner) {
  CellLoad load;
  load.force = force.data(), load.what = "distributed force";
  assemble_cells(mesh, dim, cells, load, dofs, f_ext, axisymmetric, node_owner, [&](int cell) {
    const CellType type = mesh.cell_types[cell];
    if (!has_shape_functions(type) || cell_dim(type) != cells_dim)
      throw DeckError("distributed force on cell " + cell_label(mesh, cell) + ": expected a cell of dimension " +
                      std::to_string(cells_dim));
  });
}

}  // namespace lunaster::engine

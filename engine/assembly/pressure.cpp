/// Consistent nodal forces of a pressure on boundary cells:
/// f_a = -p * integral N_a n dS, with n dS from the cell's own parametrisation:
/// 2D SEG (n1 -> n2): n dS = (t_y, -t_x) dxi, t = dx/dxi;
/// 3D faces: n dS = (dx/dxi x dx/deta) dxi deta, i.e. along (x2-x1) x (x3-x1).
/// A positive pressure pushes against the normal (into the body when the
/// normal is outward, as ORIE_PEAU makes it).
/// Axisymmetric models (x = r): dS = r dl per radian, the measure of the AXIS
/// elements, so a pressure stays a pressure and the forces are per radian. A
/// segment lying on the axis (r = 0) has no area and receives no force.
#include "engine/assembly/assembly.hpp"

#include <algorithm>
#include <string>

#include "engine/core/error.hpp"
#include "engine/fe/reference_element.hpp"
#include "engine/mesh/orientation.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {
namespace {

[[noreturn]] void unmodelled_node(const Mesh& mesh, int node) {
  const std::string name =
      node < static_cast<int>(mesh.node_names.size()) ? mesh.node_names[node] : "#" + std::to_string(node + 1);
  throw DeckError("pressure on node " + name + ", which belongs to no modelled cell");
}

/// Adds the pressure forces of one boundary cell.
void cell_pressure(const Mesh& mesh, int dim, int cell, double pressure, bool axisymmetric, const DofMap& dofs,
                   Vector& f_ext) {
  const CellType type = mesh.cell_types[cell];
  const ReferenceElement& re = reference_element(type);
  const int* nodes = mesh.cell(cell);
  const int nn = re.n_nodes, rd = re.dim;
  for (int q = 0; q < re.n_qp; ++q) {
    const double* n = &re.n[static_cast<size_t>(q) * nn];
    const double* dn = &re.dn[static_cast<size_t>(q) * nn * rd];
    double a1[3] = {0, 0, 0}, a2[3] = {0, 0, 0};
    for (int a = 0; a < nn; ++a) {
      const double* x = mesh.node(nodes[a]);
      for (int k = 0; k < 3; ++k) {
        a1[k] += dn[a * rd] * x[k];
        if (rd == 2) a2[k] += dn[a * rd + 1] * x[k];
      }
    }
    double ns[3];
    if (dim == 2) {
      ns[0] = a1[1], ns[1] = -a1[0], ns[2] = 0.0;
    } else {
      ns[0] = a1[1] * a2[2] - a1[2] * a2[1];
      ns[1] = a1[2] * a2[0] - a1[0] * a2[2];
      ns[2] = a1[0] * a2[1] - a1[1] * a2[0];
    }
    double radius = 1.0;
    if (axisymmetric) {
      radius = 0.0;
      for (int a = 0; a < nn; ++a) radius += n[a] * mesh.node(nodes[a])[0];
    }
    for (int a = 0; a < nn; ++a) {
      const double s = -pressure * n[a] * re.weight[q] * radius;
      for (int k = 0; k < dim; ++k) {
        const int eq = dofs.dof(nodes[a], k);
        if (eq < 0) unmodelled_node(mesh, nodes[a]);
        f_ext(eq) += s * ns[k];
      }
    }
  }
}

}  // namespace

void assemble_pressure(const Mesh& mesh, int dim, const std::vector<int>& cells, double pressure,
                       const DofMap& dofs, Vector& f_ext, bool axisymmetric, const std::vector<int>* node_owner) {
  if (f_ext.size() != dofs.n_dofs()) f_ext = Vector::Zero(dofs.n_dofs());
  const int me = node_owner ? parallel::rank() : 0;
  for (int cell : cells) {
    if (!is_boundary_type(mesh.cell_types[cell], dim)) {
      const std::string name = cell < static_cast<int>(mesh.cell_names.size()) ? mesh.cell_names[cell]
                                                                                  : "#" + std::to_string(cell + 1);
      throw DeckError("pressure on cell " + name + ": expected a boundary cell (" +
                      std::string(dim == 2 ? "SEG2/SEG3" : "TRIA3/TRIA6/QUAD4/QUAD8") + ")");
    }
    if (node_owner) {
      // Every rank checks every cell (an error stops them all alike); the rank owning the
      // cell's first node integrates it.
      const int* nodes = mesh.cell(cell);
      for (int a = 0; a < mesh.cell_n_nodes(cell); ++a)
        for (int k = 0; k < dim; ++k)
          if (dofs.dof(nodes[a], k) < 0) unmodelled_node(mesh, nodes[a]);
      if (std::max(0, (*node_owner)[nodes[0]]) != me) continue;
    }
    cell_pressure(mesh, dim, cell, pressure, axisymmetric, dofs, f_ext);
  }
}

}  // namespace lunaster::engine

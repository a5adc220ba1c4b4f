#include "engine/contact/contact_common.hpp"

#include <algorithm>
#include <cmath>

#include "engine/contact/surface_element.hpp"

namespace lunaster::engine::contact {

std::string cell_label(const Mesh& mesh, int cell) {
  if (cell >= 0 && cell < static_cast<int>(mesh.cell_names.size())) return mesh.cell_names[cell];
  return "#" + std::to_string(cell);
}

std::string node_label(const Mesh& mesh, int node) {
  if (node >= 0 && node < static_cast<int>(mesh.node_names.size())) return mesh.node_names[node];
  return "#" + std::to_string(node);
}

std::vector<double> current_coordinates(const Mesh& mesh, const DofMap& dofs, int dim, const Vector& u) {
  std::vector<double> xyz(mesh.coords);
  const int n = std::min(static_cast<int>(xyz.size() / 3), dofs.n_nodes());
  for (int node = 0; node < n; ++node)
    for (int k = 0; k < dim; ++k) {
      const int eq = dofs.dof(node, k);
      if (eq >= 0 && eq < u.size()) xyz[3 * static_cast<size_t>(node) + k] += u[eq];
    }
  return xyz;
}

double geometric_residual(const std::vector<int>& nodes, const DofMap& dofs, int dim, const Vector& u,
                          const Vector& u_before) {
  double du_max = 0.0, u_max = 0.0;
  for (int node : nodes) {
    double du2 = 0.0, u2 = 0.0;
    for (int k = 0; k < dim; ++k) {
      const int eq = dofs.dof(node, k);
      if (eq < 0) continue;
      const double prev = eq < u_before.size() ? u_before[eq] : 0.0;
      du2 += (u[eq] - prev) * (u[eq] - prev);
      u2 += u[eq] * u[eq];
    }
    du_max = std::max(du_max, std::sqrt(du2));
    u_max = std::max(u_max, std::sqrt(u2));
  }
  return u_max > 0.0 ? du_max / u_max : 0.0;
}

double smallest_edge(const Mesh& mesh, const std::vector<int>& cells) {
  double h = 1e300;
  for (int c : cells) {
    const CellType t = mesh.cell_types[c];
    const int nv = surface_n_vertices(t);
    const int n_edges = nv == 2 ? 1 : nv;
    for (int e = 0; e < n_edges; ++e) {
      const double* a = mesh.node(mesh.cell(c)[e]);
      const double* b = mesh.node(mesh.cell(c)[(e + 1) % nv]);
      h = std::min(h, std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                (a[2] - b[2]) * (a[2] - b[2])));
    }
  }
  return h;
}

std::vector<std::string> contact_state_components(int dim, bool pressure, bool friction) {
  std::vector<std::string> cmps = {"CONT", "JEU", "RN", "RNX", "RNY"};
  if (dim == 3) cmps.push_back("RNZ");
  if (pressure) cmps.push_back("PRES");
  if (!friction) return cmps;
  for (const char* c : {"GLIX", "GLIY", "GLI"}) cmps.push_back(c);
  for (const char* prefix : {"RTA", "RTG", "R"}) {
    const std::string p = prefix;
    cmps.push_back(p + "X"), cmps.push_back(p + "Y");
    if (dim == 3) cmps.push_back(p + "Z");
  }
  cmps.push_back("R");
  return cmps;
}

void set_friction_components(NodalField& field, int node, int dim, int status, const double* slip,
                             const double* tangential, const double* normal) {
  const int first = field.n_components() - (3 + 3 * dim + 1);
  field.set(node, 0, status);
  field.set(node, first, slip[0]);
  field.set(node, first + 1, dim == 3 ? slip[1] : 0.0);
  field.set(node, first + 2, std::sqrt(slip[0] * slip[0] + (dim == 3 ? slip[1] * slip[1] : 0.0)));
  const int stick = first + 3, slide = stick + dim, whole = slide + dim;
  double r2 = 0.0;
  for (int k = 0; k < dim; ++k) {
    field.set(node, (status == 2 ? slide : stick) + k, tangential[k]);
    const double r = normal[k] + tangential[k];
    field.set(node, whole + k, r);
    r2 += r * r;
  }
  field.set(node, whole + dim, std::sqrt(r2));
}

NodalField nodal_contact_field(const std::vector<NodalContactState>& states, int n_nodes, int dim, bool friction) {
  const std::vector<std::string> cmps = contact_state_components(dim, true, friction);
  NodalField field(cmps, n_nodes);
  const int pres = 3 + dim;
  for (const auto& s : states) {
    const double* f = s.force;
    field.set(s.node, 0, s.active ? 1.0 : 0.0);
    field.set(s.node, 1, s.gap);
    field.set(s.node, 2, std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
    for (int k = 0; k < dim; ++k) field.set(s.node, 3 + k, f[k]);
    field.set(s.node, pres, s.pressure);
    if (friction) set_friction_components(field, s.node, dim, s.active ? s.status : 0, s.slip, s.tangential, s.force);
  }
  return field;
}

}  // namespace lunaster::engine::contact

/// ELGA fields from the points' history (point_fields.hpp).
#include "engine/assembly/point_fields.hpp"

#include <algorithm>
#include <string>

#include "engine/assembly/green_lagrange.hpp"
#include "engine/core/error.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "engine/fe/quadrature.hpp"
#include "engine/fe/reference_element.hpp"
#include "engine/fe/shape.hpp"

namespace lunaster::engine {
namespace {

/// The reference nodes and the full-integration points of a cell type (reference_element's).
PointLayout point_layout(CellType type) {
  PointLayout layout;
  layout.dim = cell_dim(type);
  for (int a = 0; a < cell_n_nodes(type); ++a) {
    double xi[3] = {0.0, 0.0, 0.0};
    reference_node(type, a, xi);
    layout.nodes.insert(layout.nodes.end(), xi, xi + layout.dim);
  }
  for (const QuadraturePoint& p : full_integration(type)) {
    layout.points.insert(layout.points.end(), p.xi, p.xi + layout.dim);
    layout.weights.push_back(p.weight);
  }
  return layout;
}

/// An ELGA field of `n_components` columns over the cells with points, each row from `row`.
template <class Row>
ElgaField points_field(const FeModel& model, const MaterialStates& states, std::vector<std::string> components,
                       Row&& row) {
  const Mesh& mesh = *model.mesh;
  LUNASTER_ASSERT(states.n_cells() == mesh.n_cells(), "ELGA field: states of another mesh");
  ElgaField f;
  f.components = std::move(components);
  const int nc = f.n_components();
  f.cell_offsets.assign(mesh.n_cells() + 1, 0);
  for (int c = 0; c < mesh.n_cells(); ++c) {
    f.cell_offsets[c + 1] = f.cell_offsets[c] + states.n_points(c);
    if (states.n_points(c) > 0 && !f.layouts.count(mesh.cell_types[c]))
      f.layouts.emplace(mesh.cell_types[c], point_layout(mesh.cell_types[c]));
  }
  f.values.assign(static_cast<size_t>(f.cell_offsets.back()) * nc, 0.0);
  if (nc == 0) return f;  // no component (a behaviour without internal variables): no row to write
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int q = 0; q < states.n_points(c); ++q) row(c, q, &f.values[(static_cast<size_t>(f.cell_offsets[c]) + q) * nc]);
  return f;
}

}  // namespace

ElgaField stresses_at_points(const FeModel& model, const MaterialStates& states) {
  std::vector<std::string> names = model.dim == 2
                                       ? std::vector<std::string>{"SIXX", "SIYY", "SIZZ", "SIXY"}
                                       : std::vector<std::string>{"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"};
  const int nt = states.tensor_size();
  return points_field(model, states, std::move(names), [&](int c, int q, double* out) {
    const double* s = states.stress(MaterialStates::Slot::End, c, q);
    std::copy(s, s + nt, out);
  });
}

ElgaField stresses_at_points(const CellBehaviours& behaviours, const DofMap& dofs, const Vector& u,
                             const MaterialStates& states) {
  const FeModel& model = behaviours.model();
  ElgaField f = stresses_at_points(model, states);
  const int nc = f.n_components();
  for (int c : model.volume_cells()) {
    if (behaviours.kinematics(c) != Kinematics::TotalLagrangian || states.n_points(c) == 0) continue;
    kernels::with_green_lagrange(model, c, [&](auto& kin) {
      using Kin = std::decay_t<decltype(kin)>;
      constexpr int NN = Kin::kNodes, DIM = Kin::kDim;
      typename Kin::Dofs ue;
      const int* nodes = model.mesh->cell(c);
      for (int a = 0; a < NN; ++a)
        for (int k = 0; k < DIM; ++k) ue(DIM * a + k) = u(dofs.dof(nodes[a], k));
      typename Kin::BMatrix b;
      typename Kin::Rows e;
      for (int q = 0; q < kin.n_points(); ++q) {
        kin.point(q, ue, b, e);
        double* out = &f.values[(static_cast<size_t>(f.cell_offsets[c]) + q) * nc];
        const TensorVector pk2 = Eigen::Map<const Eigen::VectorXd>(out, nc);
        const TensorVector sigma = kin.cauchy(pk2);
        std::copy(sigma.data(), sigma.data() + nc, out);
      }
    });
  }
  return f;
}

ElgaField variables_at_points(const FeModel& model, const MaterialStates& states) {
  int n = 0;
  for (int c = 0; c < states.n_cells(); ++c) n = std::max(n, states.n_points(c) > 0 ? states.n_variables(c) : 0);
  std::vector<std::string> names;
  for (int k = 1; k <= n; ++k) names.push_back("V" + std::to_string(k));
  return points_field(model, states, std::move(names), [&](int c, int q, double* out) {
    const double* v = states.variables(MaterialStates::Slot::End, c, q);
    if (v) std::copy(v, v + states.n_variables(c), out);
  });
}

}  // namespace lunaster::engine

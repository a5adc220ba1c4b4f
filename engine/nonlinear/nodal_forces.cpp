#include "engine/nonlinear/nodal_forces.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/assembly/assembly.hpp"
#include "engine/core/error.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {

namespace {

/// The vector `f` as a nodal field over the displacement unknowns of `dofs`.
NodalField as_nodal_field(const FeModel& model, const DofMap& dofs, const Vector& f) {
  std::vector<std::string> cmps = {"DX", "DY"};
  if (model.dim == 3) cmps.push_back("DZ");
  NodalField field(cmps, model.mesh->n_nodes());
  for (int node = 0; node < model.mesh->n_nodes(); ++node)
    for (int c = 0; c < model.dim; ++c) {
      const int eq = dofs.dof(node, c);
      if (eq >= 0) field.set(node, c, f[eq]);
    }
  return field;
}

/// B^T sigma over the cells, this rank's only with `cell_rank` and then summed over the ranks.
Vector internal_forces(const FeModel& model, const DofMap& dofs, const Vector& u, const std::vector<int>* cell_rank) {
  Vector f_int;
  assemble_internal_forces(model, dofs, u, f_int, cell_rank);
  if (cell_rank) parallel::sum_over_ranks(f_int.data(), static_cast<long long>(f_int.size()));
  return f_int;
}

}  // namespace

Vector external_forces(const FeModel& model, const DofMap& dofs, const MechanicalLoads& loads, double t,
                       const std::vector<int>* node_owner, const Halo* halo) {
  LUNASTER_ASSERT(!halo || node_owner, "external_forces: a halo without the part's owners");
  Vector f = Vector::Zero(dofs.n_dofs());
  for (const auto& p : loads.pressures)
    assemble_pressure(*model.mesh, model.dim, p.cells, p.pressure * loads.multipliers.at(p.load)(t), dofs, f,
                      model.axisymmetric(), node_owner);
  for (const auto& d : loads.distributed) {
    const double m = loads.multipliers.at(d.load)(t);
    if (!d.per_mass) {
      assemble_distributed_force(*model.mesh, model.dim, d.cells, d.cells_dim, {m * d.force[0], m * d.force[1], m * d.force[2]},
                                 dofs, f, model.axisymmetric(), node_owner);
      continue;
    }
    // Per unit mass: the cells of each material together, times its density.
    std::vector<std::vector<int>> by_material(model.materials.size());
    for (int c : d.cells) {
      const int mat = model.material.at(c);
      if (mat < 0 || std::isnan(model.materials[mat].density))
        throw DeckError("force per unit mass on cell " + model.mesh->cell_names.at(c) + ", whose material has no density");
      by_material[mat].push_back(c);
    }
    for (size_t mat = 0; mat < by_material.size(); ++mat) {
      if (by_material[mat].empty()) continue;
      const double s = m * model.materials[mat].density;
      assemble_distributed_force(*model.mesh, model.dim, by_material[mat], d.cells_dim,
                                 {s * d.force[0], s * d.force[1], s * d.force[2]}, dofs, f, model.axisymmetric(),
                                 node_owner);
    }
  }
  const int me = node_owner ? parallel::rank() : 0;
  for (const auto& fn : loads.forces) {
    const int eq = dofs.dof(fn.node, fn.component);
    if (eq < 0)
      throw DeckError("nodal force " + std::string(component_name(fn.component)) + " on node " +
                      model.mesh->node_names[fn.node] + ", which carries no such unknown in the model");
    if (node_owner && std::max(0, (*node_owner)[fn.node]) != me) continue;
    f[eq] += fn.value * loads.multipliers.at(fn.load)(t);
  }
  if (halo) {
    halo->add_to_owners(f.data(), 1);
    halo->copy_to_ghosts(f.data(), 1);
  } else if (node_owner) {
    parallel::sum_over_ranks(f.data(), static_cast<long long>(f.size()));
  }
  return f;
}

NodalField internal_nodal_forces(const FeModel& model, const DofMap& dofs, const Vector& u,
                                 const std::vector<int>* cell_rank) {
  return as_nodal_field(model, dofs, internal_forces(model, dofs, u, cell_rank));
}

NodalField reaction_forces(const FeModel& model, const DofMap& dofs, const Vector& u, const MechanicalLoads& loads,
                           double t, const std::vector<int>* cell_rank) {
  const Vector f_int = internal_forces(model, dofs, u, cell_rank);
  return as_nodal_field(model, dofs, f_int - external_forces(model, dofs, loads, t));
}

namespace {

Vector internal_forces(const FeModel& model, const DofMap& dofs, const Vector& u, const MeshPart& part,
                       const Halo& equations) {
  LUNASTER_ASSERT(model.mesh == &part.mesh, "internal forces in parts: a model of another mesh");
  Vector f_int;
  assemble_internal_forces(model, dofs, u, f_int, &part.cell_part);
  equations.add_to_owners(f_int.data(), 1);
  equations.copy_to_ghosts(f_int.data(), 1);
  return f_int;
}

}  // namespace

NodalField internal_nodal_forces(const FeModel& model, const DofMap& dofs, const Vector& u, const MeshPart& part,
                                 const Halo& equations) {
  return as_nodal_field(model, dofs, internal_forces(model, dofs, u, part, equations));
}

NodalField reaction_forces(const FeModel& model, const DofMap& dofs, const Vector& u, const MechanicalLoads& loads,
                           double t, const MeshPart& part, const Halo& equations) {
  const Vector f_int = internal_forces(model, dofs, u, part, equations);
  return as_nodal_field(model, dofs, f_int - external_forces(model, dofs, loads, t, &part.node_owner, &equations));
}

}  // namespace lunaster::engine

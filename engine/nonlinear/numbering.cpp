#include "engine/nonlinear/numbering.hpp"

#include <string>

#include "engine/core/error.hpp"
#include "engine/nonlinear/renumbered_hook.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {

RunNumbering number_unknowns(const FeModel& model, const MechanicalLoads& loads, ContactHook* hook,
                             const MeshPart* part, const MeshPart* hook_part, const NewtonOptions& options,
                             std::optional<NodeHalo>& node_halo) {
  RunNumbering out;
  out.hook = hook;
  out.dofs = DofMap(*model.mesh, model.volume_cells(), model.dim);
  DofMap& dofs = out.dofs;
  if (part && hook_part) {
    // The hook's nodes beyond the part (contact surfaces, relations): ghosts with their
    // displacement unknowns.
    LUNASTER_ASSERT(out.hook && hook_part->n_owned_nodes == part->n_owned_nodes &&
                        hook_part->mesh.n_nodes() >= part->mesh.n_nodes(),
                    "the hook's nodes are the part's and more, for a run with a hook");
    dofs.add_nodes(hook_part->mesh.n_nodes());
    for (int v = part->mesh.n_nodes(); v < hook_part->mesh.n_nodes(); ++v)
      for (int c = 0; c < model.dim; ++c) dofs.add(v, c);
  }
  const int displacement_dofs = dofs.n_dofs();
  // In parts, the exchanges of the part's nodes (the owners' Dirichlet conditions for the hook,
  // then the numbering across the ranks).
  if (part) node_halo.emplace(hook_part ? *hook_part : *part);
  if (out.hook) {
    out.hook->set_dirichlet(part && hook_part ? owners_dirichlet(*hook_part, *node_halo, loads.dirichlet)
                                                   : loads.dirichlet);
    out.hook->add_dofs(dofs);
  }
  if (!part) return out;
  const int n = dofs.n_dofs();
  // What a mesh in parts does not do yet (docs/distributed-model.md): said alike on every rank.
  LUNASTER_ASSERT(model.mesh == &part->mesh && part->parts == parallel::size(),
                  "a run in parts takes the model of this rank's part, one part per rank");
  LUNASTER_ASSERT(!out.hook || hook_part, "a hook on a mesh in parts takes the part with the hook's nodes");
  if (n != displacement_dofs) {
    // The hook's multipliers came after every node's displacements: the owned unknowns go
    // first (global_dofs.hpp), each class in its order, and the hook keeps its numbering.
    if (options.solver == SolverKind::Petsc) {
      DeckError refused("the multipliers of contact or linear relations on a mesh in parts are solved by the "
                        "MUMPS backend, not PETSc");
      refused.failure().what = Failure::What::PartsMultipliers;
      throw refused;
    }
    std::vector<int> new_of_old(n);
    int next = 0;
    for (int owned_class : {1, 0})
      for (int eq = 0; eq < n; ++eq)
        if (part->owns(dofs.node_of(eq)) == (owned_class == 1)) new_of_old[eq] = next++;
    dofs = dofs.renumbered(new_of_old);
    out.renumbered = std::make_unique<RenumberedHook>(*out.hook, std::move(new_of_old));
    out.hook = out.renumbered.get();
  }
  if (options.auto_solver || (options.solver != SolverKind::Mumps && options.solver != SolverKind::Petsc)) {
    DeckError refused("on a mesh in parts the MUMPS or PETSc backend solves, not " +
                      std::string(options.auto_solver ? "the automatic choice" : "a backend of one process"));
    refused.failure().what = Failure::What::PartsBackend;
    refused.failure().count = options.auto_solver ? 1 : 0;
    throw refused;
  }
  return out;
}

std::vector<DirichletValue> owners_dirichlet(const MeshPart& numbered, const NodeHalo& node_halo,
                                             const std::vector<DirichletValue>& dirichlet) {
  // The part's loads miss the conditions of the hook's nodes beyond it (and of ghosts whose
  // constrained faces it lacks): each node takes its owner's, who holds every one of its own.
  // Per node and component: imposed or not, the value, the load (the last condition wins).
  constexpr int kPer = 9;
  std::vector<double> imposed(kPer * static_cast<size_t>(numbered.mesh.n_nodes()), 0.0);
  for (const DirichletValue& d : dirichlet)
    if (d.component >= 0 && d.component < 3) {
      double* at = &imposed[kPer * static_cast<size_t>(d.node) + 3 * d.component];
      at[0] = 1.0, at[1] = d.value, at[2] = d.load;
    }
  node_halo.copy_to_ghosts(imposed, kPer);
  std::vector<DirichletValue> out;
  for (int v = 0; v < numbered.mesh.n_nodes(); ++v)
    for (int c = 0; c < 3; ++c) {
      const double* at = &imposed[kPer * static_cast<size_t>(v) + 3 * c];
      if (at[0] != 0.0) out.push_back({v, c, at[1], static_cast<int>(at[2])});
    }
  return out;
}

}  // namespace lunaster::engine

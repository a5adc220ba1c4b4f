#pragma once
/// The unknowns of a run: the DOF map of the model (displacements, then the hook's multipliers),
/// and on a mesh in parts the hook's nodes beyond the part as ghosts and the owned unknowns first.
#include <memory>
#include <optional>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/assembly/halo.hpp"
#include "engine/assembly/mesh_part.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/contact/contact_hook.hpp"
#include "engine/nonlinear/loads.hpp"
#include "engine/nonlinear/newton_options.hpp"

namespace lunaster::engine {

/// The numbering of one run.
struct RunNumbering {
  DofMap dofs;
  ContactHook* hook = nullptr;              ///< the hook as the run sees it (renumbered in parts), or null
  std::unique_ptr<ContactHook> renumbered;  ///< owns the renumbered view of the hook, when there is one
};

/// Numbers the unknowns of `model` (and of `hook`, which adds its multipliers and gets the
/// run's Dirichlet conditions; may be null). In parts (`part` not null; `hook_part`: the part
/// with the hook's nodes), `node_halo` becomes the numbered part's node exchanges, the hook's
/// nodes beyond the part carry displacement unknowns, and a hook with multipliers is seen
/// through a renumbering with the owned unknowns first. Refuses what a mesh in parts does not
/// do (DeckError with Failure::What::PartsBackend or PartsMultipliers). Collective in parts.
RunNumbering number_unknowns(const FeModel& model, const MechanicalLoads& loads, ContactHook* hook,
                             const MeshPart* part, const MeshPart* hook_part, const NewtonOptions& options,
                             std::optional<NodeHalo>& node_halo);

/// On a mesh in parts: the Dirichlet conditions on the nodes of `numbered` (a part with nodes
/// beyond it: a hook's, StaticSolver::set_part), each node's as its owner has them (value and
/// load of the last condition on each component, as the driver imposes it). `dirichlet`
/// are this rank's conditions on its part's nodes (numbered's first nodes); `node_halo` is
/// numbered's. Collective.
std::vector<DirichletValue> owners_dirichlet(const MeshPart& numbered, const NodeHalo& node_halo,
                                             const std::vector<DirichletValue>& dirichlet);

}  // namespace lunaster::engine

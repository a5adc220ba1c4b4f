#pragma once
/// Nodal forces of a converged state (code_aster's FORC_NODA and REAC_NODA) and the
/// external load vector the Newton solver balances them against.
#include "engine/assembly/dof_map.hpp"
#include "engine/assembly/halo.hpp"
#include "engine/assembly/mesh_part.hpp"
#include "engine/core/linalg.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/fields/fields.hpp"
#include "engine/nonlinear/loads.hpp"

namespace lunaster::engine {

/// External nodal forces at instant t (N): consistent pressure and distributed forces (a force per
/// unit mass times each cell's density) and nodal forces, each scaled by its load multiplier. DeckError for a nodal force on a node without that
/// displacement unknown. With `node_owner` (a shared model's owner rank per node) each rank
/// computes the pressure cells and nodal forces of its own nodes and the ranks sum
/// (collective): every rank ends with the whole vector. With `halo` as well (a mesh in parts:
/// `node_owner` is the part's, the halo that of its unknowns), the ghosts' shares go to their
/// owners and the owners' sums back to the ghosts instead: every rank ends with its part's vector.
Vector external_forces(const FeModel& model, const DofMap& dofs, const MechanicalLoads& loads, double t,
                       const std::vector<int>* node_owner = nullptr, const Halo* halo = nullptr);

/// Internal nodal forces B^T sigma (N, or N per unit thickness in 2D) of displacement `u`,
/// assembled by the same element kernels as the solver's internal forces, as a nodal
/// field DX, DY[, DZ] defined on every node carrying displacement unknowns in `dofs`.
/// With `cell_rank` (a shared model's partition, per mesh cell) each rank assembles its own
/// cells and the ranks sum (collective): every rank ends with the whole field.
NodalField internal_nodal_forces(const FeModel& model, const DofMap& dofs, const Vector& u,
                                 const std::vector<int>* cell_rank = nullptr);

/// Reactions: internal forces minus the external loads at instant t. What remains is what
/// the supports (DDL_IMPO, linear relations) and, where surfaces touch, contact exert on the
/// body, with the sign of a force the body applies on them (code_aster's REAC_NODA).
NodalField reaction_forces(const FeModel& model, const DofMap& dofs, const Vector& u, const MechanicalLoads& loads,
                           double t, const std::vector<int>* cell_rank = nullptr);

/// On a mesh in parts (docs/distributed-model.md): the part's own volume cells' internal forces
/// summed into the owners and copied to the ghosts through `equations` (the halo of the part's
/// unknowns, equation_halo): every local node holds the whole model's value. Collective.
NodalField internal_nodal_forces(const FeModel& model, const DofMap& dofs, const Vector& u, const MeshPart& part,
                                 const Halo& equations);

/// reaction_forces on a mesh in parts: internal forces as above, the loads of the faces whose
/// first node the rank owns and of its own nodes, both summed through `equations`. Collective.
NodalField reaction_forces(const FeModel& model, const DofMap& dofs, const Vector& u, const MechanicalLoads& loads,
                           double t, const MeshPart& part, const Halo& equations);

}  // namespace lunaster::engine

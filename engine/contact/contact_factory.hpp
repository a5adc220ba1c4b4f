#pragma once
/// Entry point of engine/contact: builds the contact algorithm the Newton
/// driver (engine/nonlinear/static_solver) plugs in as a ContactHook.
///
/// Every method is a discretisation times a law, assembled by the shared part
/// contact::ContactProblem (contact_problem.hpp):
/// | ContactMethod      | discretisation (discretisation.hpp) | law (contact_law.hpp) |
/// |--------------------|-------------------------------------|-----------------------|
/// | Continuous         | integration points                  | augmented Lagrangian  |
/// | ContinuousPenalty  | integration points                  | penalty (Pa/m)        |
/// | DiscreteLagrange   | node to segment                     | active set            |
/// | DiscretePenalty    | node to segment                     | penalty (N/m per node)|
/// Mortar (MortarLagrange, MortarPenalty) is its own hook, mortar_problem.hpp: its conditions
/// are weighted gaps per slave node, and its Lagrange law eliminates them from the solve.
/// Unknowns: LAGS_C (Component::LAGS_C) on the slave nodes for every law but the nodal
/// penalty (vertices only for node-to-segment). LAGS_C is in Pa, negative in compression.
/// Fields: write_fields adds the nodal field "CONT_NOEU" on slave nodes with
/// CONT (1 in contact, 0 not), JEU (gap, m, > 0 open), RN (norm of the nodal
/// contact force, N), RNX, RNY[, RNZ] (force on the slave node), and for
/// node-to-segment PRES (nodal contact pressure, Pa, negative in compression).
#include <memory>

#include "engine/contact/contact_definition.hpp"
#include "engine/core/error.hpp"
#include "engine/mesh/mesh.hpp"
#include "engine/nonlinear/static_solver.hpp"

namespace lunaster::engine {

/// Builds the hook for `definition` on `mesh` (dim 2 or 3). The mesh and the
/// definition are read at construction; the mesh must outlive the hook.
/// Throws DeckError for unusable surfaces (non-boundary cells, E_N <= 0 ...).
std::unique_ptr<ContactHook> make_contact_hook(const ContactDefinition& definition, const Mesh& mesh, int dim);

}  // namespace lunaster::engine

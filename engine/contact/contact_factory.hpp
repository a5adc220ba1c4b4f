#pragma once
/// Entry point of engine/contact: builds the contact algorithm the Newton
/// driver (engine/nonlinear/static_solver) plugs in as a ContactHook.
///
/// Every method is a discretisation (ContactMethod::where) times a law (ContactMethod::how,
/// contact_law.hpp), assembled by a shared part:
/// | ContactMethod     | discretisation                           | law                          | shared part    |
/// |-------------------|------------------------------------------|------------------------------|----------------|
/// | Continuous        | integration points (discretisation.hpp)  | augmented Lagrangian         | ContactProblem |
/// | ContinuousPenalty | integration points                       | penalty (Pa/m)               | ContactProblem |
/// | DiscreteLagrange  | node to segment                          | active set                   | ContactProblem |
/// | DiscretePenalty   | node to segment                          | springs (N/m per node)       | ContactProblem |
/// | MortarLagrange    | segment to segment (mortar_segments.hpp) | primal-dual active set (exact) | MortarProblem |
/// | MortarPenalty     | segment to segment                       | penalty (Pa/m)               | MortarProblem  |
/// ContactProblem (contact_problem.hpp) takes point discretisations, whose conditions share
/// LAGS_C unknowns; MortarProblem (mortar_problem.hpp) takes the dual rows of the segment
/// discretisation, one per slave node, which a law may hold exactly by elimination.
/// Unknowns: LAGS_C (Component::LAGS_C) on the slave nodes for every point law but the nodal
/// penalty (vertices only for node-to-segment); mortar adds none and reports LAGS_C in DEPL.
/// LAGS_C is in Pa, negative in compression.
/// Fields: write_fields adds the nodal field "CONT_NOEU" on slave nodes with
/// CONT (1 in contact, 0 not), JEU (gap, m, > 0 open), RN (norm of the nodal
/// contact force, N), RNX, RNY[, RNZ] (force on the slave node), and for
/// node-to-segment PRES (nodal contact pressure, Pa, negative in compression).
#include <memory>

#include "engine/contact/contact_definition.hpp"
#include "engine/contact/contact_hook.hpp"
#include "engine/core/error.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Builds the hook for `definition` on `mesh` (dim 2 or 3). The mesh and the
/// definition are read at construction; the mesh must outlive the hook.
/// Throws DeckError for unusable surfaces (non-boundary cells, E_N <= 0 ...).
std::unique_ptr<ContactHook> make_contact_hook(const ContactDefinition& definition, const Mesh& mesh, int dim);

}  // namespace lunaster::engine

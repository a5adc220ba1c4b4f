#pragma once
/// Result fields at the integration points (ELGA) from the points' history: the stresses and
/// the internal variables as a behaviour left them, for the result and its MED file.
#include "engine/assembly/dof_map.hpp"
#include "engine/core/linalg.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/fields/fields.hpp"
#include "engine/material/material_states.hpp"

namespace lunaster::engine {

class CellBehaviours;

/// Stresses at the points (the trial slot: the last step's end once committed), components
/// SIXX SIYY SIZZ SIXY (2D) or SIXX SIYY SIZZ SIXY SIXZ SIYZ (3D), Pa.
ElgaField stresses_at_points(const FeModel& model, const MaterialStates& states);

/// Stresses at the points as the result fields hold them, Cauchy's under every kinematics: a
/// small-strain cell's as stored, a total Lagrangian cell's (whose states hold the second
/// Piola-Kirchhoff stress S) F S F^T / det F with F at the displacement `u` (n_dofs, the states'
/// end). Components as above.
ElgaField stresses_at_points(const CellBehaviours& behaviours, const DofMap& dofs, const Vector& u,
                             const MaterialStates& states);

/// Internal variables at the points (the trial slot), components V1..Vn with n the most any cell
/// has (a cell's behaviour names them: Behaviour::variable_names); a cell with fewer holds zeros
/// after its own, a cell with none holds zeros.
ElgaField variables_at_points(const FeModel& model, const MaterialStates& states);

}  // namespace lunaster::engine

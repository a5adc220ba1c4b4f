#pragma once
/// The result fields of a converged step, from the unknowns: the displacement field with the
/// components the DOF map carries, and the contact hook's own fields.
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/fields/fields.hpp"
#include "engine/contact/contact_hook.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "engine/material/material_states.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

class StepResults {
 public:
  /// `dofs` numbers the unknowns of `model_nodes` nodes (and, with a hook on a part with whole
  /// contact surfaces, of `hook_nodes` >= model_nodes nodes: the hook writes its fields on
  /// those, and the fields keep the model's). `hook` may be null. All are borrowed for the run.
  StepResults(const DofMap& dofs, int model_nodes, const ContactHook* hook, int hook_nodes);
  /// The integration points' history of `model` (borrowed for the run; null: none, the
  /// default): each step then carries the stresses (SIEF_ELGA) and the internal variables
  /// (VARI_ELGA) of the states' trial slot, the step's converged end once committed.
  /// `behaviours` (may be null: all small strain) gives each cell's kinematics: the stresses of
  /// a total Lagrangian cell are then stored as Cauchy's (its states hold the second
  /// Piola-Kirchhoff stress).
  void set_points(const FeModel* model, const MaterialStates* states, const CellBehaviours* behaviours = nullptr) {
    points_model_ = model;
    points_ = states;
    points_behaviours_ = behaviours;
  }
  /// Step `index` at instant `inst` from the unknowns u; `initial`: the state before any
  /// pairing (the hook writes its initial fields).
  ResultStep step(int index, double inst, const Vector& u, bool initial) const;

 private:
  NodalField displacement(const Vector& u) const;
  const DofMap& dofs_;
  int model_nodes_;
  const ContactHook* hook_;
  int hook_nodes_;
  std::vector<int> components_;  ///< of the displacement field, in the DOF map's order
  const FeModel* points_model_ = nullptr;
  const MaterialStates* points_ = nullptr;
  const CellBehaviours* points_behaviours_ = nullptr;
};

}  // namespace lunaster::engine

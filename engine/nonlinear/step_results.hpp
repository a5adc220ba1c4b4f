#pragma once
/// The result fields of a converged step, from the unknowns: the displacement field with the
/// components the DOF map carries, and the contact hook's own fields.
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/fields/fields.hpp"
#include "engine/contact/contact_hook.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

class StepResults {
 public:
  /// `dofs` numbers the unknowns of `model_nodes` nodes (and, with a hook on a part with whole
  /// contact surfaces, of `hook_nodes` >= model_nodes nodes: the hook writes its fields on
  /// those, and the fields keep the model's). `hook` may be null. All are borrowed for the run.
  StepResults(const DofMap& dofs, int model_nodes, const ContactHook* hook, int hook_nodes);
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
};

}  // namespace lunaster::engine

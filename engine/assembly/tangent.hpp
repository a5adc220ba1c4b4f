#pragma once
/// The mechanical tangent a Newton driver asks for: the internal force and the tangent of the
/// model's behaviours at a displacement, over the history of its integration points.
#include "engine/assembly/dof_map.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "engine/material/material_states.hpp"
#include "engine/core/linalg.hpp"

namespace lunaster::engine {

/// Internal force and tangent of a model's behaviours, with their history. A driver calls
/// assemble() at each iteration (when constant() it may keep the matrix of the first call and its
/// factorisation for as long as the constraints are unchanged), commit() when a step converged,
/// restore() when a step is abandoned to be subdivided. Lifetime: one run; the behaviours and the
/// DOF map are kept by reference and must outlive it.
class Tangent {
 public:
  Tangent(const CellBehaviours& behaviours, const DofMap& dofs);

  /// True when every behaviour is linear: the tangent is the stiffness, the same at every
  /// displacement and instant.
  bool constant() const { return constant_; }
  /// At displacement `u` (n_dofs, the step's end): the tangent into `k` (n_dofs x n_dofs, the
  /// pattern of assemble_stiffness_matrix, both triangles) and the internal force into `f_int`
  /// (n_dofs), each when given; the points' trial states are updated (with f_int, or with k when
  /// not constant()). Returns false when a behaviour's integration failed at a point (the step is
  /// to be subdivided).
  bool assemble(const Vector& u, SparseMatrix* k, Vector* f_int);
  /// The step converged: the trial states become the next step's start.
  void commit() { states_.commit(); }
  /// The step is abandoned: the trial states go back to the step's start.
  void restore() { states_.restore(); }
  /// The points' history (the stresses and the internal variables for the result fields).
  const MaterialStates& states() const { return states_; }

 private:
  const CellBehaviours& behaviours_;
  const DofMap& dofs_;
  bool constant_;
  MaterialStates states_;
};

}  // namespace lunaster::engine

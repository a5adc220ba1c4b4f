#pragma once
/// Where the Newton system's stiffness and internal forces come from (a behaviour's tangent,
/// assembled by engine/assembly). The driver keeps one for the run; SystemMatrix asks it.
#include <memory>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/core/error.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "engine/material/material_states.hpp"
#include "engine/nonlinear/rank_layout.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

class TangentSource {
 public:
  virtual ~TangentSource() = default;
  /// True when the tangent does not depend on u (linear elasticity): K is assembled once per
  /// Dirichlet set, its factorisations are kept, and f_int = K u. False: K and f_int are
  /// assembled again at every Newton iteration that solves.
  virtual bool constant() const = 0;
  /// False when the tangent may be indefinite (a softening behaviour): the system is then
  /// factorised as symmetric indefinite, never by Cholesky.
  virtual bool positive_definite() const { return true; }
  /// The tangent at u into *k and/or the internal forces into *f_int (either may be null), over
  /// the run's numbering (this rank's nodes' columns and entries when the model is shared).
  /// Returns false when a behaviour's integration failed at a point (no admissible state at the
  /// step's end): the driver treats it as a failed iteration, and the step is subdivided.
  virtual bool assemble(const Vector& u, SparseMatrix* k, Vector* f_int) = 0;
  /// The state of a converged step becomes the start of the next one.
  virtual void commit() {}
  /// Back to the state at the start of the step (a failed step is split).
  virtual void restore() {}
  /// The history of the integration points (stresses, internal variables) for the results, or
  /// null when the tangent keeps none (linear elasticity). Valid while the source lives.
  virtual const MaterialStates* states() const { return nullptr; }
};

/// The linear elastic stiffness of a model: constant, K assembled from the cells' materials.
/// `owned_nodes` (may be null: the whole model): per node, whether this rank assembles its
/// columns. Borrows its arguments for the run.
std::unique_ptr<TangentSource> make_elastic_tangent(const FeModel& model, const DofMap& dofs,
                                                    const std::vector<char>* owned_nodes);

/// The tangent and internal forces of the cells' behaviours (assembly's Tangent), with the
/// history of their points, for a run laid out as `layout`; null when every behaviour is linear
/// (the elastic tangent serves, unchanged). The behaviours' tangent assembles every cell on this
/// rank: a shared model or a mesh in parts is refused (DeckError, Failure::What::SharedBehaviour,
/// `count` 1 in parts). Borrows its arguments for the run.
std::unique_ptr<TangentSource> make_behaviour_tangent(const CellBehaviours& behaviours, const DofMap& dofs,
                                                      RankLayout::Kind layout);

/// The error of a behaviour whose integration failed at a point at instant t (the assemble of
/// a TangentSource returned false): a failed Newton iteration, the step to be subdivided.
ConvergenceError integration_failure(double t);

/// The error of a linear solve that failed on a tangent that is not constant at instant t (a
/// behaviour that lost its stiffness: no equilibrium at this load, or too large a step): a
/// failed Newton iteration, the step to be subdivided; `err` (the solver's) in the hints.
ConvergenceError tangent_solve_failure(const SolveError& err, double t);

}  // namespace lunaster::engine

#pragma once
/// Where the Newton system's stiffness and internal forces come from (a behaviour's tangent,
/// assembled by engine/assembly). The driver keeps one for the run; SystemMatrix asks it.
#include <memory>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

class TangentSource {
 public:
  virtual ~TangentSource() = default;
  /// True when the tangent does not depend on u (linear elasticity): K is assembled once per
  /// Dirichlet set, its factorisations are kept, and f_int = K u. False: K and f_int are
  /// assembled again at every Newton iteration that solves.
  virtual bool constant() const = 0;
  /// The tangent at u into *k and/or the internal forces into *f_int (either may be null), over
  /// the run's numbering (this rank's nodes' columns and entries when the model is shared).
  virtual void assemble(const Vector& u, SparseMatrix* k, Vector* f_int) = 0;
  /// The state of a converged step becomes the start of the next one.
  virtual void commit() {}
  /// Back to the state at the start of the step (a failed step is split).
  virtual void restore() {}
};

/// The linear elastic stiffness of a model: constant, K assembled from the cells' materials.
/// `owned_nodes` (may be null: the whole model): per node, whether this rank assembles its
/// columns. Borrows its arguments for the run.
std::unique_ptr<TangentSource> make_elastic_tangent(const FeModel& model, const DofMap& dofs,
                                                    const std::vector<char>* owned_nodes);

}  // namespace lunaster::engine

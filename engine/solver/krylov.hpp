#pragma once
/// Restarted GMRES with right preconditioning by a direct solver's factorisation
/// of a nearby matrix. The Newton driver uses it when a contact pass changed the
/// pairing but not the statuses: the previous factorisation is then a very good
/// preconditioner and a few iterations replace a new factorisation.
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

struct KrylovResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;  ///< |A x - b| / |b| reached
};

/// Solves A x = b from x = 0, M^-1 applied by `preconditioner.solve` (its last
/// factorisation, of another matrix of A's size). Stops at |A x - b| <= tolerance |b|
/// or after `max_iterations` (one restart cycle of that length).
KrylovResult preconditioned_gmres(const SparseMatrix& a, const LinearSolver& preconditioner, const Vector& b,
                                  Vector& x, int max_iterations, double tolerance);
/// The same with A known through its product (a system shared among MPI ranks).
KrylovResult preconditioned_gmres(const MatrixProduct& a, const LinearSolver& preconditioner, const Vector& b,
                                  Vector& x, int max_iterations, double tolerance);

}  // namespace lunaster::engine

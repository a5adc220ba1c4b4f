#pragma once
/// Restriction of an assembled matrix to a subset of its equations.
#include <vector>

#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

/// The submatrix A(I, I) where `index[eq]` is the position of equation eq in
/// I, or -1 if eq is left out; `index` must be increasing over the kept
/// equations (so each column stays sorted). One linear pass, no sorting:
/// used to eliminate Dirichlet equations without going back to triplets.
SparseMatrix restrict_matrix(const SparseMatrix& a, const std::vector<int>& index, int n_kept);

}  // namespace lunaster::engine

#pragma once
/// Restriction of an assembled matrix to a subset of its equations.
#include <algorithm>
#include <vector>

#include "engine/core/linalg.hpp"

namespace lunaster::engine {

/// The submatrix A(I, I) where `index[eq]` is the position of equation eq in
/// I, or -1 if eq is left out; `index` must be increasing over the kept
/// equations (so each column stays sorted). One linear pass, no sorting:
/// used to eliminate Dirichlet equations without going back to triplets.
SparseMatrix restrict_matrix(const SparseMatrix& a, const std::vector<int>& index, int n_kept);

/// A symmetric matrix K split by a set C of constrained equations (Dirichlet conditions)
/// into what a solve with C eliminated needs: K(F, F) on the free equations F and the
/// columns K(:, C). Together they are K (K(C, F) = K(F, C)^T): no full copy is kept.
struct SplitMatrix {
  SparseMatrix ff;               ///< K(F, F), column free_index[eq] for equation eq
  SparseMatrix c;                ///< K(:, C): column k is equation constrained[k], every row
  std::vector<int> constrained;  ///< C, sorted
  std::vector<int> free_index;   ///< per equation: its column in ff, -1 in C
  std::vector<int> equation;     ///< per column of ff: its equation
  /// ff is the whole K(F, F), so symmetric as stored; false for one rank's columns of a
  /// shared model, whose product must scatter column by column.
  bool symmetric = true;
  /// K u over the whole numbering.
  Vector times(const Vector& u) const;
  /// K(F, F) x, x over the free equations (ff's columns).
  Vector ff_times(const Vector& x) const;
  /// y[C] += K(C, F) x, x over the free equations, y over the whole numbering.
  void add_constrained_rows(const Vector& x, Vector& y) const;
};

/// Splits K (square, symmetric, compressed, sorted columns) into `out`; `constrained` need
/// not be sorted nor unique. K's storage becomes out.ff's (the free entries moved to its
/// front, the rest left unused) and k is left empty, so no second copy of K is ever
/// allocated. (An output argument: Eigen 3.4's SparseMatrix copies where it would move.)
void split_matrix(SparseMatrix& k, std::vector<int> constrained, SplitMatrix& out);

}  // namespace lunaster::engine

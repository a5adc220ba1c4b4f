#pragma once
/// The engine's linear-algebra vocabulary: global vectors, the assembled sparse matrix, the
/// triplets it is built from, and what a caller knows of a matrix. Here, in the lowest folder,
/// because these are types every layer from the elements up passes around and they depend on
/// Eigen alone: a header that only names them does not need the linear solvers
/// (engine/solver/linear_solver.hpp), which it would otherwise drag in with their options.
#include <Eigen/Sparse>

namespace lunaster::engine {

using Vector = Eigen::VectorXd;
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Triplet = Eigen::Triplet<double, int>;

/// What the caller knows about the matrix; backends use it to pick a factorisation.
enum class MatrixKind { SymmetricPositiveDefinite, SymmetricIndefinite, General };

}  // namespace lunaster::engine

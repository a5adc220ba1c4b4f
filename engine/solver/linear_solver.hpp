#pragma once
/// One interface for every direct solver. The assembled matrix is an Eigen
/// compressed-column matrix built from (row, col, value) triplets: the same
/// triplets are what a distributed MUMPS takes (ICN_loc/JCN_loc/A_loc), so
/// moving to MPI means giving each rank its triplets, not changing assembly.
#include <memory>
#include <string>

#include <Eigen/Sparse>

namespace lunaster::engine {

using Vector = Eigen::VectorXd;
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Triplet = Eigen::Triplet<double, int>;

/// What the caller knows about the matrix; backends use it to pick a factorisation.
enum class MatrixKind { SymmetricPositiveDefinite, SymmetricIndefinite, General };

/// Available backends. Cholmod needs an SPD matrix; Umfpack and Mumps take any.
enum class SolverKind { Cholmod, Umfpack, Mumps };

/// Direct solver: factorise once, solve for many right-hand sides.
class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// Factorises A (square, full storage of both triangles). Throws SolveError if
  /// A is singular / not positive definite; `failed_column()` then tells which
  /// column (equation) broke down, or -1 if unknown.
  virtual void factorize(const SparseMatrix& a, MatrixKind kind) = 0;
  /// Solves A x = b with the last factorisation.
  virtual Vector solve(const Vector& b) const = 0;
  virtual std::string name() const = 0;
  /// Equation where the last factorisation failed, -1 if none / unknown.
  virtual int failed_column() const { return -1; }
};

/// Builds a backend. Never returns null.
std::unique_ptr<LinearSolver> make_linear_solver(SolverKind kind);

/// |A x - b| / |b| (2-norms); +inf if x is not finite.
double relative_residual(const SparseMatrix& a, const Vector& x, const Vector& b);

/// Accuracy of one refined solve: relative residual straight from the factorisation
/// and after refinement, and the extra solves spent.
struct RefinedSolve {
  double raw_residual = 0.0;
  double residual = 0.0;
  int steps = 0;
};

/// Solves A x = b with the solver's current factorisation of A, then refines
/// iteratively (x -= A^-1 (A x - b)) while the relative residual is above
/// `refine_above` and each step lowers it, `max_steps` at most. An ill-conditioned
/// but regular system (a stiff penalty, badly scaled multipliers) is then solved to
/// working accuracy; a singular one keeps its large residual for the caller to judge.
RefinedSolve solve_with_refinement(const LinearSolver& solver, const SparseMatrix& a, const Vector& b, Vector& x,
                                   int max_steps = 3, double refine_above = 1e-10);

}  // namespace lunaster::engine

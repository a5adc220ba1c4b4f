#pragma once
/// Contact passes on a factorisation kept for the whole run. A contact system differs from
/// the elastic stiffness only on the equations of the contact surfaces (the interface I:
/// their nodes' displacements and the multipliers); the interior rows and columns (i) stay
/// the elastic ones. With the interface ordered last, one Cholesky factorisation of the
/// reference R (the elastic stiffness, a unit diagonal where it has none)
///
///   P R P^T = L L^T,   L = [L_ii 0; L_Ii L_II]
///
/// gives the interface's Schur complement R_II - R_Ii R_ii^-1 R_iI = L_II L_II^T, dense and
/// small. A system A equal to R outside the II block then has the Schur complement
///
///   S = A_II - A_Ii A_ii^-1 A_iI = G + A_II,   G = L_II L_II^T - R_II (kept),
///
/// and factorising A costs a dense symmetric-indefinite factorisation of S (LAPACK dsytrf).
/// A solve is one forward and one backward sweep through L:
///   y = L^-1 P b;  S x_I = L_II y_I;  y_I <- L_II^T x_I;  x = P^T L^-T y.
/// (With z_i = L_ii^-1 b_i, L_II y_I = b_I - L_Ii z_i = b_I - A_Ii A_ii^-1 b_i is the reduced
/// right-hand side, and L_ii^T x_i = z_i - L_Ii^T x_I gives x_i = A_ii^-1 (b_i - A_iI x_I).)
#include <memory>
#include <vector>

#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

class InterfaceSolver : public LinearSolver {
 public:
  /// Factorises the reference R (CHOLMOD, the interface ordered last): every later
  /// factorize(A) takes A's interior rows and columns to be R's. R's zero or missing
  /// diagonals on the interface (multipliers) count as 1: `r`'s values are changed for the
  /// call and restored. Throws SolveError when R is not positive definite (a body held by
  /// contact alone); the caller then solves without this solver.
  virtual void factorize_reference(SparseMatrix& r) = 0;
  /// Equations of the interface (sorted; the system's own numbering).
  virtual const std::vector<int>& interface() const = 0;
};

/// `interface`: the equations whose rows and columns may differ from the reference's.
std::unique_ptr<InterfaceSolver> make_interface_solver(std::vector<int> interface);

}  // namespace lunaster::engine

#pragma once
/// Contact passes on a factorisation kept for the whole run. A contact system is the elastic
/// stiffness K plus contact terms C that live on the equations of the contact surfaces only
/// (the interface I: their nodes' displacements and the multipliers). With the interface
/// ordered last, one Cholesky factorisation of the reference R = K + D (D: a unit diagonal
/// where K has none, the multipliers)
///
///   P R P^T = L L^T,   L = [L_ii 0; L_Ii L_II]
///
/// gives the interface's Schur complement R_II - K_Ii K_ii^-1 K_iI = L_II L_II^T, dense and
/// small. The system A = K + C then has the Schur complement
///
///   S = A_II - K_Ii K_ii^-1 K_iI = G + C_II,   G = L_II L_II^T - D_II (kept),
///
/// and factorising A costs a dense symmetric-indefinite factorisation of S (LAPACK dsytrf).
/// A solve is one forward and one backward sweep through L:
///   y = L^-1 P b;  S x_I = L_II y_I;  y_I <- L_II^T x_I;  x = P^T L^-T y.
/// (With z_i = L_ii^-1 b_i, L_II y_I = b_I - L_Ii z_i = b_I - K_Ii K_ii^-1 b_i is the reduced
/// right-hand side, and L_ii^T x_i = z_i - L_Ii^T x_I gives x_i = K_ii^-1 (b_i - K_iI x_I).)
#include <memory>
#include <vector>

#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

class InterfaceSolver : public LinearSolver {
 public:
  /// Factorises the reference from the elastic stiffness K (CHOLMOD, the interface ordered
  /// last); K must store a diagonal entry, zero or not, on every interface equation. Its zero
  /// diagonals (multipliers) count as 1: `k`'s values are changed for the call and restored.
  /// Throws SolveError when K is not positive definite on its other equations (a body held by
  /// contact alone); the caller then solves without this solver.
  /// Returns false, without factorising, when the interface's dense factorisation (m^3 / 3
  /// operations per contact pass, m equations) would cost more than `max_dense_share` times
  /// the reference's sparse one (as CHOLMOD's analysis counts it); 0: no such limit.
  virtual bool factorize_reference(SparseMatrix& k, double max_dense_share) = 0;
  /// factorize(c, kind) takes the contact terms C alone (A = K + C), zero outside the
  /// interface's rows and columns: only C_II is read.
  /// Equations of the interface (sorted; the system's own numbering).
  virtual const std::vector<int>& interface() const = 0;
};

/// `interface`: the equations whose rows and columns may differ from the reference's.
std::unique_ptr<InterfaceSolver> make_interface_solver(std::vector<int> interface);

}  // namespace lunaster::engine

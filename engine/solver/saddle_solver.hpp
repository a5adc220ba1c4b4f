#pragma once
/// Symmetric saddle-point systems on CHOLMOD.
///
/// Contact and tie multipliers make the system [A B^T; B C]: A (the displacements' block)
/// symmetric positive definite, B the constraint rows, C the multipliers' own block (zero for
/// an active CONTINUE point or a tie, negative semi-definite otherwise). An indefinite LDL^T
/// with pivoting (MUMPS) factorises it whole. On the SSNP121 3D contact benchmark that is
/// 1.0e10 operations at about 7 GFlop/s, where CHOLMOD's supernodal Cholesky of an SPD
/// system of the same size runs about 2.5 times faster per operation.
///
/// This backend factorises instead S = A + B^T D^-1 B, the Schur complement of the nearby
/// system [A B^T; B -D], D a positive diagonal: S is SPD (CHOLMOD). D is E minus C's
/// diagonal, E being delta (1e-6) times each constraint row's scale sum_j B_ij^2 / A_jj. The
/// preconditioner takes u from S and then the multipliers from their own rows with C whole,
/// (C - E) l = r_l - B u (a sparse LDL^T of the multipliers alone); GMRES on the true
/// system, right-preconditioned by it, converges in a few iterations: the preconditioned
/// operator is the identity up to O(delta) on the constraint rows and exact on the rows of
/// multipliers without a constraint (an inactive point's).
///
/// The multipliers are the equations whose diagonal is not positive (a displacement's
/// stiffness always is). When there are none, too many (over a quarter of the equations),
/// S is not positive definite, or GMRES does not reach the accuracy of a direct solve, the
/// `direct` backend factorises the system itself, from then on; `note` is told why.
#include <functional>
#include <memory>
#include <string>

#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

std::unique_ptr<LinearSolver> make_saddle_solver(SolverKind direct, std::function<void(const std::string&)> note);

}  // namespace lunaster::engine

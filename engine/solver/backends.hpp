#pragma once
/// Backend constructors behind make_linear_solver (internal to lunaster_fe).
#include <memory>
#include <vector>

#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

/// CHOLMOD supernodal Cholesky (SPD matrices only).
std::unique_ptr<LinearSolver> make_cholmod_solver();
/// UMFPACK unsymmetric multifrontal LU (any square matrix).
std::unique_ptr<LinearSolver> make_umfpack_solver();
/// MUMPS (LDL^T for symmetric kinds, LU otherwise), on every rank of the run.
std::unique_ptr<LinearSolver> make_mumps_solver();
/// PETSc Krylov solver and preconditioner, from the module loaded on first use.
std::unique_ptr<LinearSolver> make_petsc_solver(const IterativeSettings& settings);

/// Nested dissection (METIS) of the graph of a's nodes (runs of consecutive columns with one
/// pattern), or of its equations where they form no such runs: perm[k] is the column
/// eliminated k-th. `a`: compressed, both triangles. Empty where METIS fails.
std::vector<int> nested_dissection_ordering(const SparseMatrix& a);

/// Pivot-ratio threshold used to call a factorisation singular: a pivot that
/// lost more than this relative size against its matrix diagonal (about 10
/// significant digits) marks a rigid-body mode or a missing boundary condition.
constexpr double kSingularPivotRatio = 1e-10;

}  // namespace lunaster::engine

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
/// MUMPS (LDL^T for symmetric kinds, LU otherwise), on every rank of the run; in single
/// precision when asked (code_aster's SOLVEUR MIXER_PRECISION = 'OUI').
std::unique_ptr<LinearSolver> make_mumps_solver(bool single_precision = false);
/// PETSc Krylov solver and preconditioner, from the module loaded on first use.
std::unique_ptr<LinearSolver> make_petsc_solver(const IterativeSettings& settings);

/// The elimination order `ordering` gives a (Metis: nested dissection, Amd, Rcm or Natural;
/// the graph of a's nodes, runs of consecutive columns with one pattern, where its columns
/// form such runs, of its equations otherwise): perm[k] is the column eliminated k-th. `a`:
/// compressed, both triangles. Empty where the ordering fails or is not one of these four.
std::vector<int> given_ordering(const SparseMatrix& a, FactorOrdering ordering);

/// Reverse Cuthill-McKee of a symmetric graph given by its adjacency lists (xadj, adj:
/// the neighbours of v are adj[xadj[v] .. xadj[v+1]), both directions, no self loops):
/// breadth-first from a pseudo-peripheral vertex of each connected component, neighbours by
/// increasing degree, the whole order reversed. order[k] is the vertex placed k-th.
std::vector<int> reverse_cuthill_mckee(const std::vector<int>& xadj, const std::vector<int>& adj);

}  // namespace lunaster::engine

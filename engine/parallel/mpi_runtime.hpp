#pragma once
/// The MPI runtime of one lunaster process.
///
/// A run started without `mpirun` is one process and initialises MPI only when a
/// solver needs it (MUMPS and PETSc are MPI libraries): decks that never reach
/// them pay nothing, and those that do pay a singleton start-up of a few tens of
/// milliseconds. A run started by `mpirun -np N` initialises MPI first thing, so
/// that every rank knows its number before the deck runs.
namespace lunaster::engine::parallel {

/// True when this process was started by an MPI launcher (mpirun, mpiexec, srun).
bool launched_by_mpi();

/// Initialises MPI once (thread level: funneled); later calls do nothing. Without
/// a launcher, OpenMPI is steered to a self-contained singleton (no daemon, no
/// network probing) unless the user set those parameters.
void ensure_initialised();

/// Whether ensure_initialised() has run.
bool initialised();

/// This process's rank in the run and the number of ranks: 0 and 1 before MPI is
/// initialised and in a run without launcher.
int rank();
int size();

/// Rank 0 of the run writes files and prints; the others compute only.
inline bool writes_output() { return rank() == 0; }

/// The communicator of the whole run as a Fortran handle (what MUMPS takes).
int fortran_comm_world();

/// Sum of a value over the ranks (identity on one rank).
double sum(double value);
/// Largest value over the ranks (identity on one rank).
int max(int value);

/// Rank 0's values of `data` on every rank (nothing on one rank).
void broadcast(double* data, long long n);

/// Finalises MPI if it was initialised (called once, at the end of main).
void finalise();

}  // namespace lunaster::engine::parallel

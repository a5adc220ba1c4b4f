#pragma once
#include <optional>
#include <string>
#include <vector>

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
/// Ranks of the run on this machine (those sharing its memory, MPI_COMM_TYPE_SHARED), this one
/// included; 1 outside an MPI run.
int ranks_on_this_machine();

/// Rank 0 of the run writes files and prints; the others compute only.
inline bool writes_output() { return rank() == 0; }

/// The communicator of the whole run as a Fortran handle (what MUMPS takes).
int fortran_comm_world();

/// Rank 0's values of `data` on every rank (nothing on one rank).
void broadcast(double* data, long long n);
void broadcast(int* data, long long n);
/// Rank 0's `bytes` on every rank (resized there; nothing on one rank).
void broadcast(std::string& bytes);
/// `bytes` to rank `to` (blocking; rank `to` calls receive_bytes(this rank)).
void send_bytes(int to, const std::string& bytes);
/// What rank `from` sent with send_bytes.
std::string receive_bytes(int from);
/// One int from every rank to every rank: out[r] is what rank r put in its mine[this rank].
std::vector<int> all_to_all(const std::vector<int>& mine);
/// Point-to-point exchange with some ranks: sends[k] goes to ranks[k], and receives[k],
/// sized by the caller (both sides know the sizes), is filled from ranks[k]. Collective
/// among the ranks named (each names the other).
void exchange(const std::vector<int>& ranks, const std::vector<std::vector<int>>& sends,
              std::vector<std::vector<int>>& receives);
void exchange(const std::vector<int>& ranks, const std::vector<std::vector<double>>& sends,
              std::vector<std::vector<double>>& receives);
/// Every rank's `data` summed element by element, the sum on every rank (nothing on one rank).
void sum_over_ranks(double* data, long long n);
/// The largest of the ranks' `value`s, on every rank.
double max_over_ranks(double value);
/// Every rank's `mine` concatenated in rank order, on every rank.
std::vector<int> gather_all(const std::vector<int>& mine);
std::vector<double> gather_all(const std::vector<double>& mine);
/// Every rank's `mine` concatenated in rank order, on every rank.
std::string gather_all(const std::string& mine);
/// Every rank's `mine` concatenated in rank order, on rank 0 only (empty elsewhere).
std::vector<int> gather_to_root(const std::vector<int>& mine);
std::vector<double> gather_to_root(const std::vector<double>& mine);
/// Rank 0's `whole` cut in the ranks' consecutive pieces: this rank gets its `mine` values
/// (the pieces in rank order; `whole` is read on rank 0 only).
std::vector<double> scatter_from_root(const std::vector<double>& whole, int mine);
/// Rank `root`'s values of `data` on every rank (nothing on one rank).
void broadcast_from(int root, double* data, long long n);
void broadcast_from(int root, std::string& bytes);

/// Finalises MPI if it was initialised (called once, at the end of main).
void finalise();

// ---- a run of several ranks: one voice, one exit status ----

/// On a rank other than 0 of a run of several ranks: the process's standard output and
/// error (file descriptors 1 and 2) go to /dev/null, so that neither the front end nor a
/// library prints the same lines once per rank. Nothing on rank 0 or in a one-rank run.
void silence_other_ranks();

/// The file descriptor of this process's standard error as it was before
/// silence_other_ranks() (STDERR_FILENO if it was not redirected): where the front end
/// writes what a rank other than 0 says when it is the one that brings the run down.
/// Callable from any thread (no MPI call).
int standard_error_fd();

/// The lowest and the highest value given by the ranks.
struct Spread {
  int lowest = 0;
  int highest = 0;
};

/// Every rank's `value` reduced over the ranks, on a communicator of its own (never
/// matched with a solver's messages). Waits `wait_seconds` at most if given (nullopt if
/// some rank did not take part in time: it is still computing, or blocked in a collective
/// call waiting for this rank), else until every rank takes part.
std::optional<Spread> spread(int value, std::optional<double> wait_seconds);

/// Every rank's `text` on rank 0, in rank order (empty elsewhere). Only after a spread()
/// that every rank completed.
std::vector<std::string> gather_texts(const std::string& text);

/// Ends every rank of the run with `exit_code` (MPI_Abort): a rank cannot leave the
/// others waiting in a collective call for it. In a one-rank run, ends the process
/// (_exit). Flushes nothing: callable from a watchdog thread.
[[noreturn]] void abort_run(int exit_code);

}  // namespace lunaster::engine::parallel

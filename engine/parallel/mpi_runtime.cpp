#include "engine/parallel/mpi_runtime.hpp"

#include <fcntl.h>
#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <type_traits>

namespace lunaster::engine::parallel {
namespace {

bool env_set(const char* name) { return std::getenv(name) != nullptr; }

/// A default for one OpenMPI MCA parameter, kept if the user set it.
void mca_default(const char* name, const char* value) { setenv(name, value, 0); }

// Rank and size, read once by ensure_initialised(): rank() is then callable from any
// thread (the budget's watchdog), which MPI_THREAD_FUNNELED does not allow for MPI calls.
std::atomic<bool> known{false};
std::atomic<int> the_rank{0};
std::atomic<int> the_size{1};
std::atomic<int> the_local_size{1};  ///< ranks of the run on this machine (shared memory)
/// The end-of-run agreement's own communicator (a duplicate of MPI_COMM_WORLD, several ranks only).
MPI_Comm end_comm = MPI_COMM_NULL;
/// Standard error as it was before silence_other_ranks(), -1 if it was not redirected.
std::atomic<int> saved_stderr{-1};

}  // namespace

bool launched_by_mpi() {
  return env_set("OMPI_COMM_WORLD_SIZE") || env_set("PMIX_RANK") || env_set("PMI_RANK") || env_set("PMI_SIZE");
}

bool initialised() {
  int flag = 0;
  MPI_Initialized(&flag);
  return flag != 0;
}

namespace {

void start_mpi() {
  if (!launched_by_mpi()) {
    // A singleton: no orted daemon to start (0.35 s of a 0.4 s start-up on this
    // machine's OpenMPI 4.1), the point-to-point layer that needs no network
    // interface, and only the self transport. Measured: 36 ms instead of 0.38 s.
    mca_default("OMPI_MCA_ess_singleton_isolated", "1");
    mca_default("OMPI_MCA_pml", "ob1");
    mca_default("OMPI_MCA_btl", "self");
    // No session directory: every isolated singleton of a user would share
    // /tmp/ompi.<host>.<uid>/jf.0, which one removes when it ends while another, starting,
    // creates its own below it (MPI_Init then fails on mkdir: about 1 run in 60 when many
    // run at once, tests/mpi/concurrent_runs.sh). A singleton with only the self transport
    // keeps nothing there.
    mca_default("OMPI_MCA_orte_create_session_dirs", "0");
  }
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  std::atexit(finalise);  // every way out of the process (return from main, std::exit) finalises
}

}  // namespace

void ensure_initialised() {
  if (!initialised()) start_mpi();
  if (known) return;
  // Also when a library initialised MPI itself: what this process is in the run is learnt once.
  int r = 0, s = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  the_rank = r;
  the_size = s;
  // Collective: every rank of an mpirun run initialises first thing in main, together.
  if (s > 1) {
    MPI_Comm_dup(MPI_COMM_WORLD, &end_comm);
    // The ranks that share this machine's memory, whatever launched them (MPI-3).
    MPI_Comm local = MPI_COMM_NULL;
    int local_size = 1;
    if (MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, r, MPI_INFO_NULL, &local) == MPI_SUCCESS &&
        local != MPI_COMM_NULL) {
      MPI_Comm_size(local, &local_size);
      MPI_Comm_free(&local);
    }
    the_local_size = std::max(1, local_size);
  }
  known = true;
}

int rank() {
  if (known || !initialised()) return the_rank.load();
  int r = 0;  // MPI initialised by a library, ensure_initialised() not called yet
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int size() {
  if (known || !initialised()) return the_size.load();
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

int ranks_on_this_machine() { return known ? the_local_size.load() : 1; }

int fortran_comm_world() {
  ensure_initialised();
  return static_cast<int>(MPI_Comm_c2f(MPI_COMM_WORLD));
}

namespace {

/// `call(offset, count)` over [0, n) in pieces that an MPI count (an int) can hold.
template <class Call>
void in_chunks(long long n, Call&& call) {
  constexpr long long kChunk = 1LL << 30;
  for (long long start = 0; start < n; start += kChunk) call(start, static_cast<int>(std::min(kChunk, n - start)));
}

}  // namespace

void broadcast(double* data, long long n) { broadcast_from(0, data, n); }

void broadcast(int* data, long long n) {
  if (size() == 1) return;
  in_chunks(n, [&](long long at, int count) { MPI_Bcast(data + at, count, MPI_INT, 0, MPI_COMM_WORLD); });
}

void broadcast(std::string& bytes) { broadcast_from(0, bytes); }

void broadcast_from(int root, std::string& bytes) {
  if (size() == 1) return;
  long long n = static_cast<long long>(bytes.size());
  MPI_Bcast(&n, 1, MPI_LONG_LONG, root, MPI_COMM_WORLD);
  bytes.resize(static_cast<size_t>(n));
  in_chunks(n, [&](long long at, int count) { MPI_Bcast(bytes.data() + at, count, MPI_BYTE, root, MPI_COMM_WORLD); });
}

void send_bytes(int to, const std::string& bytes) {
  long long n = static_cast<long long>(bytes.size());
  MPI_Send(&n, 1, MPI_LONG_LONG, to, 0, MPI_COMM_WORLD);
  in_chunks(n, [&](long long at, int count) {
    MPI_Send(bytes.data() + at, count, MPI_BYTE, to, 0, MPI_COMM_WORLD);
  });
}

std::string receive_bytes(int from) {
  long long n = 0;
  MPI_Recv(&n, 1, MPI_LONG_LONG, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  std::string bytes(static_cast<size_t>(n), '\0');
  in_chunks(n, [&](long long at, int count) {
    MPI_Recv(bytes.data() + at, count, MPI_BYTE, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  });
  return bytes;
}

std::vector<int> all_to_all(const std::vector<int>& mine) {
  if (size() == 1) return mine;
  std::vector<int> out(mine.size());
  MPI_Alltoall(mine.data(), 1, MPI_INT, out.data(), 1, MPI_INT, MPI_COMM_WORLD);
  return out;
}

namespace {

template <typename T>
void exchange_with(const std::vector<int>& ranks, const std::vector<std::vector<T>>& sends,
                   std::vector<std::vector<T>>& receives) {
  if (ranks.empty()) return;
  const MPI_Datatype type = std::is_same_v<T, double> ? MPI_DOUBLE : MPI_INT;
  std::vector<MPI_Request> requests;
  requests.reserve(2 * ranks.size());
  constexpr int kTag = 7;
  for (size_t k = 0; k < ranks.size(); ++k) {
    if (receives[k].empty()) continue;
    requests.emplace_back();
    MPI_Irecv(receives[k].data(), static_cast<int>(receives[k].size()), type, ranks[k], kTag, MPI_COMM_WORLD,
              &requests.back());
  }
  for (size_t k = 0; k < ranks.size(); ++k) {
    if (sends[k].empty()) continue;
    requests.emplace_back();
    MPI_Isend(sends[k].data(), static_cast<int>(sends[k].size()), type, ranks[k], kTag, MPI_COMM_WORLD,
              &requests.back());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}

}  // namespace

void exchange(const std::vector<int>& ranks, const std::vector<std::vector<int>>& sends,
              std::vector<std::vector<int>>& receives) {
  exchange_with(ranks, sends, receives);
}

void exchange(const std::vector<int>& ranks, const std::vector<std::vector<double>>& sends,
              std::vector<std::vector<double>>& receives) {
  exchange_with(ranks, sends, receives);
}

void sum_over_ranks(double* data, long long n) {
  if (size() == 1) return;
  in_chunks(n, [&](long long at, int count) {
    MPI_Allreduce(MPI_IN_PLACE, data + at, count, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  });
}

double max_over_ranks(double value) {
  if (size() == 1) return value;
  double out = value;
  MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return out;
}

namespace {

/// Every rank's `mine` concatenated in rank order, on every rank or on rank 0 only.
template <typename T>
std::vector<T> gather(const std::vector<T>& mine, bool everywhere) {
  if (size() == 1) return mine;
  const MPI_Datatype type = std::is_same_v<T, double> ? MPI_DOUBLE : std::is_same_v<T, char> ? MPI_CHAR : MPI_INT;
  const int ranks = size();
  std::vector<int> counts(ranks), offsets(ranks + 1, 0);
  const int count = static_cast<int>(mine.size());
  if (everywhere) MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  else MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  for (int r = 0; r < ranks; ++r) offsets[r + 1] = offsets[r] + counts[r];
  std::vector<T> all(everywhere || rank() == 0 ? offsets[ranks] : 0);
  if (everywhere)
    MPI_Allgatherv(mine.data(), count, type, all.data(), counts.data(), offsets.data(), type, MPI_COMM_WORLD);
  else
    MPI_Gatherv(mine.data(), count, type, all.data(), counts.data(), offsets.data(), type, 0, MPI_COMM_WORLD);
  return all;
}

}  // namespace

std::vector<int> gather_all(const std::vector<int>& mine) { return gather(mine, true); }

std::vector<double> gather_all(const std::vector<double>& mine) { return gather(mine, true); }

std::string gather_all(const std::string& mine) {
  const std::vector<char> all = gather(std::vector<char>(mine.begin(), mine.end()), true);
  return std::string(all.begin(), all.end());
}

std::vector<int> gather_to_root(const std::vector<int>& mine) { return gather(mine, false); }

std::vector<double> gather_to_root(const std::vector<double>& mine) { return gather(mine, false); }

std::vector<double> scatter_from_root(const std::vector<double>& whole, int mine) {
  if (size() == 1) return std::vector<double>(whole.begin(), whole.begin() + mine);
  const int ranks = size();
  std::vector<int> counts(ranks), offsets(ranks + 1, 0);
  MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  for (int r = 0; r < ranks; ++r) offsets[r + 1] = offsets[r] + counts[r];
  std::vector<double> out(mine);
  MPI_Scatterv(whole.data(), counts.data(), offsets.data(), MPI_DOUBLE, out.data(), mine, MPI_DOUBLE, 0,
               MPI_COMM_WORLD);
  return out;
}

void broadcast_from(int root, double* data, long long n) {
  if (size() == 1) return;
  in_chunks(n, [&](long long at, int count) { MPI_Bcast(data + at, count, MPI_DOUBLE, root, MPI_COMM_WORLD); });
}

void finalise() {
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (initialised() && !finalised) {
    if (end_comm != MPI_COMM_NULL) MPI_Comm_free(&end_comm);
    MPI_Finalize();
  }
}

void silence_other_ranks() {
  if (rank() == 0 || saved_stderr.load() >= 0) return;
  std::fflush(stdout);
  std::fflush(stderr);
  saved_stderr = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);
  const int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (null < 0) return;
  dup2(null, STDOUT_FILENO);
  dup2(null, STDERR_FILENO);
  close(null);
}

int standard_error_fd() {
  const int saved = saved_stderr.load();
  return saved >= 0 ? saved : STDERR_FILENO;
}

std::optional<Spread> spread(int value, std::optional<double> wait_seconds) {
  if (size() == 1 || end_comm == MPI_COMM_NULL) return Spread{value, value};
  int in[2] = {value, -value}, out[2] = {value, -value};
  MPI_Request request;
  MPI_Iallreduce(in, out, 2, MPI_INT, MPI_MAX, end_comm, &request);
  if (!wait_seconds) {
    MPI_Wait(&request, MPI_STATUS_IGNORE);
  } else {
    using clock = std::chrono::steady_clock;
    const auto deadline =
        clock::now() + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(*wait_seconds));
    for (int done = 0;;) {
      MPI_Test(&request, &done, MPI_STATUS_IGNORE);
      if (done) break;
      if (clock::now() >= deadline) return std::nullopt;  // the request is left pending: the run is aborted
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  return Spread{-out[1], out[0]};
}

std::vector<std::string> gather_texts(const std::string& text) {
  if (size() == 1 || end_comm == MPI_COMM_NULL) return {text};
  const int n = size();
  const int length = static_cast<int>(text.size());
  std::vector<int> lengths(rank() == 0 ? n : 0), offsets(rank() == 0 ? n : 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, end_comm);
  std::string all;
  if (rank() == 0) {
    long long total = 0;
    for (int r = 0; r < n; ++r) {
      offsets[r] = static_cast<int>(total);
      total += lengths[r];
    }
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0, end_comm);
  std::vector<std::string> texts;
  if (rank() == 0)
    for (int r = 0; r < n; ++r) texts.push_back(all.substr(static_cast<std::size_t>(offsets[r]), lengths[r]));
  return texts;
}

void abort_run(int exit_code) {
  if (initialised() && size() > 1) {
    // Called by the budget's watchdog thread too: MPI_THREAD_FUNNELED does not provide for
    // that, but OpenMPI's MPI_Abort only asks the launcher (PMIx, thread-safe) to end the run,
    // and ends it within moments where a plain exit takes mpirun a second or two to notice.
    // Should it ever not return nor end the process, this rank ends anyway.
    std::thread([exit_code] {
      std::this_thread::sleep_for(std::chrono::seconds(5));
      _exit(exit_code);
    }).detach();
    MPI_Abort(MPI_COMM_WORLD, exit_code);
  }
  _exit(exit_code);
}

}  // namespace lunaster::engine::parallel

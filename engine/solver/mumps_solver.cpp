/// MUMPS (Debian's MPI build) through the C interface. Assembled input in coordinate
/// form (1-based); for symmetric kinds only the upper triangle is passed. One process is a
/// one-rank run (MPI initialised on the first factorisation); under mpirun every rank takes
/// part in the factorisation and the solution is broadcast from the host. The matrix is
/// centralised on the host, rank 0, unless the layout is distributed (each rank's matrix
/// holds its own columns): then each rank passes the entries of its columns (ICNTL(18) = 3),
/// and no rank ever holds the whole matrix. Null-pivot detection (ICNTL(24) = 1, its threshold from the
/// SingularityTest) reports singular matrices and the first null pivot's equation, or sets the null
/// pivots aside when the run goes on past them. In double precision (DMUMPS), or in single
/// (SMUMPS, SOLVEUR MIXER_PRECISION); in full rank, or in block low rank (SOLVEUR ACCELERATION).
#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <dmumps_c.h>
#include <iomanip>
#include <smumps_c.h>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/core/memory.hpp"
#include "engine/parallel/mpi_runtime.hpp"
#include "engine/solver/backends.hpp"
#include "engine/solver/blas.hpp"
#include "engine/solver/mumps_entries.hpp"

namespace lunaster::engine {
namespace {

/// `what` (an option of the factorisation) refused on a mesh in parts; `instead` says what to ask.
/// Typed (Failure::What::NotInParts) for commands/ to name the deck's keyword.
DeckError not_in_parts(const std::string& what, const std::string& instead) {
  DeckError error("MUMPS: " + what + " is not available on a mesh in parts", {instead + ", or read the mesh whole"});
  error.failure().what = Failure::What::NotInParts;
  return error;
}

/// The ordering `give` (given_ordering) of a matrix shared among the ranks, each holding its
/// own columns complete: every rank sends its columns' patterns to rank 0, which orders the
/// whole pattern. Collective; the order on rank 0, empty on the others.
std::vector<int> shared_matrix_ordering(const SparseMatrix& mine, FactorOrdering give) {
  std::vector<int> packed;  // per non-empty column: its index, its number of rows, the rows
  packed.reserve(static_cast<size_t>(mine.nonZeros()) + 2 * static_cast<size_t>(mine.cols()));
  for (int c = 0; c < mine.outerSize(); ++c) {
    const int begin = mine.outerIndexPtr()[c];
    const int end = mine.isCompressed() ? mine.outerIndexPtr()[c + 1] : begin + mine.innerNonZeroPtr()[c];
    if (end == begin) continue;
    packed.push_back(c);
    packed.push_back(end - begin);
    packed.insert(packed.end(), mine.innerIndexPtr() + begin, mine.innerIndexPtr() + end);
  }
  const std::vector<int> all = parallel::gather_to_root(packed);
  std::vector<int>().swap(packed);
  if (parallel::rank() != 0) return {};
  const int n = static_cast<int>(mine.cols());
  // The whole pattern, column by column; a column sent by two ranks gets the union of its
  // rows (sorted, each once).
  std::vector<int> count(n + 1, 0);
  for (size_t k = 0; k < all.size(); k += 2 + static_cast<size_t>(all[k + 1])) count[all[k] + 1] += all[k + 1];
  for (int c = 0; c < n; ++c) count[c + 1] += count[c];
  std::vector<int> rows(static_cast<size_t>(count[n])), fill(count.begin(), count.end() - 1);
  for (size_t k = 0; k < all.size(); k += 2 + static_cast<size_t>(all[k + 1]))
    fill[all[k]] = static_cast<int>(std::copy(all.begin() + static_cast<long>(k) + 2,
                                              all.begin() + static_cast<long>(k) + 2 + all[k + 1],
                                              rows.begin() + fill[all[k]]) -
                                    rows.begin());
  SparseMatrix whole(n, n);
  whole.resizeNonZeros(count[n]);
  int kept = 0;
  for (int c = 0; c < n; ++c) {
    const auto first = rows.begin() + count[c], last = rows.begin() + count[c + 1];
    std::sort(first, last);
    whole.outerIndexPtr()[c] = kept;
    kept = static_cast<int>(std::unique_copy(first, last, whole.innerIndexPtr() + kept) - whole.innerIndexPtr());
  }
  whole.outerIndexPtr()[n] = kept;
  whole.resizeNonZeros(kept);  // keeps the first `kept` entries
  std::fill(whole.valuePtr(), whole.valuePtr() + kept, 1.0);
  return given_ordering(whole, give);
}

void mumps_call(DMUMPS_STRUC_C* id) { dmumps_c(id); }
void mumps_call(SMUMPS_STRUC_C* id) {
  // SMUMPS serves SOLVEUR MIXER_PRECISION only: loaded on its first call rather than linked,
  // which would map it into every run (about 1.5 ms of each start).
  using Call = void (*)(SMUMPS_STRUC_C*);
  static const Call call = [] {
    void* handle = dlopen(LUNASTER_SMUMPS_LIBRARY, RTLD_NOW | RTLD_GLOBAL);
    void* symbol = handle ? dlsym(handle, "smumps_c") : nullptr;
    if (!symbol)
      throw SolveError(std::string("MUMPS in single precision: cannot load ") + LUNASTER_SMUMPS_LIBRARY + ": " +
                           dlerror(),
                       {"install Debian's libmumps-dev (scripts/install-deps.sh names it), or factorise in "
                        "double precision"});
    return reinterpret_cast<Call>(symbol);
  }();
  call(id);
}

/// MUMPS in the precision of its instance `Id`: DMUMPS_STRUC_C (double, the default) or
/// SMUMPS_STRUC_C (single: code_aster's SOLVEUR MIXER_PRECISION = 'OUI', the factors in half the
/// memory, each solve's right-hand side and solution rounded to single precision; the
/// driver's iterative refinement, in double precision, takes the solve to the accuracy asked).
template <class Id>
class MumpsSolver final : public LinearSolver {
 public:
  using Real = std::remove_pointer_t<decltype(Id::a)>;
  static constexpr bool kSingle = std::is_same_v<Real, float>;
  MumpsSolver() = default;
  ~MumpsSolver() override { release(); }
  MumpsSolver(const MumpsSolver&) = delete;
  MumpsSolver& operator=(const MumpsSolver&) = delete;

  void factorize(const SparseMatrix& a, MatrixKind kind) override;
  Vector solve(const Vector& b) const override;
  std::string name() const override { return kSingle ? "MUMPS in single precision" : "MUMPS"; }
  int failed_column() const override { return failed_; }
  void set_layout(SystemLayout layout) override {
    parts_ = layout.in_parts();
    distributed_ = layout.distributed() || parts_;
    global_ = std::move(layout.global);
    first_ = layout.first, n_global_ = layout.n_global, n_owned_ = layout.n_owned;
  }
  void configure(const FactorSettings& settings) override { settings_ = settings; }
  std::string ordering_used() const override;
  std::string approximation_note() const override;
  std::string factorisation_used() const override {
    if (settings_.by_kind || !initialised_) return {};
    return id_.sym == 0 ? "LU (SYM = 0)" : id_.sym == 2 ? "LDL^T with pivoting (SYM = 2)" : "LDL^T (SYM = 1)";
  }
  std::string memory_used() const override { return memory_note_; }
  bool takes_distributed() const override { return true; }
  bool takes_parts() const override { return true; }
  int singular_column() const override { return singular_; }
  std::string singular_note() const override { return singular_note_; }

 private:
  void release() {
    if (!initialised_) return;
    id_.job = -2;
    mumps_call(&id_);
    initialised_ = false;
    analysed_ = false;
  }
  /// MUMPS's numeric factorisation (job 2) on the analysis in id_, with two BLAS threads where
  /// the analysis estimated a large one (wide_).
  void factorise_numerically() {
    // Null pivots as code_aster detects them (SOLVEUR NPREC): below 10^-NPREC in MUMPS's
    // scaled matrix (CNTL(3) < 0: that absolute threshold; the scaling makes it independent of
    // the units), set to 1e20 (CNTL(5)) so that the solution is zero along them; NPREC < 0: no
    // detection. A symmetric positive definite factorisation (SYM = 1) detects none (it stops
    // on an exact zero only): the driver's check factorises K_ff with CHOLMOD for it.
    const bool detect = settings_.singularity.digits >= 0;
    id_.icntl[23] = detect ? 1 : 0;  // ICNTL(24)
    id_.cntl[2] = detect ? -settings_.singularity.pivot_ratio() : 0.0;
    id_.cntl[4] = detect ? 1e20 : 0.0;
    id_.job = 2;
    const WideBlas threads(wide_);
    mumps_call(&id_);
  }
  /// MUMPS's SYM for a matrix of this kind: the kind's own, or the factorisation asked for where
  /// the matrix allows it (DeckError where it does not); an SPD matrix whose null pivots are to
  /// be gone past is factorised as symmetric indefinite.
  int symmetry(MatrixKind kind) const;
  /// The entries handed to MUMPS for SYM = sym, 1-based (a symmetric kind's upper triangle; in
  /// parts the owned columns, numbered across the ranks), filtered when asked.
  void gather_entries(const SparseMatrix& a, int sym, std::vector<MUMPS_INT>& irn, std::vector<MUMPS_INT>& jcn,
                      std::vector<Real>& val);
  /// A new instance (job -1) for SYM = sym with the run's controls: outputs silenced, working
  /// space, preprocessing, block low rank.
  void initialise(int sym);
  /// ICNTL(7) (and PERM_IN) for the next analysis of `a`, n equations.
  void choose_ordering(const SparseMatrix& a, int sym, long long n);
  /// The ordering `give` computed on the host and given to MUMPS (ICNTL(7) = 1, PERM_IN); a failed
  /// one asked for is a SolveError, the automatic choice then left to MUMPS. Collective.
  void give_ordering(const SparseMatrix& a, FactorOrdering give);
  /// A new instance, its analysis (job 1) of the entries in irn_, jcn_, val_, then the numeric
  /// factorisation if the analysis went well.
  void analyse(const SparseMatrix& a, int sym, long long n);
  /// The null pivots of the last factorisation: gone past as asked (singular_), or SolveError.
  void check_null_pivots();
  void choose_memory();
  void filter_entries(const SparseMatrix& a, std::vector<MUMPS_INT>& irn, std::vector<MUMPS_INT>& jcn,
                      std::vector<Real>& val);
  static bool workspace_too_small(int infog1) {
    return infog1 == -8 || infog1 == -9 || infog1 == -14 || infog1 == -15 || infog1 == -17 || infog1 == -20;
  }
  void check(const char* phase) const {
    if (id_.infog[0] >= 0) return;
    const int code = id_.infog[0], detail = id_.infog[1];
    // -13: an allocation failed; the others: a workspace was still too small after the
    // retries of factorize() (INFOG(2) says by how much).
    if (code == -13 || workspace_too_small(code))
      throw SolveError::out_of_memory("MUMPS", id_.n, std::string("during ") + phase + ", INFOG(1) = " +
                                      std::to_string(code) + ", INFOG(2) = " + std::to_string(detail));
    if (code == -10)
      throw SolveError(std::string("MUMPS: numerically singular matrix during ") + phase,
                       {"check the boundary conditions (rigid-body modes) and the contact definition"});
    throw SolveError(std::string("MUMPS: error during ") + phase + ": INFOG(1) = " + std::to_string(code) +
                     ", INFOG(2) = " + std::to_string(detail));
  }

  mutable Id id_{};
  bool initialised_ = false;
  bool analysed_ = false;  ///< the analysis in id_ is valid for (sym, irn_, jcn_)
  std::vector<MUMPS_INT> irn_, jcn_;
  std::vector<Real> val_;
  std::vector<MUMPS_INT> perm_in_;  ///< ICNTL(7) = 1: each equation's place in the given order
  int failed_ = -1;
  bool distributed_ = false;  ///< the matrices given are this rank's columns (ICNTL(18) = 3)
  /// A system of a mesh in parts (SystemLayout::in_parts): the matrices are this rank's, in its
  /// local numbering, global_ gives each equation's number across the ranks; the right-hand
  /// sides and solutions are the owned equations' (first_ .. first_ + n_owned_ - 1), gathered on
  /// the host for MUMPS's centralised solve and cut back into the ranks' pieces after it.
  bool parts_ = false;
  std::vector<long long> global_;
  long long first_ = 0, n_global_ = 0;
  int n_owned_ = 0;
  /// The equations of this system (the whole system's with parts).
  long long n_equations(const SparseMatrix& a) const { return parts_ ? n_global_ : a.rows(); }
  /// A null pivot's equation (1-based across the ranks with parts) as this rank's equation, -1
  /// if another rank's.
  int local_equation(MUMPS_INT one_based) const {
    if (!parts_) return one_based - 1;
    const long long g = one_based - 1;
    return g >= first_ && g < first_ + n_owned_ ? static_cast<int>(g - first_) : -1;
  }
  bool wide_ = false;         ///< factorised with two BLAS threads (per analysis)
  /// Ordering, memory, ICNTL(14), preprocessing, block low rank, TYPE_RESOL, the null-pivot test
  /// (ICNTL(24), CNTL(3), CNTL(5)) and the filter of the next analyses and factorisations.
  FactorSettings settings_;
  FactorOrdering given_ = FactorOrdering::Auto;  ///< the ordering given to the last analysis (ICNTL(7) = 1)
  int singular_ = -1;     ///< the first null pivot the last factorisation went past, or -1
  std::pair<double, double> filtered_;  ///< the last matrix's entries left out and entries, over the ranks
  std::string singular_note_;
  std::string memory_note_;  ///< memory_used() of the last analysis
};

/// The first number in a file (a cgroup's limit or usage, in bytes), negative when there is none
/// ("max", no such file).
double number_in(const char* path) {
  std::FILE* f = std::fopen(path, "r");
  if (!f) return -1.0;
  double value = -1.0;
  if (std::fscanf(f, "%lf", &value) != 1) value = -1.0;
  std::fclose(f);
  return value;
}

/// Memory this process may still take, in MB: the machine's MemAvailable, or less where the
/// process's memory cgroup (v1 or v2, as /proc/self/cgroup names it) leaves less under its limit
/// (a container), shared among the ranks of the run on this machine; and no more than the run's
/// memory budget leaves this process (engine/core/memory.hpp: a budget is per process). Negative
/// when unknown.
double available_megabytes() {
  std::FILE* f = std::fopen("/proc/meminfo", "r");
  if (!f) return -1.0;
  char line[256];
  double kb = -1.0;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, "MemAvailable: %lf kB", &kb) == 1) break;
  std::fclose(f);
  if (kb < 0.0) return -1.0;
  double bytes = kb * 1024.0;
  // The process's cgroup, from /proc/self/cgroup: "0::/path" (v2) or "N:...memory...:/path" (v1).
  std::string v2, v1;
  if (std::FILE* g = std::fopen("/proc/self/cgroup", "r")) {
    while (std::fgets(line, sizeof line, g)) {
      std::string entry(line);
      if (!entry.empty() && entry.back() == '\n') entry.pop_back();
      const size_t first = entry.find(':'), second = entry.find(':', first + 1);
      if (first == std::string::npos || second == std::string::npos) continue;
      const std::string controllers = entry.substr(first + 1, second - first - 1), path = entry.substr(second + 1);
      if (controllers.empty()) v2 = path;
      else if (("," + controllers + ",").find(",memory,") != std::string::npos) v1 = path;
    }
    std::fclose(g);
  }
  double limit = -1.0, used = -1.0;
  if (!v1.empty()) {
    limit = number_in(("/sys/fs/cgroup/memory" + v1 + "/memory.limit_in_bytes").c_str());
    used = number_in(("/sys/fs/cgroup/memory" + v1 + "/memory.usage_in_bytes").c_str());
  } else if (!v2.empty()) {
    limit = number_in(("/sys/fs/cgroup" + v2 + "/memory.max").c_str());
    used = number_in(("/sys/fs/cgroup" + v2 + "/memory.current").c_str());
  }
  if (limit > 0.0 && limit < 1e18 && used >= 0.0) bytes = std::min(bytes, std::max(0.0, limit - used));
  bytes /= parallel::ranks_on_this_machine();
  if (const std::size_t budget = memory_budget(); budget > 0)
    bytes = std::min(bytes, std::max(0.0, static_cast<double>(budget) - static_cast<double>(resident_bytes())));
  return bytes / (1024.0 * 1024.0);
}

template <class Id>
void MumpsSolver<Id>::choose_memory() {
  // After the analysis, before the factorisation: INFOG(16) is the largest per-process
  // estimate of the in-core factorisation (MB), INFOG(26) the same out of core.
  memory_note_.clear();
  bool out = settings_.memory == FactorMemory::OutOfCore;
  double available = -1.0;
  if (settings_.memory == FactorMemory::Auto) {
    available = available_megabytes();
    double short_of_memory = available >= 0.0 && id_.infog[15] > 0.8 * available ? 1.0 : 0.0;
    if (parallel::size() > 1) short_of_memory = parallel::max_over_ranks(short_of_memory);  // every rank alike
    out = short_of_memory > 0.0;
  }
  id_.icntl[21] = out ? 1 : 0;  // ICNTL(22)
  if (!out) return;
  const char* tmp = std::getenv("TMPDIR");
  const std::string dir = tmp && *tmp ? tmp : "/tmp";
  const std::string prefix = "lunaster_" + std::to_string(static_cast<long>(::getpid())) + "_";
  std::snprintf(id_.ooc_tmpdir, sizeof id_.ooc_tmpdir, "%s", dir.c_str());
  std::snprintf(id_.ooc_prefix, sizeof id_.ooc_prefix, "%s", prefix.c_str());
  memory_note_ = "out of core, factors in " + dir + " (estimated " + std::to_string(id_.infog[25]) +
                 " MB a process, against " + std::to_string(id_.infog[15]) + " MB in core" +
                 (available >= 0.0 ? ", " + std::to_string(static_cast<long>(available)) + " MB available" +
                                         (memory_budget() > 0 ? " under the run's memory limit)" : ")")
                                   : ")");
}

template <class Id>
void MumpsSolver<Id>::filter_entries(const SparseMatrix& a, std::vector<MUMPS_INT>& irn, std::vector<MUMPS_INT>& jcn,
                                     std::vector<Real>& val) {
  // code_aster's MUMPS driver (FILTRAGE_MATRICE): each row's share filter |a_ii|, and an entry
  // is kept when it is larger than the sum of its row's and its column's shares. A column may
  // lie on several ranks (its parts summed by MUMPS): so are the diagonal's parts here.
  Vector share = Vector::Zero(a.rows());
  for (int c = 0; c < a.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(a, c); it; ++it)
      if (it.row() == c) share[c] += it.value();
  if (distributed_) parallel::sum_over_ranks(share.data(), share.size());
  share = settings_.filter * share.cwiseAbs();
  std::size_t kept = 0;
  for (std::size_t k = 0; k < val.size(); ++k) {
    if (!(std::abs(static_cast<double>(val[k])) > share[irn[k] - 1] + share[jcn[k] - 1])) continue;
    irn[kept] = irn[k], jcn[kept] = jcn[k], val[kept] = val[k];
    ++kept;
  }
  filtered_ = {static_cast<double>(val.size() - kept), static_cast<double>(val.size())};
  irn.resize(kept), jcn.resize(kept), val.resize(kept);
  if (distributed_) parallel::sum_over_ranks(&filtered_.first, 1), parallel::sum_over_ranks(&filtered_.second, 1);
}

template <class Id>
int MumpsSolver<Id>::symmetry(MatrixKind kind) const {
  int sym = kind == MatrixKind::SymmetricPositiveDefinite ? 1 : (kind == MatrixKind::SymmetricIndefinite ? 2 : 0);
  if (!settings_.by_kind) {  // TYPE_RESOL: the factorisation asked for, where the matrix allows it
    const MatrixKind asked = settings_.factorisation;
    if (asked == MatrixKind::General) {
      sym = 0;
    } else if (kind == MatrixKind::General) {
      throw DeckError("MUMPS: a symmetric factorisation was asked for a system that is not symmetric",
                      {"ask for a general (LU) factorisation, or let the system's kind choose"});
    } else if (asked == MatrixKind::SymmetricIndefinite) {
      sym = 2;
    } else if (kind != MatrixKind::SymmetricPositiveDefinite) {
      throw DeckError("MUMPS: a positive definite factorisation (LDL^T without pivoting) was asked for a symmetric "
                      "indefinite system (contact or relation multipliers)",
                      {"ask for a symmetric indefinite or general factorisation, or let the system's kind choose"});
    }
  }
  // Going on past null pivots needs them detected and set aside, which SYM = 1 does not do
  // (its round-off pivot along a free body's motion would move it by 1e13): an SPD system is
  // then factorised as symmetric indefinite.
  if (sym == 1 && !settings_.singularity.stop && settings_.singularity.digits >= 0) sym = 2;
  return sym;
}

template <class Id>
void MumpsSolver<Id>::gather_entries(const SparseMatrix& a, int sym, std::vector<MUMPS_INT>& irn,
                                     std::vector<MUMPS_INT>& jcn, std::vector<Real>& val) {
  if (parts_) {
    // The owned columns, numbered across the ranks; a symmetric kind keeps the upper triangle in
    // that numbering, each entry on the one rank owning its column.
    LUNASTER_ASSERT(static_cast<Eigen::Index>(global_.size()) == a.rows() && n_global_ < (1LL << 31),
                    "MUMPS: a system in parts without its numbering");
    if (settings_.filter > 0.0) throw not_in_parts("filtering the matrix's small entries", "keep every entry");
    for (int c = 0; c < a.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(a, c); it; ++it) {
        const long long gi = global_[it.row()], gj = global_[c];
        if (sym != 0 && gi > gj) continue;
        irn.push_back(static_cast<MUMPS_INT>(gi + 1));
        jcn.push_back(static_cast<MUMPS_INT>(gj + 1));
        val.push_back(static_cast<Real>(it.value()));
      }
  } else {
    mumps_entries(a, sym, irn, jcn, val);
    if (settings_.filter > 0.0) filter_entries(a, irn, jcn, val);
  }
}

template <class Id>
void MumpsSolver<Id>::initialise(int sym) {
  id_ = Id{};
  id_.comm_fortran = parallel::fortran_comm_world();
  id_.par = 1;
  id_.sym = sym;
  id_.job = -1;
  mumps_call(&id_);
  check("initialisation");
  initialised_ = true;
  id_.icntl[0] = -1;  // ICNTL(1..4): silence error, diagnostic, global output and statistics
  id_.icntl[1] = -1;
  id_.icntl[2] = -1;
  id_.icntl[3] = 0;
  // ICNTL(14): the working space beyond the analysis's estimate (PCENT_PIVOT). MUMPS's own
  // default unless one was asked for (5.5 on one process: 5 % for SYM = 1, 20 % otherwise).
  if (settings_.workspace_relaxation > 0) id_.icntl[13] = settings_.workspace_relaxation;
  // PRETRAITEMENTS = 'SANS': the matrix as assembled, no scaling (ICNTL(8) = 0), no
  // permutation to a zero-free or heavy diagonal (ICNTL(6) = 0) and no 2x2 pivots chosen
  // by it (ICNTL(12) = 1). MUMPS's own choices otherwise (77, 7 and 0, its defaults).
  if (!settings_.preprocessing) id_.icntl[5] = 0, id_.icntl[7] = 0, id_.icntl[11] = 1;
  // ACCELERATION = 'LR': block low-rank factors, as code_aster sets them with a public MUMPS
  // (ICNTL(35) = 1, MUMPS's automatic BLR; CNTL(7) the dropping threshold, LOW_RANK_SEUIL;
  // a negative LOW_RANK_SEUIL asks for the UCFS variant, ICNTL(36) = 1). Fixed at the analysis.
  set_low_rank(id_, settings_.low_rank);
}

template <class Id>
void MumpsSolver<Id>::choose_ordering(const SparseMatrix& a, int sym, long long n) {
  // ICNTL(7): the fill-reducing ordering. On sparse rows (2D meshes: 18 to 26 entries a row
  // for QUAD4/QUAD8) AMD beat the automatic choice (PORD's nested dissection: Debian 12's
  // MUMPS 5.5 is built without METIS and SCOTCH, and says so when asked for them), whose
  // analysis cost more than it saved: SSNP121 2D contact, k = 16, 1.7 s against 2.0 s; k = 32,
  // 7.5 s against 8.7 s. On 3D rows (81 and more) nested dissection wins: the 3D HEXA8/HEXA20
  // contact case took 2.0 s against 3.2 s with AMD. tests/bench/README.md has the runs.
  double entries = static_cast<double>(val_.size());
  if (distributed_) parallel::sum_over_ranks(&entries, 1);
  const double entries_per_row = 2.0 * entries / std::max<double>(1.0, static_cast<double>(n));
  id_.icntl[6] = sym != 0 && entries_per_row < 40.0 ? 0 : 7;
  // On 3D rows, nested dissection of the node graph (METIS, the ordering CHOLMOD uses there)
  // is given instead (ICNTL(7) = 1): fewer operations than PORD on the SSNP121 3D contact
  // systems (CONTINUE 3D benchmark 1.0e10 against 1.2e10; the refined case 2.03e12 against
  // 2.43e12). An ordering asked for (RENUM) replaces the choice. METIS, reverse
  // Cuthill-McKee and the natural order are computed on the host and given (PERM_IN), from
  // the whole matrix's pattern: a matrix shared among the ranks sends its columns' patterns
  // to the host for it, as MUMPS's own (sequential) analysis gathers them there.
  perm_in_.clear();
  given_ = FactorOrdering::Auto;
  FactorOrdering give = FactorOrdering::Auto;
  // A mesh in parts gives no ordering: MUMPS's own (its analysis gathers the pattern itself).
  if (parts_ && (settings_.ordering == FactorOrdering::Metis || settings_.ordering == FactorOrdering::Rcm ||
                 settings_.ordering == FactorOrdering::Natural))
    throw not_in_parts("the " + ordering_name(settings_.ordering) + " ordering, computed from the whole matrix's "
                       "pattern on one process,",
                       "choose the AMD, AMF, QAMD or PORD ordering, or the backend's choice");
  switch (settings_.ordering) {
    case FactorOrdering::Auto:
      if (!parts_ && sym != 0 && entries_per_row >= 40.0 && a.rows() >= 10000) give = FactorOrdering::Metis;
      break;
    case FactorOrdering::Metis:
    case FactorOrdering::Rcm:
    case FactorOrdering::Natural: give = settings_.ordering; break;
    case FactorOrdering::Amd: id_.icntl[6] = 0; break;
    case FactorOrdering::Amf: id_.icntl[6] = 2; break;
    case FactorOrdering::Qamd: id_.icntl[6] = 6; break;
    case FactorOrdering::Pord: id_.icntl[6] = 4; break;
  }
  if (give != FactorOrdering::Auto) give_ordering(a, give);
}

template <class Id>
void MumpsSolver<Id>::give_ordering(const SparseMatrix& a, FactorOrdering give) {
  SparseMatrix compressed;
  const SparseMatrix* m = &a;
  if (!a.isCompressed()) compressed = a, compressed.makeCompressed(), m = &compressed;
  std::vector<int> perm;
  if (distributed_) perm = shared_matrix_ordering(*m, give);  // collective; empty but on the host
  else if (parallel::rank() == 0) perm = given_ordering(*m, give);
  int ok = perm.empty() ? 0 : 1;
  if (parallel::size() > 1) parallel::broadcast(&ok, 1);  // the host's verdict, on every rank
  if (ok) {
    if (parallel::rank() == 0) {
      perm_in_.resize(perm.size());
      for (size_t k = 0; k < perm.size(); ++k) perm_in_[perm[k]] = static_cast<MUMPS_INT>(k + 1);
      id_.perm_in = perm_in_.data();
    }
    id_.icntl[6] = 1;
    given_ = give;
  } else if (settings_.ordering != FactorOrdering::Auto) {
    throw SolveError("MUMPS: the " + ordering_name(give) + " ordering failed");
  }
}

template <class Id>
void MumpsSolver<Id>::analyse(const SparseMatrix& a, int sym, long long n) {
  release();
  initialise(sym);
  choose_ordering(a, sym, n);
  id_.icntl[17] = distributed_ ? 3 : 0;  // ICNTL(18): distributed assembled entries, pattern and values
  id_.n = static_cast<MUMPS_INT>(n);
  give_mumps_entries(id_, distributed_, irn_, jcn_, val_);
  id_.job = 1;  // analysis
  mumps_call(&id_);
  // A factorisation estimated at over 5e10 operations (RINFOG(1): the refined 3D CONTINUE
  // benchmark's 2.0e12) has fronts large enough for two BLAS threads; the CONTINUE 3D
  // benchmark's (1.0e10) ran no faster on two.
  wide_ = id_.infog[0] >= 0 && id_.rinfog[0] > 5e10;
  if (id_.infog[0] >= 0) {
    choose_memory();
    factorise_numerically();
  }
}

template <class Id>
void MumpsSolver<Id>::factorize(const SparseMatrix& a, MatrixKind kind) {
  failed_ = -1;
  LUNASTER_ASSERT(a.rows() == a.cols(), "MUMPS: matrix is not square");
  const int sym = symmetry(kind);
  std::vector<MUMPS_INT> irn, jcn;
  std::vector<Real> val;
  gather_entries(a, sym, irn, jcn, val);
  const long long n = n_equations(a);
  // The Newton and contact loops of a step factorise matrices of one pattern again and
  // again: keep MUMPS's analysis (ordering, symbolic factorisation) while it holds.
  bool same_pattern = analysed_ && sym == id_.sym && static_cast<MUMPS_INT>(n) == id_.n &&
                      distributed_ == (id_.icntl[17] == 3) && irn == irn_ && jcn == jcn_;
  // Every rank takes the same branch (each sees only its part of the pattern).
  if (distributed_) same_pattern = parallel::max_over_ranks(same_pattern ? 0.0 : 1.0) == 0.0;
  irn_.swap(irn);
  jcn_.swap(jcn);
  val_.swap(val);
  if (same_pattern) {
    give_mumps_entries(id_, distributed_, irn_, jcn_, val_);
    factorise_numerically();  // the analysis kept
  } else {
    analyse(a, sym, n);
  }
  // -8/-9/-14/-15/-17/-20: a workspace sized from the analysis' estimate was too small
  // (off-diagonal pivoting on contact systems grows the factors): factorise again with
  // twice the relaxation ICNTL(14), three times at most, before calling it out of memory.
  for (int retry = 0; retry < 3 && workspace_too_small(id_.infog[0]); ++retry) {
    id_.icntl[13] = 2 * std::max(20, id_.icntl[13]);
    factorise_numerically();  // again, same analysis
  }
  // An asked-for relaxation: what the factorisation allocated with it, in memory (INFOG(18), the
  // largest process's MB), and the relaxation it ended with (doubled if it ran short).
  if (settings_.workspace_relaxation > 0 && id_.infog[0] >= 0 && id_.icntl[21] == 0)
    memory_note_ = "in memory, " + std::to_string(id_.infog[17]) + " MB a process (working space: the analysis's "
                   "estimate + " + std::to_string(id_.icntl[13]) + " %)";
  analysed_ = id_.infog[0] >= 0;  // reuse an analysis only after a good factorisation
  if (id_.infog[0] == -10 && sym == 1) {
    // LDL^T without pivoting met a zero/negative pivot: redo as symmetric
    // indefinite, whose null-pivot detection names the equation (or which
    // succeeds if the matrix is merely indefinite).
    release();
    factorize(a, MatrixKind::SymmetricIndefinite);
    return;
  }
  check("factorisation");
  check_null_pivots();
}

template <class Id>
void MumpsSolver<Id>::check_null_pivots() {
  singular_ = -1;
  singular_note_.clear();
  if (id_.infog[27] > 0 && !settings_.singularity.stop) {  // INFOG(28): number of null pivots; kept as asked
    singular_ = id_.pivnul_list ? local_equation(id_.pivnul_list[0]) : -1;
    singular_note_ = std::to_string(id_.infog[27]) + " null pivot(s) below 1e-" +
                     std::to_string(settings_.singularity.digits) +
                     " in the scaled matrix, set to 1e20: the solution is zero along them";
  } else if (id_.infog[27] > 0) {
    failed_ = id_.pivnul_list ? local_equation(id_.pivnul_list[0]) : -1;
    release();
    throw SolveError("MUMPS: singular matrix" + (failed_ >= 0 ? " at equation " + std::to_string(failed_) : std::string()),
                     {"check the boundary conditions (rigid-body modes) and the contact definition"});
  }
}

template <class Id>
std::string MumpsSolver<Id>::approximation_note() const {
  if (!initialised_ || id_.infog[0] < 0) return {};
  std::ostringstream out;
  if (settings_.filter > 0.0)
    out << std::setprecision(3) << "matrix filtered (" << settings_.filter
        << "): " << static_cast<long long>(filtered_.first) << " of " << static_cast<long long>(filtered_.second)
        << " entries left out";
  if (!settings_.low_rank.on) return out.str();
  if (settings_.filter > 0.0) out << "; ";
  // INFOG(35): the factor entries the compressed factorisation kept; INFOG(29): the same
  // factorisation's entries in full rank. Negative: in millions.
  auto entries = [](MUMPS_INT v) { return v < 0 ? -1e6 * v : static_cast<double>(v); };
  const double kept = entries(id_.infog[34]), full = entries(id_.infog[28]);
  out << std::setprecision(3) << "block low-rank factors (threshold " << std::abs(settings_.low_rank.threshold)
      << (settings_.low_rank.threshold < 0.0 ? ", UCFS" : "") << "): " << kept << " entries against " << full
      << " in full rank (" << std::setprecision(1) << std::fixed << 100.0 * kept / std::max(1.0, full) << " %)";
  return out.str();
}

template <class Id>
std::string MumpsSolver<Id>::ordering_used() const {
  if (!initialised_) return {};
  switch (id_.infog[6]) {  // INFOG(7): the ordering the analysis used
    case 0: return "AMD";
    case 1: return ordering_name(given_) + ", given";
    case 2: return "AMF";
    case 3: return "SCOTCH";
    case 4: return "PORD";
    case 5: return "METIS";
    case 6: return "QAMD";
    default: return "ICNTL(7) = " + std::to_string(id_.infog[6]);
  }
}

template <class Id>
Vector MumpsSolver<Id>::solve(const Vector& b) const {
  if (!initialised_) throw InternalError("MUMPS: solve called without a valid factorisation");
  if (parts_) {
    // The owned equations' values, in rank order: the whole right-hand side on the host.
    LUNASTER_ASSERT(b.size() == static_cast<Eigen::Index>(global_.size()), "MUMPS: a right-hand side of another part");
    std::vector<double> host = parallel::gather_to_root(std::vector<double>(b.data(), b.data() + n_owned_));
    if (parallel::rank() == 0) {
      std::vector<Real> rhs(host.begin(), host.end());
      id_.rhs = rhs.data();
      id_.nrhs = 1;
      id_.lrhs = static_cast<MUMPS_INT>(rhs.size());
      id_.job = 3;
      mumps_call(&id_);
      std::copy(rhs.begin(), rhs.end(), host.begin());
    } else {
      id_.job = 3;
      mumps_call(&id_);
    }
    check("solve");
    const std::vector<double> mine = parallel::scatter_from_root(host, n_owned_);
    Vector x = Vector::Zero(b.size());
    std::copy(mine.begin(), mine.end(), x.data());
    return x;
  }
  Vector x = b;
  auto run = [this](Real* rhs, Eigen::Index n) {
    id_.rhs = rhs;
    id_.nrhs = 1;
    id_.lrhs = static_cast<MUMPS_INT>(n);
    id_.job = 3;
    mumps_call(&id_);
    check("solve");
  };
  if constexpr (kSingle) {
    std::vector<float> rhs(b.data(), b.data() + b.size());
    run(rhs.data(), b.size());
    std::copy(rhs.begin(), rhs.end(), x.data());
  } else {
    run(x.data(), x.size());
  }
  parallel::broadcast(x.data(), x.size());  // the solution is on the host
  return x;
}

}  // namespace

std::unique_ptr<LinearSolver> make_mumps_solver(bool single_precision) {
  if (single_precision) return std::make_unique<MumpsSolver<SMUMPS_STRUC_C>>();
  return std::make_unique<MumpsSolver<DMUMPS_STRUC_C>>();
}

}  // namespace lunaster::engine

/// PETSc's Krylov solvers and preconditioners behind LinearSolver. Built as a
/// module of its own (liblunaster_petsc.so), loaded by engine/solver/petsc_module.cpp
/// on the first METHODE='PETSC' solve: PETSc and the hundred libraries it brings
/// (hypre, ML, SuperLU, ScaLAPACK...) would otherwise add 50 ms to every start-up.
///
/// One process: a sequential AIJ matrix. Under mpirun: each rank owns a block of rows
/// of an MPI AIJ matrix, the solution is gathered on every rank. With a distributed layout
/// (the model shared among the ranks), a rank owns the rows of its own equations, which its
/// matrix holds complete; otherwise PETSc's default split of whole node blocks.
#include <mpi.h>
#include <petscksp.h>
#include <petscpc.h>
#include <petscmathypre.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <map>
#include <memory>
#include <smumps_c.h>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/parallel/mpi_runtime.hpp"
#include "engine/solver/linear_solver.hpp"
#include "engine/solver/mumps_entries.hpp"

namespace lunaster::engine {
namespace {

using Settings = IterativeSettings;

/// Whether the user named option `name` (PETSC_OPTIONS, the command line): looked up the first
/// time, before this code sets it in PETSc's options database, which the whole run shares.
bool named_by_user(const char* name) {
  static std::map<std::string, bool> user_named;
  auto it = user_named.find(name);
  if (it == user_named.end()) {
    PetscBool set = PETSC_FALSE;
    PetscOptionsHasName(nullptr, nullptr, name, &set);
    it = user_named.emplace(name, set == PETSC_TRUE).first;
  }
  return it->second;
}

/// A solve that did not converge, or a preconditioner that cannot work on this system.
SolveError iterative_failure(const std::string& message, std::vector<std::string> hints) {
  SolveError err(message, std::move(hints));
  Failure f;
  f.what = Failure::What::IterativeSolve;
  err.set_failure(f);
  return err;
}

/// A PETSc call that failed: PETSc's own message, our context.
void check(PetscErrorCode code, const char* what) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw SolveError(std::string("PETSc: ") + what + " failed: " + (text ? text : "error " + std::to_string(code)));
}

void initialise_petsc() {
  PetscBool done = PETSC_FALSE;
  PetscInitialized(&done);
  if (done) return;
  parallel::ensure_initialised();  // MPI is ours: PETSc then leaves it alone at its end
  // No signal handlers of PETSc's (the run's budget watchdog has its own), no report of
  // options left unused, and errors returned to us rather than printed with a trace.
  PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr);
  PetscOptionsSetValue(nullptr, "-options_left", "0");
  if (PetscInitializeNoArguments() != 0) throw SolveError("PETSc: initialisation failed");
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  // Finalised before MPI (atexit runs in reverse order): PETSC_OPTIONS=-log_view reports then.
  std::atexit([] { PetscFinalize(); });
}

/// LDLT_SP: a single-precision MUMPS factorisation of the whole matrix, applied as the
/// preconditioner (code_aster's choice for contact and other hard systems). The matrix and
/// the residuals are gathered on the host, rank 0, which is where MUMPS takes them.
class SinglePrecisionFactor {
 public:
  ~SinglePrecisionFactor() { release(); }

  /// `distributed`: each rank's `a` holds its own columns (SystemLayout::owner), passed
  /// from every rank; otherwise the host's whole matrix. `workspace`: ICNTL(14), the percent
  /// of working space beyond the analysis's estimate (doubled, up to three times, when short);
  /// `low_rank`: block low-rank factors (ICNTL(35), CNTL(7), and ICNTL(36) when negative).
  void factorize(const SparseMatrix& a, MatrixKind kind, bool distributed, int workspace, LowRank low_rank) {
    release();
    id_ = SMUMPS_STRUC_C{};
    id_.comm_fortran = parallel::fortran_comm_world();
    id_.par = 1;
    id_.sym = kind == MatrixKind::General ? 0 : 2;
    id_.job = -1;
    smumps_c(&id_);
    initialised_ = true;
    id_.icntl[0] = id_.icntl[1] = id_.icntl[2] = -1;
    id_.icntl[3] = 0;
    id_.icntl[6] = 7;
    id_.icntl[13] = workspace;
    set_low_rank(id_, low_rank);  // as the MUMPS backend sets ACCELERATION = 'LR'
    id_.icntl[17] = distributed ? 3 : 0;  // ICNTL(18): each rank's entries
    if (distributed || parallel::rank() == 0) {
      mumps_entries(a, id_.sym, irn_, jcn_, val_);
      id_.n = static_cast<MUMPS_INT>(a.rows());
      give_mumps_entries(id_, distributed, irn_, jcn_, val_);
    }
    id_.job = 4;
    smumps_c(&id_);
    for (int retry = 0; retry < 3 && id_.infog[0] < 0 && id_.infog[0] != -10; ++retry) {
      id_.icntl[13] = 2 * std::max(20, id_.icntl[13]);
      id_.job = 2;
      smumps_c(&id_);
    }
    if (id_.infog[0] < 0)
      throw SolveError("the single-precision factorisation used as preconditioner failed (MUMPS INFOG(1) = " +
                       std::to_string(id_.infog[0]) + ")");
  }

  /// y = A^-1 x in single precision; x and y are whole vectors on the host.
  void apply(std::vector<float>& rhs) const {
    id_.rhs = rhs.data();
    id_.nrhs = 1;
    id_.lrhs = static_cast<MUMPS_INT>(rhs.size());
    id_.job = 3;
    smumps_c(&id_);
  }

 private:
  void release() {
    if (!initialised_) return;
    id_.job = -2;
    smumps_c(&id_);
    initialised_ = false;
  }
  mutable SMUMPS_STRUC_C id_{};
  bool initialised_ = false;
  std::vector<MUMPS_INT> irn_, jcn_;
  std::vector<float> val_;
};

class PetscSolver final : public LinearSolver {
 public:
  explicit PetscSolver(const Settings& settings) : settings_(settings) { initialise_petsc(); }
  ~PetscSolver() override { release(); }
  PetscSolver(const PetscSolver&) = delete;
  PetscSolver& operator=(const PetscSolver&) = delete;

  void factorize(const SparseMatrix& a, MatrixKind kind) override { set_up(a, kind, nullptr); }
  bool factorize_taking(SparseMatrix& a, MatrixKind kind) override {
    // A kept LDLT_SP preconditioner may have to factorise this matrix during a solve: the
    // caller keeps it.
    if (may_keep_preconditioner()) {
      set_up(a, kind, nullptr);
      return false;
    }
    set_up(a, kind, &a);
    return true;
  }
  bool multiply(const Vector& x, Vector& y) const override;
  Vector solve(const Vector& b) const override;
  std::string name() const override {
    return "PETSc " + krylov_label() + " + " + preconditioner_label() + low_rank_name() +
           (kept_      ? " (kept from an earlier matrix)"
            : renewed_ ? " (factorised again: the kept one did not converge)"
                       : "");
  }
  bool iterative() const override { return true; }
  void set_layout(SystemLayout layout) override { layout_ = std::move(layout); }
  bool takes_distributed() const override { return true; }
  int iterations() const override { return iterations_; }

 private:
  void release() {
    if (ksp_) KSPDestroy(&ksp_);
    if (a_) MatDestroy(&a_);
    if (scatter_) VecScatterDestroy(&scatter_);
    if (gathered_) VecDestroy(&gathered_);
    ksp_ = nullptr, a_ = nullptr, scatter_ = nullptr, gathered_ = nullptr;
  }
  /// factorize(); `taken` (the same matrix as `a`): its storage is released once PETSc has
  /// the matrix, before the preconditioner is built (the largest memory of the set-up).
  void set_up(const SparseMatrix& a, MatrixKind kind, SparseMatrix* taken);
  /// A system of this kind the settings cannot solve (a saddle point without a factorisation as
  /// preconditioner, or under CG; that factorisation on a mesh in parts): the error, thrown.
  void refuse_unsolvable(MatrixKind kind) const;
  /// The Krylov method on a_ (ksp_): its type, the unpreconditioned residual test, the monitor.
  void create_krylov();
  /// The preconditioner the settings name, set on pc for the system a.
  void set_preconditioner(PC pc, const SparseMatrix& a, MatrixKind kind);
  /// BoomerAMG with hypre's settings for 3D problems (options the user named win).
  void set_boomer(PC pc);
  /// The single-precision factorisation of a (kept while REAC_PRECOND allows) as a shell.
  void set_single_precision(PC pc, const SparseMatrix& a, MatrixKind kind);
  /// A whole vector in the system's numbering into a PETSc vector (this rank's rows), and back.
  void to_petsc(const Vector& x, Vec v) const;
  void from_petsc(Vec v, Vector& x) const;
  void number_rows(int n_equations);
  /// The system's equation of this rank's row r (0-based, local), -1 for an identity row.
  int local_equation(PetscInt r) const { return layout_.in_parts() ? eq_of_[r] : eq_of_[first_row_ + r]; }
  void build_matrix(const SparseMatrix& a, MatrixKind kind);
  /// BoomerAMG's matrix: hypre's own (ParCSR), built from `a` directly. PCHYPRE would convert
  /// an AIJ matrix into one and keep both; this way the system is held once on PETSc's side.
  void build_hypre_matrix(const SparseMatrix& a, MatrixKind kind);
  /// Calls row(r, entries) for each of this rank's rows r (0-based, local) with its entries
  /// (column in PETSc's numbering, value), sorted by column unless `sorted` is false; `a`
  /// is symmetric.
  template <class Row>
  void for_each_local_row(const SparseMatrix& a, Row row, bool sorted = true) const;
  void set_symmetry_options(MatrixKind kind);
  void attach_near_null_space();
  /// The method and the preconditioner as the caller names them (IterativeSettings), else the engine's names.
  std::string krylov_label() const {
    return settings_.krylov_label.empty() ? krylov_name(settings_.krylov) : settings_.krylov_label;
  }
  std::string preconditioner_label() const {
    return settings_.preconditioner_label.empty() ? preconditioner_name(settings_.preconditioner)
                                                  : settings_.preconditioner_label;
  }
  /// " in block low rank (threshold 1e-08)" for LDLT_SP's compressed factors, else empty.
  std::string low_rank_name() const {
    if (settings_.preconditioner != Settings::Preconditioner::LdltSp || !settings_.low_rank.on) return {};
    char text[64];
    std::snprintf(text, sizeof text, " in block low rank (threshold %g%s)", std::abs(settings_.low_rank.threshold),
                  settings_.low_rank.threshold < 0.0 ? ", UCFS" : "");
    return text;
  }
  int iteration_limit() const { return settings_.max_iterations > 0 ? settings_.max_iterations : 10000; }
  bool may_keep_preconditioner() const {
    return settings_.preconditioner == Settings::Preconditioner::LdltSp && settings_.reac_precond > 0;
  }
  /// KSPSolve of b into x; false when it did not converge (what it reached in `detail`).
  bool krylov_solve(Vec b, Vec x, std::string& detail) const;
  bool multigrid() const {
    return settings_.preconditioner == Settings::Preconditioner::Gamg ||
           settings_.preconditioner == Settings::Preconditioner::Ml ||
           settings_.preconditioner == Settings::Preconditioner::Boomer;
  }
  static PetscErrorCode monitor(KSP, PetscInt it, PetscReal rnorm, void* self);
  static PetscErrorCode apply_single_precision(PC pc, Vec x, Vec y);

  Settings settings_;
  SystemLayout layout_;
  /// PETSc's numbering: row_of_[eq] is equation eq's row, eq_of_[row] its equation or -1 for
  /// a padding row (an identity row completing a node block). With multigrid and a layout,
  /// the rows are node blocks of bs_ components (Dirichlet-fixed components padded), then
  /// the equations outside any block; otherwise the system's own numbering.
  std::vector<PetscInt> row_of_;
  std::vector<int> eq_of_;
  /// Per group of bs_ rows (a node block, or bs_ equations outside the blocks): its node
  /// block, -1 if none (the rigid-body modes' coordinates).
  std::vector<int> block_of_group_;
  /// The matrix's compressed rows in PETSc's numbering (this rank's rows); with one process
  /// PETSc's matrix is built on them without a copy.
  std::vector<PetscInt> ia_, ja_;
  std::vector<PetscScalar> va_;
  PetscInt bs_ = 1;
  Mat a_ = nullptr;
  KSP ksp_ = nullptr;
  VecScatter scatter_ = nullptr;  ///< distributed vector -> whole vector on every rank
  Vec gathered_ = nullptr;
  PetscInt first_row_ = 0, local_rows_ = 0, n_ = 0;
  mutable double rhs_norm_ = 1.0;  ///< |b| of the solve in progress (the history's scale)
  mutable int iterations_ = 0;
  std::unique_ptr<SinglePrecisionFactor> single_;
  /// REAC_PRECOND: the matrix of the last set-up (alive until the next: the caller keeps it)
  /// and its kind, which a solve on a kept factorisation may have to factorise; the size of the
  /// matrix `single_` factorised; whether the preconditioner is an earlier matrix's, and
  /// whether the next set-up factorises (the last solve took more than REAC_PRECOND
  /// iterations).
  const SparseMatrix* source_ = nullptr;
  MatrixKind kind_ = MatrixKind::SymmetricPositiveDefinite;
  Eigen::Index single_n_ = -1;
  mutable bool kept_ = false;
  mutable bool renew_ = true;
  mutable bool renewed_ = false;  ///< the last solve factorised its matrix after a kept one failed
};

void PetscSolver::number_rows(int n_equations) {
  if (layout_.in_parts()) {
    // A mesh in parts: this rank's rows are its owned nodes' unknowns, node blocks of dim (the
    // Dirichlet-fixed ones identity rows), numbered across the ranks by the caller; eq_of_ is
    // then indexed by the local row.
    LUNASTER_ASSERT(static_cast<int>(layout_.row.size()) == n_equations && layout_.dim > 0 &&
                        static_cast<int>(layout_.row_coords.size()) == layout_.n_owned_rows,
                    "PETSc: a system in parts without its rows");
    bs_ = layout_.dim;
    n_ = static_cast<PetscInt>(layout_.n_rows);
    first_row_ = static_cast<PetscInt>(layout_.first_row);
    local_rows_ = layout_.n_owned_rows;
    row_of_.assign(layout_.row.begin(), layout_.row.end());
    eq_of_.assign(local_rows_, -1);
    for (int eq = 0; eq < n_equations; ++eq)
      if (row_of_[eq] >= first_row_ && row_of_[eq] < first_row_ + local_rows_) eq_of_[row_of_[eq] - first_row_] = eq;
    block_of_group_.clear();
    return;
  }
  const bool blocks = multigrid() && layout_.dim > 1 && static_cast<int>(layout_.block.size()) == n_equations;
  const bool owned = layout_.distributed() && static_cast<int>(layout_.owner.size()) == n_equations;
  bs_ = blocks ? layout_.dim : 1;
  // Groups of bs_ rows in the system's order: the node blocks, then the equations outside
  // them packed bs_ to a group (the last one padded); without blocks, one equation each.
  std::vector<PetscInt> group_row(n_equations);  // row in the groups' order
  PetscInt groups = 0;
  if (!blocks) {
    for (int eq = 0; eq < n_equations; ++eq) group_row[eq] = eq;
    groups = n_equations;
  } else {
    const PetscInt in_blocks = static_cast<PetscInt>(layout_.n_blocks()) * bs_;
    std::vector<int> outside;
    for (int eq = 0; eq < n_equations; ++eq) {
      if (layout_.block[eq] >= 0) group_row[eq] = layout_.block[eq] * bs_ + layout_.component[eq];
      else outside.push_back(eq);
    }
    // With owners, each rank's outside equations fill groups of their own.
    if (owned)
      std::stable_sort(outside.begin(), outside.end(), [this](int x, int y) { return layout_.owner[x] < layout_.owner[y]; });
    PetscInt next = in_blocks;
    int group_owner = -1;
    for (int eq : outside) {
      if (owned && layout_.owner[eq] != group_owner) {
        next = (next + bs_ - 1) / bs_ * bs_;  // a new group (the last one padded)
        group_owner = layout_.owner[eq];
      }
      group_row[eq] = next++;
    }
    groups = (next + bs_ - 1) / bs_;
  }
  n_ = groups * bs_;
  // Owner of each group: the rank of its equations (a distributed layout), otherwise
  // PETSc's split of the groups in order.
  std::vector<int> owner_of(groups, -1);
  const int ranks = parallel::size(), rank = parallel::rank();
  if (owned) {
    for (int eq = 0; eq < n_equations; ++eq) {
      int& o = owner_of[group_row[eq] / bs_];
      LUNASTER_ASSERT(o < 0 || o == layout_.owner[eq], "PETSc: a node block shared by two ranks");
      o = layout_.owner[eq];
    }
    for (int& o : owner_of)
      if (o < 0) o = ranks - 1;  // padding only
  } else {
    PetscInt local_groups = PETSC_DECIDE, all = groups;
    check(PetscSplitOwnership(PETSC_COMM_WORLD, &local_groups, &all), "PetscSplitOwnership");
    std::vector<int> counts = parallel::gather_all(std::vector<int>{static_cast<int>(local_groups)});
    for (PetscInt g = 0, r = 0, left = counts[0]; g < groups; ++g) {
      while (left == 0) left = counts[++r];
      owner_of[g] = static_cast<int>(r), --left;
    }
  }
  // The groups by owner (stable): each rank's rows are one range.
  std::vector<PetscInt> first_of(ranks + 1, 0), position(groups);
  for (int o : owner_of) ++first_of[o + 1];
  for (int r = 0; r < ranks; ++r) first_of[r + 1] += first_of[r];
  {
    std::vector<PetscInt> fill(first_of.begin(), first_of.end() - 1);
    for (PetscInt g = 0; g < groups; ++g) position[g] = fill[owner_of[g]]++;
  }
  first_row_ = first_of[rank] * bs_;
  local_rows_ = (first_of[rank + 1] - first_of[rank]) * bs_;
  block_of_group_.assign(groups, -1);
  if (blocks)
    for (PetscInt g = 0; g < std::min<PetscInt>(groups, layout_.n_blocks()); ++g) block_of_group_[position[g]] = static_cast<int>(g);
  row_of_.resize(n_equations);
  for (int eq = 0; eq < n_equations; ++eq) row_of_[eq] = position[group_row[eq] / bs_] * bs_ + group_row[eq] % bs_;
  eq_of_.assign(n_, -1);
  for (int eq = 0; eq < n_equations; ++eq) eq_of_[row_of_[eq]] = eq;
}

template <class Row>
void PetscSolver::for_each_local_row(const SparseMatrix& a, Row row, bool sorted) const {
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const double* value = a.valuePtr();
  std::vector<std::pair<PetscInt, double>> entries;
  for (PetscInt r = 0; r < local_rows_; ++r) {
    const int eq = local_equation(r);
    entries.clear();
    if (eq < 0) {
      entries.emplace_back(first_row_ + r, 1.0);  // padding: an identity row
    } else {
      for (int k = outer[eq]; k < outer[eq + 1]; ++k) entries.emplace_back(row_of_[inner[k]], value[k]);
      // (In parts the local equations' rows are not in the local order.)
      if (sorted && (bs_ > 1 || layout_.in_parts())) std::sort(entries.begin(), entries.end());
    }
    row(r, entries);
  }
}

void PetscSolver::set_symmetry_options(MatrixKind kind) {
  if (kind != MatrixKind::General) check(MatSetOption(a_, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  if (kind == MatrixKind::SymmetricPositiveDefinite) check(MatSetOption(a_, MAT_SPD, PETSC_TRUE), "MatSetOption");
}

void PetscSolver::build_matrix(const SparseMatrix& a, MatrixKind kind) {
  // Rows of this rank as compressed rows. The system matrices are symmetric with both
  // triangles stored, so A's compressed columns are its compressed rows; a general
  // matrix is transposed first.
  SparseMatrix transposed;
  const SparseMatrix* rows = &a;
  LUNASTER_ASSERT(kind != MatrixKind::General || !layout_.distributed(), "PETSc: a distributed system must be symmetric");
  if (kind == MatrixKind::General) {
    transposed = a.transpose();
    transposed.makeCompressed();
    rows = &transposed;
  }
  number_rows(static_cast<int>(a.rows()));
  const int size = parallel::size();
  const int* outer = rows->outerIndexPtr();
  // The rows in PETSc's numbering, sized exactly (no growth: at 3e6 unknowns a doubling
  // vector would hold a third more than the matrix).
  std::vector<PetscInt>& ia = ia_;
  std::vector<PetscInt>& ja = ja_;
  std::vector<PetscScalar>& va = va_;
  ia.assign(static_cast<size_t>(local_rows_) + 1, 0);
  for (PetscInt r = 0; r < local_rows_; ++r) {
    const int eq = local_equation(r);
    ia[r + 1] = ia[r] + (eq < 0 ? 1 : outer[eq + 1] - outer[eq]);
  }
  ja.clear();
  va.clear();
  ja.shrink_to_fit();
  va.shrink_to_fit();
  ja.reserve(ia.back());
  va.reserve(ia.back());
  for_each_local_row(*rows, [&](PetscInt, const std::vector<std::pair<PetscInt, double>>& entries) {
    for (const auto& [col, v] : entries) ja.push_back(col), va.push_back(v);
  });
  if (size == 1) {
    // One process: PETSc works on these arrays (kept alive by the solver), no copy.
    check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, n_, n_, ia.data(), ja.data(), va.data(), &a_),
          "MatCreateSeqAIJWithArrays");
    check(MatSetBlockSize(a_, bs_), "MatSetBlockSize");
  } else {
    check(MatCreate(PETSC_COMM_WORLD, &a_), "MatCreate");
    check(MatSetSizes(a_, local_rows_, local_rows_, n_, n_), "MatSetSizes");
    check(MatSetType(a_, MATMPIAIJ), "MatSetType");
    check(MatSetBlockSize(a_, bs_), "MatSetBlockSize");
    check(MatMPIAIJSetPreallocationCSR(a_, ia.data(), ja.data(), va.data()), "MatMPIAIJSetPreallocationCSR");
    // PETSc holds its own copy now.
    std::vector<PetscInt>().swap(ja_);
    std::vector<PetscScalar>().swap(va_);
  }
  set_symmetry_options(kind);
}

void PetscSolver::build_hypre_matrix(const SparseMatrix& a, MatrixKind kind) {
  LUNASTER_ASSERT(kind != MatrixKind::General, "PETSc: BoomerAMG's matrix must be symmetric");
  number_rows(static_cast<int>(a.rows()));
  // hypre's ParCSR holds this rank's rows as two CSR blocks: "diag", the columns of this
  // rank's rows (local numbering, the diagonal entry first in each row, as hypre's
  // smoothers read it) and "offd", the other columns (numbered in col_map_offd, the sorted
  // global columns). First the sizes, then the values written in place: the matrix is never
  // held twice, by us or by hypre (whose IJ interface would buffer it).
  const PetscInt first = first_row_, last = first_row_ + local_rows_;
  const auto local = [&](PetscInt col) { return col >= first && col < last; };
  HYPRE_Int nnz_diag = 0, nnz_offd = 0;
  std::vector<HYPRE_Int> offd_of(static_cast<size_t>(n_), -1);  // global column -> offd column
  for_each_local_row(a, [&](PetscInt r, const std::vector<std::pair<PetscInt, double>>& entries) {
    bool diagonal = false;
    for (const auto& entry : entries) {
      if (local(entry.first)) ++nnz_diag, diagonal = diagonal || entry.first == first + r;
      else ++nnz_offd, offd_of[entry.first] = 0;
    }
    LUNASTER_ASSERT(diagonal, "hypre: a row of the system has no diagonal entry");
  }, false);
  HYPRE_Int n_offd = 0;
  for (PetscInt col = 0; col < n_; ++col)
    if (offd_of[col] == 0) offd_of[col] = n_offd++;
  HYPRE_BigInt starts[2] = {static_cast<HYPRE_BigInt>(first), static_cast<HYPRE_BigInt>(last)};
  hypre_ParCSRMatrix* h = hypre_ParCSRMatrixCreate(PETSC_COMM_WORLD, n_, n_, starts, starts, n_offd, nnz_diag, nnz_offd);
  // Ours until PETSc takes it (an exception below frees it).
  std::unique_ptr<hypre_ParCSRMatrix, HYPRE_Int (*)(hypre_ParCSRMatrix*)> owned(h, hypre_ParCSRMatrixDestroy);
  if (!h || hypre_ParCSRMatrixInitialize(h) != 0) {
    throw SolveError("hypre: the matrix for BoomerAMG could not be allocated (" + std::to_string(nnz_diag + nnz_offd) +
                     " entries on this rank)");
  }
  hypre_CSRMatrix* diag = hypre_ParCSRMatrixDiag(h);
  hypre_CSRMatrix* offd = hypre_ParCSRMatrixOffd(h);
  HYPRE_Int *di = hypre_CSRMatrixI(diag), *dj = hypre_CSRMatrixJ(diag);
  HYPRE_Int *oi = hypre_CSRMatrixI(offd), *oj = hypre_CSRMatrixJ(offd);
  HYPRE_Complex *dv = hypre_CSRMatrixData(diag), *ov = hypre_CSRMatrixData(offd);
  HYPRE_BigInt* col_map = hypre_ParCSRMatrixColMapOffd(h);
  for (PetscInt col = 0; col < n_; ++col)
    if (offd_of[col] >= 0) col_map[offd_of[col]] = static_cast<HYPRE_BigInt>(col);
  di[0] = oi[0] = 0;
  for_each_local_row(a, [&](PetscInt r, const std::vector<std::pair<PetscInt, double>>& entries) {
    HYPRE_Int d = di[r] + 1, o = oi[r];  // di[r]: the diagonal's place (every row has one)
    for (const auto& [col, v] : entries) {
      if (col == first + r) {
        dj[di[r]] = static_cast<HYPRE_Int>(r), dv[di[r]] = v;
      } else if (local(col)) {
        dj[d] = static_cast<HYPRE_Int>(col - first), dv[d++] = v;
      } else {
        oj[o] = offd_of[col], ov[o++] = v;
      }
    }
    di[r + 1] = d, oi[r + 1] = o;
  });
  std::vector<HYPRE_Int>().swap(offd_of);
  check(MatCreateFromParCSR(h, MATHYPRE, PETSC_OWN_POINTER, &a_), "MatCreateFromParCSR");
  owned.release();
  check(MatSetBlockSize(a_, bs_), "MatSetBlockSize");  // BoomerAMG's number of functions
  set_symmetry_options(kind);
}

void PetscSolver::attach_near_null_space() {
  if (bs_ < 2) return;
  // The rigid-body modes from the blocks' coordinates (PETSc orthonormalises them);
  // padding blocks past the nodes sit at the origin.
  Vec coords = nullptr;
  check(VecCreate(PETSC_COMM_WORLD, &coords), "VecCreate");
  check(VecSetSizes(coords, local_rows_, n_), "VecSetSizes");
  check(VecSetBlockSize(coords, bs_), "VecSetBlockSize");
  check(VecSetFromOptions(coords), "VecSetFromOptions");
  PetscScalar* x = nullptr;
  check(VecGetArray(coords, &x), "VecGetArray");
  for (PetscInt r = 0; r < local_rows_; ++r) {
    if (layout_.in_parts()) {  // owned nodes in order, bs_ rows each
      x[r] = layout_.row_coords[r];
      continue;
    }
    const PetscInt row = first_row_ + r;
    const int block = block_of_group_[row / bs_];
    x[r] = block >= 0 ? layout_.coords[static_cast<size_t>(block) * bs_ + row % bs_] : 0.0;
  }
  check(VecRestoreArray(coords, &x), "VecRestoreArray");
  MatNullSpace space = nullptr;
  check(MatNullSpaceCreateRigidBody(coords, &space), "MatNullSpaceCreateRigidBody");
  check(MatSetNearNullSpace(a_, space), "MatSetNearNullSpace");
  MatNullSpaceDestroy(&space);
  VecDestroy(&coords);
}

PetscErrorCode PetscSolver::monitor(KSP, PetscInt it, PetscReal rnorm, void* self) {
  auto* s = static_cast<PetscSolver*>(self);
  s->iterations_ = static_cast<int>(it);
  if (s->settings_.history) {
    char line[96];
    std::snprintf(line, sizeof line, "    Krylov %5d   |r|/|b| = %.6e", static_cast<int>(it), rnorm / s->rhs_norm_);
    s->settings_.history(line);
  }
  return 0;
}

PetscErrorCode PetscSolver::apply_single_precision(PC pc, Vec x, Vec y) {
  void* context = nullptr;
  PetscCall(PCShellGetContext(pc, &context));
  auto* s = static_cast<PetscSolver*>(context);
  // Gather x on every rank (the host uses it), solve on the host, scatter back.
  PetscCall(VecScatterBegin(s->scatter_, x, s->gathered_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(s->scatter_, x, s->gathered_, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar* whole = nullptr;
  PetscCall(VecGetArrayRead(s->gathered_, &whole));
  // The factor is in the system's numbering (equations), the vectors in PETSc's (rows).
  const size_t n_eq = s->row_of_.size();
  std::vector<float> rhs(parallel::rank() == 0 ? n_eq : 0);
  for (size_t eq = 0; eq < rhs.size(); ++eq) rhs[eq] = static_cast<float>(whole[s->row_of_[eq]]);
  PetscCall(VecRestoreArrayRead(s->gathered_, &whole));
  s->single_->apply(rhs);
  std::vector<double> out(static_cast<size_t>(s->n_), 0.0);
  for (size_t eq = 0; eq < rhs.size(); ++eq) out[s->row_of_[eq]] = rhs[eq];
  parallel::broadcast(out.data(), s->n_);
  PetscScalar* mine = nullptr;
  PetscCall(VecGetArray(y, &mine));
  for (PetscInt r = 0; r < s->local_rows_; ++r) mine[r] = out[s->first_row_ + r];
  PetscCall(VecRestoreArray(y, &mine));
  return 0;
}

void PetscSolver::refuse_unsolvable(MatrixKind kind) const {
  // Contact multipliers make a saddle point: zero diagonal, indefinite. Only a factorisation
  // preconditions it; multigrid and point relaxations break down, and CG needs SPD.
  const bool factorised_pc = settings_.preconditioner == Settings::Preconditioner::LdltSp;
  if (kind != MatrixKind::SymmetricPositiveDefinite &&
      (!factorised_pc || settings_.krylov == Settings::Krylov::CG))
    throw iterative_failure(std::string("the iterative solver ") + name() +
                                " cannot solve this system: it has contact multipliers (a saddle point, not "
                                "positive definite)",
                            {"a saddle-point system (contact multipliers) needs a single-precision factorisation as "
                             "preconditioner with FGMRES or GMRES"});
  // The single-precision factorisation works on the whole system on the host, every vector gathered there.
  if (layout_.in_parts() && factorised_pc) {
    DeckError error("PETSc: a single-precision factorisation as preconditioner is not available on a mesh in parts: it "
                    "gathers the whole system on one rank",
                    {"an algebraic multigrid (GAMG, ML, BoomerAMG), Jacobi or SOR preconditions the parts"});
    error.failure().what = Failure::What::NotInParts;  // commands/ names PRE_COND
    throw error;
  }
}

void PetscSolver::create_krylov() {
  check(KSPCreate(PETSC_COMM_WORLD, &ksp_), "KSPCreate");
  check(KSPSetOperators(ksp_, a_, a_), "KSPSetOperators");
  switch (settings_.krylov) {
    case Settings::Krylov::CG: check(KSPSetType(ksp_, KSPCG), "KSPSetType"); break;
    case Settings::Krylov::GMRES:
      check(KSPSetType(ksp_, KSPGMRES), "KSPSetType");
      check(KSPSetPCSide(ksp_, PC_RIGHT), "KSPSetPCSide");  // the residual tested is the true one
      check(KSPGMRESSetRestart(ksp_, 30), "KSPGMRESSetRestart");
      break;
    case Settings::Krylov::FGMRES: check(KSPSetType(ksp_, KSPFGMRES), "KSPSetType"); break;
  }
  // RESI_RELA is code_aster's relative residual |b - A x| / |b|, unpreconditioned.
  check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  check(KSPSetTolerances(ksp_, settings_.relative_residual, 0.0, 1e100, iteration_limit()), "KSPSetTolerances");
  check(KSPSetInitialGuessNonzero(ksp_, PETSC_FALSE), "KSPSetInitialGuessNonzero");
  check(KSPMonitorSet(ksp_, &PetscSolver::monitor, this, nullptr), "KSPMonitorSet");
}

void PetscSolver::set_boomer(PC pc) {
  check(PCSetType(pc, PCHYPRE), "PCSetType");
  check(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
  // hypre's settings for 3D problems (its manual: HMIS coarsening, extended+i interpolation
  // truncated to 4 entries, one level of aggressive coarsening, strength 0.5). With hypre's
  // 2D defaults the 2e5-unknown HEXA8 block took 38 s to set up and solve; with these, 5.3 s.
  // Quadratic cells take strength 0.7: the refined mortar case (HEXA8 and HEXA20) needed 40
  // CG iterations instead of 91 and half the time, a HEXA20 block 0.85 of the time, while
  // the HEXA8 block is 1.2 times slower at 0.7.
  // Smoothing: hypre's Chebyshev polynomial (degree 2, on an estimate of the largest
  // eigenvalue of D^-1 A) on every level but the coarsest, each way. It is symmetric, as CG
  // needs, and the same sweep on any number of ranks (hypre's hybrid Gauss-Seidel, Jacobi
  // between ranks, made the preconditioner indefinite on the refined mortar case with two
  // ranks). It takes the iterations the l1 Gauss-Seidel sweeps took (40-42 on the refined
  // mortar case, 23-30 on the HEXA8 and HEXA20 blocks) at about 0.7 of their time: one
  // process, the refined mortar case 14.3-14.9 s against 19.4-20.0 s, the 3.3e5-unknown
  // HEXA8 block 5.3-5.8 s against 7.4-8.5 s (tests/bench/README.md).
  // These go into PETSc's options database, which the run shares: an option the user named
  // in PETSC_OPTIONS (looked up before this code set any) wins, ours follow each system.
  const bool relaxation_named = named_by_user("-pc_hypre_boomeramg_relax_type_all");
  for (const auto& [name, value] :
       {std::pair<const char*, const char*>{"-pc_hypre_boomeramg_coarsen_type", "HMIS"},
        {"-pc_hypre_boomeramg_interp_type", "ext+i"},
        {"-pc_hypre_boomeramg_P_max", "4"},
        {"-pc_hypre_boomeramg_agg_nl", "1"},
        {"-pc_hypre_boomeramg_strong_threshold", layout_.quadratic ? "0.7" : "0.5"},
        {"-pc_hypre_boomeramg_relax_type_down", relaxation_named ? nullptr : "Chebyshev"},
        {"-pc_hypre_boomeramg_relax_type_up", relaxation_named ? nullptr : "Chebyshev"}}) {
    if (value && !named_by_user(name)) PetscOptionsSetValue(nullptr, name, value);
  }
  if (settings_.history) {  // what this system's V-cycle uses (INFO = 2)
    auto option = [](const char* name) {
      char value[64] = "";
      PetscBool found = PETSC_FALSE;
      PetscOptionsGetString(nullptr, nullptr, name, value, sizeof value, &found);
      return std::string(found ? value : "hypre's default");
    };
    const std::string smoothing =
        relaxation_named ? option("-pc_hypre_boomeramg_relax_type_all") + " both ways"
                         : option("-pc_hypre_boomeramg_relax_type_down") + " down, " +
                               option("-pc_hypre_boomeramg_relax_type_up") + " up";
    settings_.history("    BoomerAMG: strength threshold " + option("-pc_hypre_boomeramg_strong_threshold") +
                      ", smoothing " + smoothing);
  }
}

void PetscSolver::set_single_precision(PC pc, const SparseMatrix& a, MatrixKind kind) {
  // REAC_PRECOND: the last factorisation serves again while the solves it preconditions
  // stay within that many iterations (every rank takes the same branch: the iterations
  // are the KSP's, collective).
  kept_ = settings_.reac_precond > 0 && single_ && !renew_ && single_n_ == a.rows();
  renewed_ = false;
  if (!kept_) {
    single_ = std::make_unique<SinglePrecisionFactor>();
    single_->factorize(a, kind, layout_.distributed(), settings_.workspace_relaxation, settings_.low_rank);
    single_n_ = a.rows();
  }
  source_ = &a, kind_ = kind;
  // A kept factorisation has REAC_PRECOND iterations to converge: beyond, this matrix would
  // be factorised for the next solve anyway, and it is factorised for this one at once
  // (code_aster waits for NMAX_ITER: 100 iterations lost on each contact pass that
  // changes the statuses, where a single-precision solve on fresh factors takes 2 to 5).
  if (kept_)
    check(KSPSetTolerances(ksp_, settings_.relative_residual, 0.0, 1e100,
                           std::min(iteration_limit(), settings_.reac_precond)),
          "KSPSetTolerances");
  check(PCSetType(pc, PCSHELL), "PCSetType");
  check(PCShellSetContext(pc, this), "PCShellSetContext");
  check(PCShellSetApply(pc, &PetscSolver::apply_single_precision), "PCShellSetApply");
  check(PCShellSetName(pc, preconditioner_label().c_str()), "PCShellSetName");
}

void PetscSolver::set_preconditioner(PC pc, const SparseMatrix& a, MatrixKind kind) {
  switch (settings_.preconditioner) {
    case Settings::Preconditioner::Gamg:
      check(PCSetType(pc, PCGAMG), "PCSetType");
      // Smoothed aggregation on an elasticity matrix: a threshold that drops weak
      // couplings keeps the coarse grids sparse (PETSc's manual, elasticity section).
      check(PCGAMGSetThreshold(pc, std::vector<PetscReal>{0.01}.data(), 1), "PCGAMGSetThreshold");
      break;
    case Settings::Preconditioner::Ml:
      check(PCSetType(pc, PCML), "PCSetType");
      // On several ranks each level is smoothed by Chebyshev on the diagonal (GAMG's default),
      // not by PETSc's default for ML, SOR within each rank and nothing between ranks: that
      // sweep depends on the partition, and on three ranks it made the V-cycle of
      // petsc_solvers.lua's mortar system indefinite (CG stopped after 4 iterations,
      // DIVERGED_INDEFINITE_PC). Chebyshev converges there on any number of ranks (32-48
      // iterations against SOR's 22-33 where SOR converged); on the 9e4-unknown HEXA8 block it
      // costs 1.24 times SOR's time on two ranks (tests/bench/README.md). One process keeps SOR,
      // a true symmetric Gauss-Seidel sweep there.
      if (parallel::size() > 1)
        for (const auto& [name, value] : {std::pair<const char*, const char*>{"-mg_levels_ksp_type", "chebyshev"},
                                          {"-mg_levels_pc_type", "jacobi"}})
          if (!named_by_user(name)) PetscOptionsSetValue(nullptr, name, value);
      break;
    case Settings::Preconditioner::Boomer: set_boomer(pc); break;
    case Settings::Preconditioner::LdltSp: set_single_precision(pc, a, kind); break;
    case Settings::Preconditioner::Jacobi: check(PCSetType(pc, PCJACOBI), "PCSetType"); break;
    case Settings::Preconditioner::Sor: check(PCSetType(pc, PCSOR), "PCSetType"); break;
    case Settings::Preconditioner::None: check(PCSetType(pc, PCNONE), "PCSetType"); break;
  }
}

void PetscSolver::set_up(const SparseMatrix& a, MatrixKind kind, SparseMatrix* taken) {
  LUNASTER_ASSERT(a.rows() == a.cols(), "PETSc: matrix is not square");
  LUNASTER_ASSERT(!taken || taken == &a, "PETSc: the matrix taken is the one factorised");
  refuse_unsolvable(kind);
  release();
  if (settings_.preconditioner == Settings::Preconditioner::Boomer) build_hypre_matrix(a, kind);
  else build_matrix(a, kind);
  attach_near_null_space();
  if (!layout_.in_parts()) {  // in parts each rank reads its own rows, nothing is gathered
    Vec local = nullptr;
    check(MatCreateVecs(a_, &local, nullptr), "MatCreateVecs");
    check(VecScatterCreateToAll(local, &scatter_, &gathered_), "VecScatterCreateToAll");
    VecDestroy(&local);
  }
  create_krylov();
  PC pc = nullptr;
  check(KSPGetPC(ksp_, &pc), "KSPGetPC");
  set_preconditioner(pc, a, kind);
  if (taken) {  // PETSc and the preconditioner hold what they need of it now
    SparseMatrix empty(a.rows(), a.cols());
    taken->swap(empty);
  }
  // Expert tuning, as PETSc users do it: options in the PETSC_OPTIONS environment variable
  // (-ksp_view, -pc_gamg_threshold 0.02, ...) apply on top of the deck's choice.
  check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
  check(KSPSetUp(ksp_), "building the preconditioner");
}

void PetscSolver::to_petsc(const Vector& x, Vec v) const {
  PetscScalar* mine = nullptr;
  check(VecGetArray(v, &mine), "VecGetArray");
  for (PetscInt r = 0; r < local_rows_; ++r) {
    const int eq = local_equation(r);
    mine[r] = eq >= 0 ? x[eq] : 0.0;
  }
  check(VecRestoreArray(v, &mine), "VecRestoreArray");
}

void PetscSolver::from_petsc(Vec v, Vector& x) const {
  if (layout_.in_parts()) {  // the owned equations' values; the others are the caller's
    const PetscScalar* mine = nullptr;
    check(VecGetArrayRead(v, &mine), "VecGetArrayRead");
    for (PetscInt r = 0; r < local_rows_; ++r)
      if (const int eq = local_equation(r); eq >= 0) x[eq] = mine[r];
    VecRestoreArrayRead(v, &mine);
    return;
  }
  check(VecScatterBegin(scatter_, v, gathered_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(scatter_, v, gathered_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  const PetscScalar* whole = nullptr;
  check(VecGetArrayRead(gathered_, &whole), "VecGetArrayRead");
  for (Eigen::Index eq = 0; eq < x.size(); ++eq) x[eq] = whole[row_of_[eq]];
  VecRestoreArrayRead(gathered_, &whole);
}

bool PetscSolver::multiply(const Vector& x, Vector& y) const {
  if (!a_) return false;
  LUNASTER_ASSERT(x.size() == static_cast<Eigen::Index>(row_of_.size()), "PETSc: product with a vector of another size");
  Vec xv = nullptr, yv = nullptr;
  check(MatCreateVecs(a_, &xv, &yv), "MatCreateVecs");
  to_petsc(x, xv);
  check(MatMult(a_, xv, yv), "MatMult");
  y = Vector::Zero(x.size());
  from_petsc(yv, y);
  VecDestroy(&xv);
  VecDestroy(&yv);
  return true;
}

bool PetscSolver::krylov_solve(Vec b, Vec x, std::string& detail) const {
  check(KSPSolve(ksp_, b, x), "KSPSolve");
  KSPConvergedReason reason;
  PetscInt its = 0;
  PetscReal rnorm = 0.0;
  KSPGetConvergedReason(ksp_, &reason);
  KSPGetIterationNumber(ksp_, &its);
  KSPGetResidualNorm(ksp_, &rnorm);
  iterations_ = static_cast<int>(its);
  if (reason >= 0 && kept_) {
    // FGMRES's residual is its own recurrence; preconditioned by an earlier matrix's
    // single-precision factors over many iterations it drifts from b - A x (SSNP121 A
    // refined 16 times: "converged" at 1e-6, the true residual 3.6e-6). A solve on kept
    // factors counts only when its true residual is within the tolerance.
    Vec r = nullptr;
    check(VecDuplicate(b, &r), "VecDuplicate");
    check(MatMult(a_, x, r), "MatMult");
    check(VecAYPX(r, -1.0, b), "VecAYPX");
    check(VecNorm(r, NORM_2, &rnorm), "VecNorm");
    VecDestroy(&r);
    if (rnorm <= settings_.relative_residual * rhs_norm_) return true;
    char text[160];
    std::snprintf(text, sizeof text, "true relative residual %.3e after %d iterations, %.1e asked", rnorm / rhs_norm_,
                  static_cast<int>(its), settings_.relative_residual);
    detail = text;
    return false;
  }
  if (reason >= 0) return true;
  char text[160];
  std::snprintf(text, sizeof text, "relative residual %.3e after %d iterations, %.1e asked (%s)", rnorm / rhs_norm_,
                static_cast<int>(its), settings_.relative_residual, KSPConvergedReasons[reason]);
  detail = text;
  return false;
}

Vector PetscSolver::solve(const Vector& b) const {
  if (!ksp_) throw InternalError("PETSc: solve called before factorize");
  Vec bv = nullptr, xv = nullptr;
  check(MatCreateVecs(a_, &xv, &bv), "MatCreateVecs");
  to_petsc(b, bv);
  // In parts b holds this rank's equations: its norm is the PETSc vector's, over the ranks.
  PetscReal b_norm = b.norm();
  if (layout_.in_parts()) check(VecNorm(bv, NORM_2, &b_norm), "VecNorm");
  rhs_norm_ = std::max(static_cast<double>(b_norm), 1e-300);
  iterations_ = 0;
  Vector out = Vector::Zero(b.size());
  if (b_norm > 0.0) {
    std::string detail;
    bool converged = krylov_solve(bv, xv, detail);
    int spent = iterations_;
    if (!converged && kept_) {
      // An earlier matrix's factorisation no longer preconditions this one (REAC_PRECOND, as
      // code_aster does): factorise this matrix and solve again.
      if (settings_.history)
        settings_.history("    " + preconditioner_label() + ": the kept factorisation did not converge (" + detail +
                          "); factorised again");
      single_->factorize(*source_, kind_, layout_.distributed(), settings_.workspace_relaxation, settings_.low_rank);
      kept_ = false, renewed_ = true;
      check(KSPSetTolerances(ksp_, settings_.relative_residual, 0.0, 1e100, iteration_limit()), "KSPSetTolerances");
      converged = krylov_solve(bv, xv, detail);
      spent += iterations_;
    }
    const int last = iterations_;  // code_aster's count: the solve that gave the solution
    iterations_ = spent;
    if (!converged) {
      VecDestroy(&bv);
      VecDestroy(&xv);
      renew_ = true;
      throw iterative_failure(std::string("the iterative solver ") + name() + " did not converge: " + detail,
                              {"allow more iterations, a larger tolerance, another preconditioner, or use a direct "
                               "solver"});
    }
    renew_ = last > settings_.reac_precond;
    from_petsc(xv, out);
  }
  VecDestroy(&bv);
  VecDestroy(&xv);
  return out;
}

}  // namespace
}  // namespace lunaster::engine

/// The module's one entry point (engine/solver/petsc_module.cpp).
extern "C" lunaster::engine::LinearSolver* lunaster_petsc_solver(const lunaster::engine::IterativeSettings* settings) {
  return new lunaster::engine::PetscSolver(*settings);
}

/// The PETSc this module runs on, as the library gives its own numbers (PetscGetVersionNumber
/// reads them without PetscInitialize: no MPI), then the version of the PETSc headers the module
/// was compiled with: "3.18.5 3.18.5" (engine/solver/petsc_module.hpp).
extern "C" int lunaster_petsc_version(char* text, size_t size) {
  PetscInt major = 0, minor = 0, subminor = 0, release = 0;
  if (PetscGetVersionNumber(&major, &minor, &subminor, &release)) return 1;
  std::snprintf(text, size, "%ld.%ld.%ld %d.%d.%d", static_cast<long>(major), static_cast<long>(minor),
                static_cast<long>(subminor), PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR, PETSC_VERSION_SUBMINOR);
  return 0;
}

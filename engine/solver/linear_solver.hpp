#pragma once
/// One interface for every direct solver. The assembled matrix is an Eigen
/// compressed-column matrix built from (row, col, value) triplets: the same
/// triplets are what a distributed MUMPS takes (ICN_loc/JCN_loc/A_loc), so
/// moving to MPI means giving each rank its triplets, not changing assembly.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/linalg.hpp"

namespace lunaster::engine {

/// Available backends. Cholmod needs an SPD matrix; Umfpack and Mumps take any.
/// Petsc is iterative (a Krylov method and a preconditioner, IterativeSettings).
enum class SolverKind { Cholmod, Umfpack, Mumps, Petsc };
constexpr int kSolverKinds = 4;

/// Block low-rank factorisation (MUMPS's BLR; code_aster's SOLVEUR ACCELERATION = 'LR' with
/// LOW_RANK_SEUIL). Off: full rank. On: the off-diagonal blocks of the large fronts are
/// compressed to the rank their singular values leave above `threshold` (ICNTL(35) = 1,
/// CNTL(7) = |threshold|); a negative threshold asks for the UCFS variant (ICNTL(36) = 1,
/// compressing before the updates) as code_aster's does. The factors are then approximate
/// to about that threshold: iterative refinement takes the solves back to round-off.
struct LowRank {
  bool on = false;
  double threshold = 0.0;
};

/// What an iterative backend does: code_aster's SOLVEUR METHODE='PETSC' keywords.
struct IterativeSettings {
  enum class Krylov { CG, GMRES, FGMRES };
  /// Gamg, Ml, Boomer: algebraic multigrid (PETSc's GAMG, Trilinos ML, hypre BoomerAMG),
  /// given the rigid-body modes as near null space; LdltSp: a single-precision MUMPS
  /// factorisation; Jacobi, Sor: point relaxations; None: no preconditioner.
  enum class Preconditioner { Gamg, Ml, Boomer, LdltSp, Jacobi, Sor, None };
  Krylov krylov = Krylov::FGMRES;
  Preconditioner preconditioner = Preconditioner::LdltSp;
  double relative_residual = 1e-6;  ///< |b - A x| / |b| to reach (true residual, not preconditioned)
  int max_iterations = 0;           ///< 0: no limit but the backend's own (10,000)
  /// LdltSp: its single-precision factorisation is kept for the next matrices of the run while
  /// each solve takes at most this many Krylov iterations, and a solve on a kept one that has
  /// not converged after that many factorises its own matrix and solves again (code_aster's
  /// REAC_PRECOND, which waits for the iteration limit). 0: every matrix factorised.
  int reac_precond = 0;
  /// LdltSp: the working space of its factorisation beyond MUMPS's estimate, in percent
  /// (ICNTL(14), code_aster's PCENT_PIVOT; 20 is MUMPS's own for these systems), and its factors
  /// in block low rank (code_aster's LOW_RANK_SEUIL of LDLT_SP; off: full rank).
  int workspace_relaxation = 20;
  LowRank low_rank{};
  /// Receives one line per Krylov iteration (iteration, residual) when set.
  std::function<void(const std::string&)> history;
  /// How the log and the messages name the Krylov method and the preconditioner: the caller's words
  /// (commands/ gives the deck's); empty: the engine's (krylov_name, preconditioner_name).
  std::string krylov_label, preconditioner_label;
};

/// The engine's name of a Krylov method. Inline: the PETSc module (petsc_module.cpp) uses it too.
inline const char* krylov_name(IterativeSettings::Krylov krylov) {
  switch (krylov) {
    case IterativeSettings::Krylov::CG: return "CG";
    case IterativeSettings::Krylov::GMRES: return "GMRES";
    case IterativeSettings::Krylov::FGMRES: return "FGMRES";
  }
  return "?";
}

/// The engine's name of a preconditioner.
inline const char* preconditioner_name(IterativeSettings::Preconditioner preconditioner) {
  using P = IterativeSettings::Preconditioner;
  switch (preconditioner) {
    case P::Gamg: return "GAMG";
    case P::Ml: return "ML";
    case P::Boomer: return "BoomerAMG";
    case P::LdltSp: return "single-precision LDL^T";
    case P::Jacobi: return "Jacobi";
    case P::Sor: return "SOR";
    case P::None: return "no preconditioner";
  }
  return "?";
}

/// The node blocks of a system: which equations are the displacement components of one
/// node. Dirichlet conditions remove some of a node's components, so the system's own
/// numbering has no fixed block size; an iterative backend may rebuild the blocks from this.
struct SystemLayout {
  int dim = 0;                  ///< displacement components per node (2 or 3); 0: no layout
  std::vector<int> block;       ///< per equation: its node block, -1 outside any (multipliers, condensed)
  std::vector<int> component;   ///< per equation in a block: its component, 0..dim-1
  std::vector<double> coords;   ///< dim per block: the node's coordinates
  /// The model has quadratic volume cells (HEXA20, TETRA10 ...): their stiffness couples a
  /// node to many more, with couplings of both signs, and multigrid's strength threshold
  /// follows (see the PETSc solver).
  bool quadratic = false;
  /// A model shared among the ranks of an MPI run: per equation, the rank whose matrix
  /// holds its column complete (and its row: the systems are symmetric). Each rank's matrix
  /// then holds only its own columns, and the system is the sum of the ranks' matrices.
  /// Empty: every rank holds the whole system.
  std::vector<int> owner;
  /// A system of a mesh in parts (docs/distributed-model.md): the matrix and vectors are the
  /// rank's own, in its local numbering, its owned equations first (their columns complete, the
  /// others empty: the system is the sum of the ranks' matrices); per local equation its number
  /// across the ranks (each rank's owned ones are first .. first + n_owned - 1, in rank order).
  /// A solve takes and gives the owned equations' values (the others are the caller's to fill).
  std::vector<long long> global;
  long long first = 0;
  long long n_global = 0;
  int n_owned = 0;
  /// In parts, the rows of a backend that keeps node blocks whole (PETSc): every displacement
  /// unknown of the model numbered across the ranks, Dirichlet-fixed ones included (they become
  /// identity rows), each rank's owned nodes' unknowns first_row .. first_row + n_owned_rows - 1,
  /// node after node, `dim` to a node. Per local equation its row; per owned node (dim values) its
  /// coordinates, for the rigid-body modes.
  std::vector<long long> row;
  long long first_row = 0;
  long long n_rows = 0;
  int n_owned_rows = 0;
  std::vector<double> row_coords;
  int n_blocks() const { return dim > 0 ? static_cast<int>(coords.size()) / dim : 0; }
  bool distributed() const { return !owner.empty(); }
  bool in_parts() const { return !global.empty(); }
};

/// Fill-reducing ordering of a factorisation (code_aster's SOLVEUR RENUM). Auto: the
/// backend's choice (MUMPS: AMD on 2D rows, METIS's nested dissection of the node graph on
/// 3D rows; CHOLMOD: AMD on the node graph, METIS too
/// where AMD fills a 3D factor badly); Metis: that nested dissection; Amd: approximate
/// minimum degree; Rcm: reverse Cuthill-McKee of the node graph (a profile ordering, as
/// code_aster's LDLT); Natural: the equations' own order. Amf, Qamd, Pord: MUMPS's own
/// (ICNTL(7) = 2, 6, 4), for MUMPS only. Metis, Rcm and Natural are computed from the whole
/// pattern (a matrix shared among MUMPS's ranks sends its columns' patterns to rank 0).
enum class FactorOrdering { Auto, Metis, Amd, Amf, Qamd, Pord, Rcm, Natural };

/// The name the log gives an ordering asked for ("METIS", "reverse Cuthill-McKee", ...).
std::string ordering_name(FactorOrdering ordering);
/// Whether every direct backend applies `ordering` (Auto, and the four we compute ourselves:
/// Metis, Amd, Rcm, Natural); Amf, Qamd and Pord are MUMPS's own.
inline bool any_backend_orders_by(FactorOrdering ordering) {
  return ordering != FactorOrdering::Amf && ordering != FactorOrdering::Qamd && ordering != FactorOrdering::Pord;
}

/// Where a MUMPS factorisation keeps its factors (code_aster's SOLVEUR GESTION_MEMOIRE):
/// InCore in memory; OutOfCore on disk (ICNTL(22) = 1, in $TMPDIR or /tmp), memory then holding
/// the fronts being factorised; Auto in memory unless the analysis' estimate of the in-core
/// factorisation exceeds 80 % of the memory available to this process.
enum class FactorMemory { Auto, InCore, OutOfCore };

/// When a factorisation calls its matrix singular (code_aster's SOLVEUR NPREC and
/// STOP_SINGULIER). A pivot is singular when it lost more than `digits` significant digits:
/// CHOLMOD compares each pivot with its matrix diagonal (L_jj^2 <= 10^-digits |A_jj|); MUMPS
/// detects null pivots below 10^-digits in its scaled matrix (ICNTL(24) = 1, CNTL(3) =
/// -10^-digits) and sets them to 1e20 (CNTL(5)), so that the solution is zero along them (an
/// SPD system told to go on is factorised as symmetric indefinite: SYM = 1 detects none).
/// digits < 0: no test (CHOLMOD still stops on a zero or negative pivot). `stop`: a singular
/// matrix is a SolveError; otherwise the factorisation is kept (CHOLMOD hands a zero or
/// negative pivot, which it cannot take, to MUMPS), and `singular_note()` says what was found.
struct SingularityTest {
  int digits = 8;
  bool stop = true;
  double pivot_ratio() const;  ///< 10^-digits; 0 when digits < 0
};

/// How a direct backend analyses and factorises, handed over once by configure() (code_aster's
/// SOLVEUR keywords of the factorising methods). Each backend reads what applies to it:
/// CHOLMOD the ordering and the singularity test, UMFPACK the ordering, MUMPS all of it.
struct FactorSettings {
  /// The fill-reducing ordering of the next analyses (RENUM).
  FactorOrdering ordering = FactorOrdering::Auto;
  /// Where MUMPS keeps its factors (GESTION_MEMOIRE); the others keep them in memory.
  FactorMemory memory = FactorMemory::Auto;
  /// The working space MUMPS's factorisations start with, as a percentage added to the
  /// analysis's estimate (ICNTL(14), PCENT_PIVOT); 0: MUMPS's default. MUMPS doubles it when a
  /// factorisation runs short. The others size their workspace exactly.
  int workspace_relaxation = 0;
  /// Whether MUMPS's analyses scale the matrix and permute it for large diagonal entries as
  /// MUMPS sees fit (automatic ICNTL(6), (8), (12); PRETRAITEMENTS = 'AUTO', the default) or
  /// leave it as assembled ('SANS').
  bool preprocessing = true;
  /// Whether MUMPS compresses the factors (ACCELERATION, LOW_RANK_SEUIL); the others factorise
  /// in full rank.
  LowRank low_rank{};
  /// The factorisation MUMPS uses whatever the matrix's kind (TYPE_RESOL): by the kind when
  /// `by_kind`; else `factorisation`: General an LU of every entry; SymmetricIndefinite an
  /// LDL^T with pivoting (refused for a matrix that is not symmetric);
  /// SymmetricPositiveDefinite an LDL^T without pivoting (refused for a matrix that is not
  /// known positive definite). The other backends factorise by the kind.
  bool by_kind = true;
  MatrixKind factorisation = MatrixKind::SymmetricIndefinite;
  /// Which pivots the factorisations call singular, and whether that stops them (NPREC,
  /// STOP_SINGULIER; UMFPACK and PETSc keep their own tests).
  SingularityTest singularity{};
  /// MUMPS leaves out of the matrix it factorises each entry with |a_ij| <= filter (|a_ii| +
  /// |a_jj|), zeros included, as code_aster's MUMPS driver does for SOLVEUR FILTRAGE_MATRICE:
  /// sparser factors, approximate to about that ratio (iterative refinement against the
  /// matrix as assembled makes up the rest). <= 0: every entry kept.
  double filter = -1.0;
};

/// Direct solver: factorise once, solve for many right-hand sides.
class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// Factorises A (square, full storage of both triangles). Throws SolveError if
  /// A is singular / not positive definite; `failed_column()` then tells which
  /// column (equation) broke down, or -1 if unknown.
  virtual void factorize(const SparseMatrix& a, MatrixKind kind) = 0;
  /// Solves A x = b with the last factorisation.
  virtual Vector solve(const Vector& b) const = 0;
  virtual std::string name() const = 0;
  /// Equation where the last factorisation failed, -1 if none / unknown.
  virtual int failed_column() const { return -1; }
  /// An iterative backend: factorize() builds the preconditioner, solve() iterates to
  /// its own tolerance (and throws SolveError when it does not get there).
  virtual bool iterative() const { return false; }
  /// Where the equations of the next matrices live (SystemLayout): algebraic multigrid
  /// aggregates node blocks and builds its coarse spaces from the rigid-body modes, and a
  /// distributed layout says which columns each rank's matrix holds. Only the backends
  /// for which `takes_distributed()` is true accept a distributed layout.
  virtual void set_layout(SystemLayout /*layout*/) {}
  /// Whether the backend can factorise a system given as its ranks' columns (MUMPS, PETSc).
  virtual bool takes_distributed() const { return false; }
  /// Whether set_layout() may give a system of a mesh in parts (SystemLayout::in_parts).
  virtual bool takes_parts() const { return false; }
  /// factorize(), for a caller that needs the matrix only through multiply() afterwards: a
  /// backend that keeps a copy of its own may release A's storage (A keeps its size, with
  /// no entries) and returns true. The default keeps A and returns false.
  virtual bool factorize_taking(SparseMatrix& a, MatrixKind kind) {
    factorize(a, kind);
    return false;
  }
  /// y = A x with the matrix last factorised, x and y whole on every rank; false when the
  /// backend keeps no copy of it (then y is untouched).
  virtual bool multiply(const Vector& /*x*/, Vector& /*y*/) const { return false; }
  /// Krylov iterations of the last solve (0 for a direct backend).
  virtual int iterations() const { return 0; }
  /// How the next analyses and factorisations are done (FactorSettings). Each direct backend
  /// reads what applies to it; PETSc has none of it.
  virtual void configure(const FactorSettings& /*settings*/) {}
  /// What the approximations asked for came to in the last factorisation: the matrix's
  /// entries left out ("matrix filtered (1e-06): 1204 of 88410 entries left out") and the
  /// compression of the factors ("block low-rank factors (threshold 1e-09): 3.1e+06 entries
  /// against 5e+06 in full rank (62.0 %)"), "; " between them; empty when it made none.
  virtual std::string approximation_note() const { return {}; }
  /// The factorisation the last one used, when it was asked for ("LU", "LDL^T with pivoting",
  /// "LDL^T"); empty otherwise.
  virtual std::string factorisation_used() const { return {}; }
  /// What the last factorisation found singular and went past (SingularityTest::stop false):
  /// the first such equation (this system's numbering), or -1 when it found none.
  virtual int singular_column() const { return -1; }
  /// The same, in words ("pivot lost 9.3 digits", "2 null pivots, set to 1e20"); empty when none.
  virtual std::string singular_note() const { return {}; }
  /// How the last factorisation held its factors, when it was not simply in memory as
  /// usual ("out of core: ...", or what a workspace relaxation asked for came to); empty
  /// otherwise.
  virtual std::string memory_used() const { return {}; }
  /// The ordering the last analysis used ("METIS (nested dissection of the node graph),
  /// given", "PORD", ...); empty for the backends that do not say.
  virtual std::string ordering_used() const { return {}; }
  /// What the last symbolic analysis came to ("AMD: 4.5e+09 operations, 1.3e+07 factor
  /// entries"), as the backend's own analysis counts it; empty for the backends that do not
  /// say. The log prints it at verbosity 2 (`lunaster run -v`), once per analysis.
  virtual std::string analysis_note() const { return {}; }
};

/// Builds a backend. Never returns null. `iterative` is read by SolverKind::Petsc only.
std::unique_ptr<LinearSolver> make_linear_solver(SolverKind kind, const IterativeSettings& iterative = {});
/// An iterative backend the driver chose (SOLVEUR METHODE='AUTO'), not the deck: PETSc with
/// `iterative`, and when it cannot build its preconditioner or a solve does not converge,
/// a factorisation by `direct` of the same matrix instead, from then on. `note` is told
/// why. The matrix given to factorize() must stay alive and unchanged until the next
/// factorize(): a failed solve factorises it then.
std::unique_ptr<LinearSolver> make_iterative_with_fallback(const IterativeSettings& iterative, SolverKind direct,
                                                           std::function<void(const std::string&)> note);

/// y = A x for an operator A known only through its product (e.g. a matrix shared among
/// MPI ranks, the product then summed over them).
using MatrixProduct = std::function<Vector(const Vector&)>;
/// The norm a solve's residuals are measured with (the 2-norm unless told otherwise).
using VectorNorm = std::function<double(const Vector&)>;

/// |A x - b| / |b| (2-norms); +inf if x is not finite. With `norm` (a system of a mesh in parts,
/// collective: see solve_with_refinement) the residual is measured with it and A x is formed
/// whatever x holds, so that every rank takes part in the product.
double relative_residual(const SparseMatrix& a, const Vector& x, const Vector& b);
double relative_residual(const MatrixProduct& a, const Vector& x, const Vector& b, const VectorNorm* norm = nullptr);

/// Accuracy of one refined solve: relative residual straight from the factorisation
/// and after refinement, and the extra solves spent.
struct RefinedSolve {
  double raw_residual = 0.0;
  double residual = 0.0;
  int steps = 0;
  Vector ax_minus_b;  ///< A x - b at the returned x (what `residual` measures)
};

/// Solves A x = b with the solver's current factorisation of A, then refines
/// iteratively (x -= A^-1 (A x - b)) while the relative residual is above
/// `refine_above` and each step lowers it, `max_steps` at most. An ill-conditioned
/// but regular system (a stiff penalty, badly scaled multipliers) is then solved to
/// working accuracy; a singular one keeps its large residual for the caller to judge.
/// With `abs_product` (|A| |x|, entry by entry), no step is spent on a solve that is
/// already backward stable, |A x - b| <= kBackwardStable (|A| |x| + |b|) in every row, and
/// whose relative residual is within `accept` (the caller's acceptance): the residual is
/// then the round-off of the products themselves (a right-hand side small beside the terms
/// of A x, as in a contact pass whose multipliers are 1e5 Pa). Row by row, not against the
/// largest row: a multiplier's row beside penalty-sized rows must meet its own round-off
/// (a two-rank MUMPS factorisation of SSNP121 E left one at 1e-9 relative to its terms,
/// and LAGS_C 3e-8 off, where one step gives 1e-12). A residual beyond `accept` is still
/// refined: a step may bring it within (a stiff penalty).
/// With `norm` (a system of a mesh in parts: the 2-norm of the owned entries over the ranks,
/// collective), every residual is measured with it and A x is formed for every iterate, finite
/// or not, so that the ranks take the same steps.
/// With `fixed_steps` (code_aster's MINI, MUMPS's ICNTL(10) < 0: a fixed count, no test), all
/// `max_steps` steps are taken, each from the last iterate whether or not it gained, and the
/// best iterate is kept: the count does not depend on the round-off of one machine's kernels.
RefinedSolve solve_with_refinement(const LinearSolver& solver, const SparseMatrix& a, const Vector& b, Vector& x,
                                   int max_steps = 3, double refine_above = 1e-10);
RefinedSolve solve_with_refinement(const LinearSolver& solver, const MatrixProduct& a, const Vector& b, Vector& x,
                                   int max_steps = 3, double refine_above = 1e-10,
                                   const MatrixProduct* abs_product = nullptr, double accept = 1e-6,
                                   const VectorNorm* norm = nullptr, bool fixed_steps = false);
/// Backward error (row by row) below which a solve is taken as exact to round-off.
constexpr double kBackwardStable = 1e-14;
/// |A| |x| for a compressed-column matrix (entry by entry), added to y.
void add_abs_product(const SparseMatrix& a, const Vector& x, Vector& y);
/// A x for a symmetric matrix whose columns hold both triangles: entry j is column j
/// times x (a gather, where the general product scatters), so the columns can be shared
/// between two threads, each writing its own entries. A matrix of fewer than 2e5 entries
/// is done on the calling thread.
Vector symmetric_times(const SparseMatrix& a, const Vector& x);

}  // namespace lunaster::engine

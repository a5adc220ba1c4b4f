/// CHOLMOD supernodal Cholesky. The upper triangle of the Eigen matrix is viewed
/// in place (no copy) as an unpacked CHOLMOD matrix (stype = 1): the sorted rows
/// of column j up to its diagonal, so that CHOLMOD's own permuted copy of A is
/// sized for one triangle, not two. The symbolic analysis (fill-reducing
/// ordering) is reused while the sparsity pattern does not change, which is the
/// common case across Newton iterations; the pattern is recognised by its size and
/// a 64-bit fingerprint instead of a kept copy of it.
#include <cblas.h>
#include <cholmod.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numeric>
#include <cstdint>
#include <cstddef>

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "engine/core/error.hpp"
#include "engine/core/memory.hpp"
#include "engine/core/two_workers.hpp"
#include "engine/solver/backends.hpp"
#include "engine/solver/blas.hpp"
#include "engine/solver/interface_solver.hpp"

namespace lunaster::engine {
namespace {

/// The supernodes of a factor shared between two threads for the triangular sweeps:
/// subtrees of the elimination tree that are disjoint (a supernode's updates go to its
/// ancestors only), two sets of them of about equal work, and the rest, their ancestors
/// (`top`). Empty lists: one thread does everything.
struct SweepPlan {
  std::vector<int> subtrees[2];   ///< each thread's supernodes, increasing
  std::vector<int> top;           ///< the other supernodes, increasing
  std::vector<int> top_columns;   ///< the columns of `top`
};
SweepPlan plan_sweeps(const cholmod_factor* f);
Vector supernodal_solve(const cholmod_factor* f, const SweepPlan& plan, const Vector& b);
void forward_sweep(const cholmod_factor* f, const SweepPlan& plan, Vector& x);
void backward_sweep(const cholmod_factor* f, const SweepPlan& plan, Vector& x);

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver() {
    cholmod_start(&common_);
    common_.supernodal = CHOLMOD_SUPERNODAL;
    common_.print = 0;
  }
  ~CholmodSolver() override {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  void factorize(const SparseMatrix& a, MatrixKind kind) override;
  Vector solve(const Vector& b) const override;
  std::string name() const override { return "CHOLMOD"; }
  int failed_column() const override { return failed_; }
  void configure(const FactorSettings& settings) override {  // the ordering and the singularity test
    LUNASTER_ASSERT(any_backend_orders_by(settings.ordering),
                    "CHOLMOD orders by AMD, METIS, reverse Cuthill-McKee or not at all");
    if (settings.ordering != ordering_ && factor_) cholmod_free_factor(&factor_, &common_);  // analyse again
    ordering_ = settings.ordering;
    test_ = settings.singularity;
  }
  std::string ordering_used() const override { return ordering_used_; }
  std::string analysis_note() const override { return analysis_note_; }
  int singular_column() const override { return past_ ? past_->singular_column() : singular_; }
  std::string singular_note() const override {
    if (!past_) return singular_note_;
    const std::string note = past_->singular_note();
    return "a pivot CHOLMOD cannot take (zero or negative), so MUMPS factorised the system" +
           (note.empty() ? std::string() : ": " + note);
  }

 private:
  bool same_pattern(const SparseMatrix& a, std::uint64_t fingerprint) const {
    return factor_ && n_ == a.cols() && nnz_ == a.nonZeros() && fingerprint_ == fingerprint;
  }
  [[noreturn]] void fail(int column, const std::string& why);
  /// The symbolic analysis of m's pattern (its upper view s): the ordering asked for, or AMD on
  /// the node graph (nested dissection too where AMD fills much), with the sweep plan.
  void analyse(const SparseMatrix& m, cholmod_sparse& s, std::uint64_t fingerprint);
  /// METIS on the node graph tried beside AMD's analysis in factor_ (kept_fl, kept_lnz): the one
  /// with fewer operations kept. Returns the note on the other ("; AMD: ..."), or empty.
  std::string try_nested_dissection(const SparseMatrix& m, cholmod_sparse& s, double& kept_fl, double& kept_lnz);
  /// The numeric factorisation on the analysis. False when a pivot CHOLMOD cannot take was gone
  /// past as asked (MUMPS factorised m instead, past_); SolveError on a failure.
  bool factorise_numerically(const SparseMatrix& m, cholmod_sparse& s);
  /// The singularity test of the factor's pivots: a weak one is a SolveError or gone past
  /// (singular_), as the test says.
  void test_pivots(const SparseMatrix& m);

  mutable cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
  Eigen::Index n_ = -1, nnz_ = -1;  ///< size of the analysed pattern
  std::uint64_t fingerprint_ = 0;   ///< pattern_fingerprint of the analysed pattern
  std::vector<int> upper_count_;    ///< rows of each column up to the diagonal (the view's nz)
  SweepPlan plan_;                  ///< how the solves share the factor's supernodes (per analysis)
  bool wide_ = false;               ///< factorised with two BLAS threads (per analysis)
  FactorOrdering ordering_ = FactorOrdering::Auto;
  std::string ordering_used_;       ///< of the last analysis
  std::string analysis_note_;       ///< its operations and factor entries
  SingularityTest test_;            ///< which pivots are singular, and whether that stops
  /// Going on past a singular matrix whose pivot CHOLMOD cannot take (zero or negative, which
  /// round-off decides for a free body): MUMPS, symmetric indefinite, sets its null pivots aside.
  std::unique_ptr<LinearSolver> past_;
  int singular_ = -1;               ///< the weak pivot the last factorisation went past, or -1
  std::string singular_note_;
  int failed_ = -1;
  bool ready_ = false;
};

/// The upper triangle of a (compressed, sorted columns) as an unpacked CHOLMOD matrix:
/// column j is the first upper_count[j] entries of a's column j. Fills upper_count.
cholmod_sparse upper_view(const SparseMatrix& a, std::vector<int>& upper_count) {
  const int n = static_cast<int>(a.cols());
  const int* p = a.outerIndexPtr();
  const int* i = a.innerIndexPtr();
  upper_count.resize(n);
  for (int j = 0; j < n; ++j) upper_count[j] = static_cast<int>(std::upper_bound(i + p[j], i + p[j + 1], j) - (i + p[j]));
  cholmod_sparse s{};
  s.nrow = a.rows();
  s.ncol = a.cols();
  s.nzmax = a.nonZeros();
  s.p = const_cast<int*>(p);
  s.i = const_cast<int*>(i);
  s.nz = upper_count.data();
  s.x = const_cast<double*>(a.valuePtr());
  s.stype = 1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 0;
  return s;
}

/// FNV-1a over the column pointers and row indices: equal patterns, equal fingerprints.
/// A different pattern taken for the analysed one would not go unnoticed either: the
/// caller checks every solve's residual against the matrix itself.
std::uint64_t pattern_fingerprint(const SparseMatrix& a) {
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](const int* v, Eigen::Index count) {
    for (Eigen::Index k = 0; k < count; ++k) h = (h ^ static_cast<std::uint32_t>(v[k])) * 1099511628211ULL;
  };
  mix(a.outerIndexPtr(), a.cols() + 1);
  mix(a.innerIndexPtr(), a.nonZeros());
  return h;
}

enum class GraphOrdering { Amd, Metis, Rcm };

/// Reverse Cuthill-McKee of the graph whose upper triangle (diagonal included or not) is
/// the pattern qp/qi of ng vertices.
std::vector<int> rcm_of_upper(int ng, const std::vector<int>& qp, const std::vector<int>& qi) {
  std::vector<int> xadj(ng + 1, 0);
  for (int g = 0; g < ng; ++g)
    for (int k = qp[g]; k < qp[g + 1]; ++k)
      if (qi[k] != g) ++xadj[g + 1], ++xadj[qi[k] + 1];
  for (int g = 0; g < ng; ++g) xadj[g + 1] += xadj[g];
  std::vector<int> adj(xadj[ng]), fill(xadj.begin(), xadj.end() - 1);
  for (int g = 0; g < ng; ++g)
    for (int k = qp[g]; k < qp[g + 1]; ++k)
      if (qi[k] != g) adj[fill[g]++] = qi[k], adj[fill[qi[k]]++] = g;
  return reverse_cuthill_mckee(xadj, adj);
}

/// Fill-reducing ordering computed by AMD, METIS or reverse Cuthill-McKee (`ordering`) on the
/// quotient graph whose vertices are runs of consecutive columns with identical patterns (the
/// DOFs of one node), expanded back to columns. Ordering the node graph instead of the DOF
/// graph is several times cheaper for the same fill. Empty if the ordering fails, or, for AMD
/// and METIS, if the matrix has few such runs (the caller then orders the equations). With
/// `last` (AMD only), the equations it flags come after all the others (constrained AMD, CAMD;
/// a run of equations is split where the flag changes: a node may have only its normal
/// component on the interface).
std::vector<int> node_graph_ordering(const SparseMatrix& a, cholmod_common* common, GraphOrdering ordering,
                                     const std::vector<char>* last = nullptr) {
  const int n = static_cast<int>(a.cols());
  const int* p = a.outerIndexPtr();
  const int* i = a.innerIndexPtr();
  std::vector<int> group_of(n), start;
  for (int j = 0; j < n; ++j) {
    const bool same = j > 0 && p[j + 1] - p[j] == p[j] - p[j - 1] && std::equal(i + p[j], i + p[j + 1], i + p[j - 1]) &&
                      (!last || (*last)[j] == (*last)[j - 1]);
    if (!same) start.push_back(j);
    group_of[j] = static_cast<int>(start.size()) - 1;
  }
  const int ng = static_cast<int>(start.size());
  if (ng > n / 2 + n / 4 && ordering != GraphOrdering::Rcm) return {};  // little to gain
  start.push_back(n);
  std::vector<int> qp(ng + 1, 0), qi;
  qi.reserve(a.nonZeros() / 4 + ng);
  for (int g = 0; g < ng; ++g) {
    int last = -1;
    for (int k = p[start[g]]; k < p[start[g] + 1]; ++k) {
      const int rg = group_of[i[k]];  // rows are sorted, so groups are non-decreasing
      if (rg != last && rg <= g) qi.push_back(rg);
      last = rg;
    }
    qp[g + 1] = static_cast<int>(qi.size());
  }
  cholmod_sparse q{};
  q.nrow = q.ncol = ng;
  q.nzmax = qi.size();
  q.p = qp.data();
  q.i = qi.data();
  q.stype = 1;
  q.itype = CHOLMOD_INT;
  q.xtype = CHOLMOD_PATTERN;
  q.dtype = CHOLMOD_DOUBLE;
  q.sorted = 1;
  q.packed = 1;
  std::vector<int> gperm(ng);
  if (ordering == GraphOrdering::Rcm) {
    gperm = rcm_of_upper(ng, qp, qi);
  } else if (ordering == GraphOrdering::Metis) {
    // The graph as it is (stype 1: CHOLMOD adds the other triangle). An unsymmetric copy
    // would be ordered as the graph of A A^T, whose nodes are linked to their neighbours'
    // neighbours: twice the operations of this ordering on 3D meshes.
    if (!cholmod_metis(&q, nullptr, 0, 0, gperm.data(), common)) return {};
  } else if (last && ordering == GraphOrdering::Amd) {
    // CAMD: the groups of `last` equations after all the others.
    std::vector<int> cmember(ng);
    for (int g = 0; g < ng; ++g) cmember[g] = (*last)[start[g]] ? 1 : 0;
    if (!cholmod_camd(&q, nullptr, 0, cmember.data(), gperm.data(), common)) return {};
  } else if (!cholmod_amd(&q, nullptr, 0, gperm.data(), common)) {
    return {};
  }
  std::vector<int> perm;
  perm.reserve(n);
  for (int g : gperm)
    for (int j = start[g]; j < start[g + 1]; ++j) perm.push_back(j);
  return perm;
}

/// A count of CHOLMOD's analysis (operations, factor entries) for the log: "4.52e+09".
std::string analysis_count(double count) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", count);
  return text;
}

/// A 3D mesh's system: over 40 stored entries a column (81 for HEXA8 meshes, 18 for QUAD4).
bool three_d_pattern(const SparseMatrix& a) {
  return static_cast<double>(a.nonZeros()) > 40.0 * static_cast<double>(std::max<Eigen::Index>(1, a.cols()));
}

/// A large factor with long columns (3D meshes: about 500 stored entries per column on the
/// SSNP121 3D benchmarks, against 100 for the glued 2D k = 16 mesh) has supernodes large
/// enough for two BLAS threads; a 2D factor's small ones run no faster on two.
bool wide_factor(const cholmod_factor* factor, Eigen::Index n) {
  constexpr double kWideEntries = 2e6, kWideColumn = 200.0;
  const auto entries = static_cast<double>(factor->xsize);
  return factor->is_super && entries > kWideEntries && entries > kWideColumn * static_cast<double>(n);
}

void CholmodSolver::fail(int column, const std::string& why) {
  failed_ = column;
  ready_ = false;
  throw SolveError("CHOLMOD: " + why + (column >= 0 ? " at equation " + std::to_string(column) : std::string()),
                   {"the stiffness matrix is singular or not positive definite: check the boundary conditions "
                    "(rigid-body modes) and the material"});
}

/// The first pivot that lost more than the significant digits `ratio` allows against its
/// diagonal (L_jj^2 <= ratio |A_jj|): its original column and the digits it lost; column -1
/// when none did or ratio is 0. Supernodal layout: column j of supernode s has its diagonal at
/// x[px[s] + j * (nsrow + 1)].
struct WeakPivot {
  int column = -1;
  double digits_lost = 0.0;
};
WeakPivot weak_pivot(const cholmod_factor* factor, const Vector& diag, double ratio) {
  if (ratio <= 0.0 || !factor->is_super) return {};
  const auto* perm = static_cast<const int*>(factor->Perm);
  const auto* lx = static_cast<const double*>(factor->x);
  const auto* super = static_cast<const int*>(factor->super);
  const auto* pi = static_cast<const int*>(factor->pi);
  const auto* px = static_cast<const int*>(factor->px);
  for (size_t s = 0; s < factor->nsuper; ++s) {
    const int nsrow = pi[s + 1] - pi[s];
    for (int k = super[s]; k < super[s + 1]; ++k) {
      const int j = k - super[s];
      const double l = lx[px[s] + static_cast<size_t>(j) * (nsrow + 1)];
      const int col = perm ? perm[k] : k;
      if (l * l <= ratio * std::abs(diag(col))) return {col, std::log10(std::abs(diag(col)) / (l * l))};
    }
  }
  return {};
}

/// The supernodal factor's arrays (CHOLMOD's layout: supernode s holds columns super[s] to
/// super[s+1]-1, its rows are ls[pi[s]..pi[s+1]), its values the column-major block at px[s]).
struct Supernodes {
  explicit Supernodes(const cholmod_factor* f)
      : n(static_cast<int>(f->n)),
        count(static_cast<int>(f->nsuper)),
        perm(static_cast<const int*>(f->Perm)),
        super(static_cast<const int*>(f->super)),
        pi(static_cast<const int*>(f->pi)),
        px(static_cast<const int*>(f->px)),
        ls(static_cast<const int*>(f->s)),
        lx(static_cast<const double*>(f->x)) {}
  int columns(int s) const { return super[s + 1] - super[s]; }
  int rows(int s) const { return pi[s + 1] - pi[s]; }
  Eigen::Map<const Eigen::MatrixXd> block(int s) const { return {lx + px[s], rows(s), columns(s)}; }
  int n, count;
  const int *perm, *super, *pi, *px, *ls;
  const double* lx;
};

/// L y = x in place, supernode `s` of the forward sweep (`t`: scratch of maxesize).
void forward(const Supernodes& f, int s, Vector& x, Vector& t) {
  const int k1 = f.super[s], nscol = f.columns(s), nbelow = f.rows(s) - nscol;
  const auto l = f.block(s);
  auto xs = x.segment(k1, nscol);
  l.topRows(nscol).triangularView<Eigen::Lower>().solveInPlace(xs);
  if (nbelow == 0) return;
  auto below = t.head(nbelow);
  below.noalias() = l.bottomRows(nbelow) * xs;
  const int* rows = f.ls + f.pi[s] + nscol;
  for (int i = 0; i < nbelow; ++i) x[rows[i]] -= below[i];
}

/// L^T z = y in place, supernode `s` of the backward sweep.
void backward(const Supernodes& f, int s, Vector& x, Vector& t) {
  const int k1 = f.super[s], nscol = f.columns(s), nbelow = f.rows(s) - nscol;
  const auto l = f.block(s);
  auto xs = x.segment(k1, nscol);
  if (nbelow > 0) {
    auto below = t.head(nbelow);
    const int* rows = f.ls + f.pi[s] + nscol;
    for (int i = 0; i < nbelow; ++i) below[i] = x[rows[i]];
    xs.noalias() -= l.bottomRows(nbelow).transpose() * below;
  }
  l.topRows(nscol).triangularView<Eigen::Lower>().transpose().solveInPlace(xs);
}

SweepPlan plan_sweeps(const cholmod_factor* factor) {
  SweepPlan plan;
  const Supernodes f(factor);
  // Below about 2e6 factor entries (a few ms a sweep) a second thread costs what it saves.
  constexpr double kEntriesForTwoThreads = 2e6;
  if (static_cast<double>(factor->xsize) < kEntriesForTwoThreads || f.count < 2) return plan;
  // Elimination tree of the supernodes: the parent holds the first row below the diagonal
  // block. A parent comes after its children.
  std::vector<int> owner_of_column(f.n), parent(f.count, -1);
  for (int s = 0; s < f.count; ++s)
    for (int k = f.super[s]; k < f.super[s + 1]; ++k) owner_of_column[k] = s;
  std::vector<double> work(f.count), subtree(f.count);
  std::vector<std::vector<int>> children(f.count);
  std::vector<int> roots;
  for (int s = 0; s < f.count; ++s) {
    work[s] = static_cast<double>(f.rows(s)) * f.columns(s);
    subtree[s] += work[s];
    if (f.rows(s) > f.columns(s)) {
      parent[s] = owner_of_column[f.ls[f.pi[s] + f.columns(s)]];
      subtree[parent[s]] += subtree[s];
      children[parent[s]].push_back(s);
    } else {
      roots.push_back(s);
    }
  }
  // Frontier of subtrees: the roots, then the heaviest subtree is opened (it joins the top,
  // its children the frontier) while it outweighs all the others together and the top stays
  // a small part of the work.
  const double total = std::accumulate(work.begin(), work.end(), 0.0);
  std::vector<int> frontier = roots;
  std::vector<char> in_top(f.count, 0);
  double top_work = 0.0;
  for (;;) {
    auto heaviest = std::max_element(frontier.begin(), frontier.end(),
                                      [&](int a, int b) { return subtree[a] < subtree[b]; });
    double frontier_work = 0.0;
    for (int s : frontier) frontier_work += subtree[s];
    if (subtree[*heaviest] <= 0.5 * frontier_work) break;
    const int s = *heaviest;
    if (top_work + work[s] > 0.25 * total) return plan;  // no balanced split worth a thread
    frontier.erase(heaviest);
    in_top[s] = 1, top_work += work[s];
    frontier.insert(frontier.end(), children[s].begin(), children[s].end());
  }
  // Heaviest subtrees first, each to the lighter thread.
  std::sort(frontier.begin(), frontier.end(), [&](int a, int b) { return subtree[a] > subtree[b]; });
  std::vector<int> thread_of(f.count, -1);
  double load[2] = {0.0, 0.0};
  for (int s : frontier) {
    const int w = load[0] <= load[1] ? 0 : 1;
    thread_of[s] = w, load[w] += subtree[s];
  }
  for (int s = f.count - 1; s >= 0; --s)
    if (!in_top[s] && thread_of[s] < 0) thread_of[s] = thread_of[parent[s]];
  for (int s = 0; s < f.count; ++s) {
    if (in_top[s]) {
      plan.top.push_back(s);
      for (int k = f.super[s]; k < f.super[s + 1]; ++k) plan.top_columns.push_back(k);
    } else {
      plan.subtrees[thread_of[s]].push_back(s);
    }
  }
  return plan;
}

/// L y = x in place for a supernodal LL^T factor (x in the factor's order), supernode by
/// supernode with Eigen's dense kernels: one small triangular solve and one product with the
/// rows below each. cholmod_solve makes the same two calls per supernode through OpenBLAS,
/// whose per-call set-up (argument checks, a locked buffer) weighs on the many small
/// supernodes of a 2D factor. A sweep is BLAS-2 and memory-bound: with a plan, two threads
/// sweep disjoint subtrees at once, the second on its own copy of x, whose updates to the
/// shared ancestors are added before the ancestors are swept.
void forward_sweep(const cholmod_factor* factor, const SweepPlan& plan, Vector& x) {
  const Supernodes f(factor);
  const Eigen::Index scratch = static_cast<Eigen::Index>(factor->maxesize);
  Vector t(scratch);
  if (plan.subtrees[0].empty()) {
    for (int s = 0; s < f.count; ++s) forward(f, s, x, t);
    return;
  }
  const Vector start = x;
  Vector y = x;  // the second thread's copy
  run_two_workers([&](int w, size_t&) {
    Vector scratch_w(scratch);
    for (int s : plan.subtrees[w]) forward(f, s, w == 0 ? x : y, scratch_w);
  });
  for (int s : plan.subtrees[1])
    for (int k = f.super[s]; k < f.super[s + 1]; ++k) x[k] = y[k];
  for (int k : plan.top_columns) x[k] += y[k] - start[k];  // the second thread's updates
  for (int s : plan.top) forward(f, s, x, t);
}

/// L^T z = y in place: the ancestors first, then the two threads' subtrees at once (each
/// reads the ancestors' values and writes its own).
void backward_sweep(const cholmod_factor* factor, const SweepPlan& plan, Vector& x) {
  const Supernodes f(factor);
  const Eigen::Index scratch = static_cast<Eigen::Index>(factor->maxesize);
  Vector t(scratch);
  if (plan.subtrees[0].empty()) {
    for (int s = f.count - 1; s >= 0; --s) backward(f, s, x, t);
    return;
  }
  for (auto s = plan.top.rbegin(); s != plan.top.rend(); ++s) backward(f, *s, x, t);
  run_two_workers([&](int w, size_t&) {
    Vector scratch_w(scratch);
    const auto& mine = plan.subtrees[w];
    for (auto s = mine.rbegin(); s != mine.rend(); ++s) backward(f, *s, x, scratch_w);
  });
}

/// x = A^-1 b from a supernodal LL^T factor of P A P^T.
Vector supernodal_solve(const cholmod_factor* factor, const SweepPlan& plan, const Vector& b) {
  const int n = static_cast<int>(factor->n);
  const auto* perm = static_cast<const int*>(factor->Perm);
  Vector x(n);
  for (int k = 0; k < n; ++k) x[k] = b[perm ? perm[k] : k];
  forward_sweep(factor, plan, x);
  backward_sweep(factor, plan, x);
  Vector out(n);
  for (int k = 0; k < n; ++k) out[perm ? perm[k] : k] = x[k];
  return out;
}

std::string CholmodSolver::try_nested_dissection(const SparseMatrix& m, cholmod_sparse& s, double& kept_fl,
                                                 double& kept_lnz) {
  std::string tried;
  // Where AMD's factorisation of a 3D system (over 40 entries a column) needs over 5e9
  // operations, or its factor is over 10 times A, nested dissection (METIS on the same
  // node graph) is tried too and the factor with fewer operations kept: on the SSNP121
  // mortar 3D benchmark 6.1e9 operations against AMD's 1.5e10, for 0.14 s of METIS.
  // Below that, METIS costs about what it saves (the elastic 3D benchmark: 2.7e9 against
  // 4.5e9 for 0.08 s), and on 2D meshes it gains little (6 % of the glued k = 16 mesh's
  // operations) for more time (0.48 s) than the whole factorisation's analysis.
  const double fl_amd = common_.fl;
  if (factor_ && ((three_d_pattern(m) && fl_amd > 5e9) || common_.lnz > 10.0 * static_cast<double>(m.nonZeros()))) {
    std::vector<int> nd = node_graph_ordering(m, &common_, GraphOrdering::Metis);
    if (!nd.empty()) {
      cholmod_factor* other = cholmod_analyze_p(&s, nd.data(), nullptr, 0, &common_);
      const double fl_nd = common_.fl, lnz_nd = common_.lnz;
      if (other && fl_nd < fl_amd) {
        std::swap(factor_, other);
        ordering_used_ = ordering_name(FactorOrdering::Metis);
        kept_fl = fl_nd, kept_lnz = lnz_nd;
        tried = "; AMD: " + analysis_count(fl_amd) + " operations";
      } else if (other) {
        tried = "; METIS: " + analysis_count(fl_nd) + " operations";
      }
      if (other) cholmod_free_factor(&other, &common_);
    }
  }
  return tried;
}

void CholmodSolver::analyse(const SparseMatrix& m, cholmod_sparse& s, std::uint64_t fingerprint) {
  if (factor_) cholmod_free_factor(&factor_, &common_);
  // The ordering asked for (SOLVEUR RENUM) whatever it costs, else AMD on the node graph.
  const bool asked = ordering_ != FactorOrdering::Auto;
  std::vector<int> perm = asked ? given_ordering(m, ordering_) : node_graph_ordering(m, &common_, GraphOrdering::Amd);
  if (asked && perm.empty()) throw SolveError("CHOLMOD: the " + ordering_name(ordering_) + " ordering failed");
  double kept_fl = 0.0, kept_lnz = 0.0;  // the analysis of the factor kept
  std::string tried;                      // the other ordering tried, if any
  if (perm.empty()) {
    common_.nmethods = 0;  // CHOLMOD's default strategy (AMD, then METIS if AMD fills badly)
    factor_ = cholmod_analyze(&s, &common_);
    ordering_used_ = "CHOLMOD's own";
  } else {
    common_.nmethods = 1;
    common_.method[0].ordering = CHOLMOD_GIVEN;
    factor_ = cholmod_analyze_p(&s, perm.data(), nullptr, 0, &common_);
    ordering_used_ = ordering_name(asked ? ordering_ : FactorOrdering::Amd);
  }
  kept_fl = common_.fl, kept_lnz = common_.lnz;
  if (!asked && !perm.empty()) tried = try_nested_dissection(m, s, kept_fl, kept_lnz);
  if (!factor_ && common_.status == CHOLMOD_OUT_OF_MEMORY)
    throw SolveError::out_of_memory("CHOLMOD", m.rows(), "symbolic analysis");
  if (!factor_) fail(-1, "symbolic analysis failed (status " + std::to_string(common_.status) + ")");
  analysis_note_ = "CHOLMOD analysis, " + ordering_used_ + ": " + analysis_count(kept_fl) + " operations, " +
                   analysis_count(kept_lnz) + " factor entries" + tried;
  n_ = m.cols();
  nnz_ = m.nonZeros();
  fingerprint_ = fingerprint;
  plan_ = factor_->is_super ? plan_sweeps(factor_) : SweepPlan{};
  wide_ = wide_factor(factor_, n_);
}

bool CholmodSolver::factorise_numerically(const SparseMatrix& m, cholmod_sparse& s) {
  const int ok = [&] {
    const WideBlas threads(wide_);
    return cholmod_factorize(&s, factor_, &common_);
  }();
  if (common_.status == CHOLMOD_NOT_POSDEF) {
    if (!test_.stop && test_.digits >= 0) {
      past_ = make_linear_solver(SolverKind::Mumps);
      FactorSettings settings;  // MUMPS's own ordering, the same test
      settings.singularity = test_;
      past_->configure(settings);
      past_->factorize(m, MatrixKind::SymmetricIndefinite);
      return false;
    }
    const auto* perm = static_cast<const int*>(factor_->Perm);
    const int minor = static_cast<int>(factor_->minor);
    fail(perm ? perm[minor] : minor, "matrix not positive definite");
  }
  if (common_.status == CHOLMOD_OUT_OF_MEMORY) {
    ready_ = false;
    throw SolveError::out_of_memory("CHOLMOD", m.rows(), "numeric factorisation");
  }
  if (!ok || common_.status < CHOLMOD_OK) fail(-1, "factorisation failed (status " + std::to_string(common_.status) + ")");
  return true;
}

void CholmodSolver::test_pivots(const SparseMatrix& m) {
  singular_ = -1;
  singular_note_.clear();
  if (const WeakPivot weak = weak_pivot(factor_, m.diagonal(), test_.pivot_ratio()); weak.column >= 0) {
    char lost[96];
    std::snprintf(lost, sizeof lost, "pivot lost %.1f significant digits (more than %d)", weak.digits_lost,
                  test_.digits);
    if (test_.stop) {
      try {
        fail(weak.column, std::string("numerically singular matrix (") + lost + ")");
      } catch (SolveError& err) {  // the digits, for a diagnosis
        err.failure().value = weak.digits_lost;
        err.failure().limit = test_.digits;
        throw;
      }
    }
    singular_ = weak.column;
    singular_note_ = lost;
  }
}

void CholmodSolver::factorize(const SparseMatrix& a, MatrixKind kind) {
  failed_ = -1;
  ready_ = false;
  past_.reset();
  if (kind != MatrixKind::SymmetricPositiveDefinite)
    throw InternalError("CHOLMOD needs a symmetric positive definite matrix; use UMFPACK or MUMPS");
  LUNASTER_ASSERT(a.rows() == a.cols(), "CHOLMOD: matrix is not square");
  SparseMatrix compressed;
  const SparseMatrix* m = &a;
  if (!a.isCompressed()) {
    compressed = a;
    compressed.makeCompressed();
    m = &compressed;
  }
  cholmod_sparse s = upper_view(*m, upper_count_);
  const std::uint64_t fingerprint = pattern_fingerprint(*m);
  if (!same_pattern(*m, fingerprint)) analyse(*m, s, fingerprint);
  if (factorise_numerically(*m, s)) test_pivots(*m);  // false: MUMPS went past a pivot
  ready_ = true;
}

Vector CholmodSolver::solve(const Vector& b) const {
  if (!ready_) throw InternalError("CHOLMOD: solve called without a valid factorisation");
  if (past_) return past_->solve(b);
  if (factor_->is_super && factor_->is_ll) return supernodal_solve(factor_, plan_, b);
  cholmod_dense rhs{};
  rhs.nrow = b.size();
  rhs.ncol = 1;
  rhs.nzmax = b.size();
  rhs.d = b.size();
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, factor_, &rhs, &common_);
  if (!x) throw SolveError("CHOLMOD: solve failed");
  Vector out = Eigen::Map<const Vector>(static_cast<const double*>(x->x), b.size());
  cholmod_free_dense(&x, &common_);
  return out;
}


// LAPACK (OpenBLAS): Bunch-Kaufman factorisation of a dense symmetric matrix and its solve.
// Fortran's hidden lengths of the character arguments are passed explicitly.
extern "C" {
void dsytrf_(const char* uplo, const int* n, double* a, const int* lda, int* ipiv, double* work, const int* lwork,
             int* info, std::size_t uplo_len);
void dsytrs_(const char* uplo, const int* n, const int* nrhs, const double* a, const int* lda, const int* ipiv,
             double* b, const int* ldb, int* info, std::size_t uplo_len);
}

class CholmodInterfaceSolver final : public InterfaceSolver {
 public:
  explicit CholmodInterfaceSolver(std::vector<int> interface) : interface_(std::move(interface)) {
    cholmod_start(&common_);
    common_.supernodal = CHOLMOD_SUPERNODAL;
    common_.print = 0;
    common_.nmethods = 1;
    common_.method[0].ordering = CHOLMOD_GIVEN;
    common_.postorder = 0;  // the given order is kept (factorize_reference)
  }
  ~CholmodInterfaceSolver() override {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }
  CholmodInterfaceSolver(const CholmodInterfaceSolver&) = delete;
  CholmodInterfaceSolver& operator=(const CholmodInterfaceSolver&) = delete;

  bool factorize_reference(SparseMatrix& r, double max_dense_share) override;
  void factorize(const SparseMatrix& a, MatrixKind kind) override;
  Vector solve(const Vector& b) const override;
  std::string name() const override { return "CHOLMOD with the contact interface condensed"; }
  std::string analysis_note() const override { return analysis_note_; }
  const std::vector<int>& interface() const override { return interface_; }
  void configure(const FactorSettings& settings) override { test_ = settings.singularity; }

 private:
  std::vector<int> interface_;
  SingularityTest test_;  ///< the reference's weak pivots (a rigid-body mode): no condensation
  std::vector<int> slot_;  ///< per equation: its index in the interface (its order in L), -1 inside
  mutable cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
  SweepPlan plan_;        ///< how the solves share the factor's supernodes
  // m x m, column-major, on huge pages (each is 23 MB on the CONTINUE 3D benchmark, whose
  // first touch of 4 kB pages cost more than filling them).
  std::vector<double> l_ii_;  ///< trailing block of L (lower triangle)
  std::vector<double> g_;     ///< L_II L_II^T - R_II (lower triangle)
  std::vector<double> s_;     ///< the last factorised Schur complement, as dsytrf left it
  std::vector<int> pivots_;
  bool wide_ = false;  ///< two BLAS threads for the factorisations (a 3D-sized factor)
  bool ready_ = false;
  std::string analysis_note_;  ///< the reference's analysis and the interface's dense factorisation
  /// The order of the reference's analysis, the interface last (CAMD, or METIS on a 3D
  /// pattern); `from_metis` says which.
  std::vector<int> interface_last_order(const SparseMatrix& r, cholmod_sparse& view, bool& from_metis);
  /// The numeric factorisation of the reference (its upper view), a unit diagonal set where
  /// an interface equation has none (`unit_diagonal`), r's values restored afterwards;
  /// SolveError (factor_ freed) when it fails or a pivot is weak (a rigid-body mode).
  void factorise_reference_values(SparseMatrix& r, cholmod_sparse& view, std::vector<int>& unit_diagonal);
  /// L_II, the trailing m x m block of the factor (n equations), into l_ii_.
  void copy_interface_block(int n);
  /// g_ = L_II L_II^T minus the unit diagonals set, its lower triangle.
  void form_g(const std::vector<int>& unit_diagonal);
  Eigen::Map<const Eigen::MatrixXd> l_ii() const {
    const auto m = static_cast<Eigen::Index>(interface_.size());
    return {l_ii_.data(), m, m};
  }
};

std::vector<int> CholmodInterfaceSolver::interface_last_order(const SparseMatrix& r, cholmod_sparse& view,
                                                              bool& from_metis) {
  const int n = static_cast<int>(r.cols()), m = static_cast<int>(interface_.size());
  // The interface last, the interior before it, both in constrained AMD's order (CAMD on the
  // node graph), except for 3D systems (below). CAMD's order is a postorder of its own
  // elimination tree: CHOLMOD's postorder would interleave the interface with the subtrees
  // hanging from it, so none is asked for.
  // On the 2D contact benchmark at k = 32 this factor needs 2.1e10 operations, fewer than
  // AMD's for the glued mesh of the same size (2.4e10); AMD's order with the interface moved
  // last needed 3.1e10.
  std::vector<char> on_interface(n, 0);
  for (int eq : interface_) on_interface[eq] = 1;
  auto interface_last = [&](const std::vector<int>& order) {
    if (order.size() != static_cast<std::size_t>(n)) return false;
    for (int k = n - m; k < n; ++k)
      if (!on_interface[order[k]]) return false;
    return true;
  };
  // A 3D system (over 40 entries a column): nested dissection of the node graph (METIS), the
  // interface then moved last. On the SSNP121 CONTINUE 3D benchmark, the normal components
  // of the contact surfaces last, 5.4e9 operations against CAMD's 8.8e9, for 0.07 s of METIS;
  // in 2D CAMD's order is the better one and METIS slow (CholmodSolver::factorize).
  std::vector<int> perm;
  if (three_d_pattern(r)) {
    perm = node_graph_ordering(r, &common_, GraphOrdering::Metis, &on_interface);
    std::stable_partition(perm.begin(), perm.end(), [&on_interface](int eq) { return !on_interface[eq]; });
  }
  from_metis = interface_last(perm);
  if (!from_metis) {
    perm = node_graph_ordering(r, &common_, GraphOrdering::Amd, &on_interface);
    if (perm.empty()) {
      perm.resize(n);
      std::vector<int> cmember(n);
      for (int eq = 0; eq < n; ++eq) cmember[eq] = on_interface[eq];
      if (!cholmod_camd(&view, nullptr, 0, cmember.data(), perm.data(), &common_))
        throw SolveError("CHOLMOD: CAMD ordering failed");
    }
    if (!interface_last(perm)) throw SolveError("CHOLMOD: CAMD did not order the interface last");
  }
  return perm;
}

void CholmodInterfaceSolver::factorise_reference_values(SparseMatrix& r, cholmod_sparse& view,
                                                        std::vector<int>& unit_diagonal) {
  const int n = static_cast<int>(r.cols());
  // Unit diagonals where K has none (multipliers), restored below.
  std::vector<std::pair<double*, double>> saved;
  for (int eq : interface_) {
    const int* rows = r.innerIndexPtr() + r.outerIndexPtr()[eq];
    const int* end = r.innerIndexPtr() + r.outerIndexPtr()[eq + 1];
    const int* d = std::lower_bound(rows, end, eq);
    if (d == end || *d != eq) throw SolveError("interface solver: no diagonal entry at equation " + std::to_string(eq));
    double& v = r.valuePtr()[d - r.innerIndexPtr()];
    if (v == 0.0) saved.emplace_back(&v, v), v = 1.0, unit_diagonal.push_back(eq);
  }
  auto restore = [&saved] {
    for (auto& [where, value] : saved) *where = value;
  };
  const int ok = factor_ ? cholmod_factorize(&view, factor_, &common_) : 0;
  // A pivot that lost more digits than the run allows is a rigid-body mode (the driver's
  // check, which this factorisation replaces): the caller solves without condensing.
  if (factor_ && ok && common_.status == CHOLMOD_OK && weak_pivot(factor_, r.diagonal(), test_.pivot_ratio()).column >= 0)
    common_.status = CHOLMOD_NOT_POSDEF;
  if (!factor_ || !ok || common_.status != CHOLMOD_OK) {
    restore();
    const bool memory = common_.status == CHOLMOD_OUT_OF_MEMORY;
    if (factor_) cholmod_free_factor(&factor_, &common_);
    if (memory) throw SolveError::out_of_memory("CHOLMOD", n, "factorisation of the elastic system");
    throw SolveError("CHOLMOD: the elastic system without contact is not positive definite (status " +
                     std::to_string(common_.status) + ")");
  }
  restore();
}

void CholmodInterfaceSolver::copy_interface_block(int n) {
  const int m = static_cast<int>(interface_.size());
  // L_II from the supernodes holding the last m columns.
  const auto* super = static_cast<const int*>(factor_->super);
  const auto* pi = static_cast<const int*>(factor_->pi);
  const auto* px = static_cast<const int*>(factor_->px);
  const auto* ls = static_cast<const int*>(factor_->s);
  const auto* lx = static_cast<const double*>(factor_->x);
  const auto* fperm = static_cast<const int*>(factor_->Perm);
  LUNASTER_ASSERT(factor_->is_super && factor_->is_ll, "interface solver: a supernodal LL^T factor");
  for (int k = n - m; k < n; ++k) LUNASTER_ASSERT(slot_[fperm[k]] == k - (n - m), "interface solver: the interface is not last");
  const auto mm = static_cast<std::size_t>(m) * static_cast<std::size_t>(m);
  resize_on_huge_pages(l_ii_, mm);
  const int first = n - m;
  for (size_t sn = 0; sn < factor_->nsuper; ++sn) {
    if (super[sn + 1] <= first) continue;
    const int nsrow = pi[sn + 1] - pi[sn];
    for (int c = std::max(super[sn], first); c < super[sn + 1]; ++c) {
      const double* col = lx + px[sn] + static_cast<std::ptrdiff_t>(c - super[sn]) * nsrow;
      double* to = l_ii_.data() + static_cast<std::size_t>(c - first) * m;
      for (int k = c - super[sn]; k < nsrow; ++k) to[ls[pi[sn] + k] - first] = col[k];
    }
  }
}

void CholmodInterfaceSolver::form_g(const std::vector<int>& unit_diagonal) {
  const int m = static_cast<int>(interface_.size());
  const auto mm = static_cast<std::size_t>(m) * static_cast<std::size_t>(m);
  // G = L_II L_II^T - D_II, its lower triangle, a panel of columns of L_II at a time: the
  // panel from column k0 is zero above row k0, so it adds to G's trailing block only
  // (dsyrk: 2.6 times faster than OpenBLAS's dtrmm and the transposed copy it needs, at
  // 1,715 equations on one thread).
  resize_on_huge_pages(g_, mm);
  constexpr int kPanel = 128;
  for (int k0 = 0; k0 < m; k0 += kPanel) {
    const int width = std::min(kPanel, m - k0);
    const std::size_t at = static_cast<std::size_t>(k0) * m + k0;
    cblas_dsyrk(CblasColMajor, CblasLower, CblasNoTrans, m - k0, width, 1.0, l_ii_.data() + at, m, 1.0,
                g_.data() + at, m);
  }
  for (int eq : unit_diagonal) g_[static_cast<std::size_t>(slot_[eq]) * (m + 1)] -= 1.0;
}

bool CholmodInterfaceSolver::factorize_reference(SparseMatrix& r, double max_dense_share) {
  ready_ = false;
  if (factor_) cholmod_free_factor(&factor_, &common_);
  std::vector<double>().swap(l_ii_);
  std::vector<double>().swap(g_);
  LUNASTER_ASSERT(r.isCompressed() && r.rows() == r.cols(), "interface solver: a square compressed reference");
  const int n = static_cast<int>(r.cols()), m = static_cast<int>(interface_.size());
  slot_.assign(n, -1);
  // The interface last, the interior before it (interface_last_order).
  std::vector<int> upper_count;
  cholmod_sparse view = upper_view(r, upper_count);
  bool from_metis = false;
  std::vector<int> perm = interface_last_order(r, view, from_metis);
  factor_ = cholmod_analyze_p(&view, perm.data(), nullptr, 0, &common_);
  if (factor_)
    analysis_note_ = "CHOLMOD analysis of the reference, " + std::string(from_metis ? "METIS" : "CAMD") +
                     " with the " + std::to_string(m) + " interface equations last: " + analysis_count(common_.fl) +
                     " operations, " + analysis_count(common_.lnz) + " factor entries; each contact pass " +
                     analysis_count(static_cast<double>(m) * m * m / 3.0) + " (dense)";
  if (factor_ && max_dense_share > 0.0 && static_cast<double>(m) * m * m / 3.0 > max_dense_share * common_.fl) {
    cholmod_free_factor(&factor_, &common_);
    return false;
  }
  for (int k = n - m; k < n; ++k) slot_[perm[k]] = k - (n - m);
  // Two BLAS threads for a factor of 3D size, for the factorisation and the dense interface
  // products below.
  wide_ = factor_ && wide_factor(factor_, n);
  const WideBlas threads(wide_);
  std::vector<int> unit_diagonal;
  factorise_reference_values(r, view, unit_diagonal);
  plan_ = plan_sweeps(factor_);
  copy_interface_block(n);
  form_g(unit_diagonal);
  return true;
}

void CholmodInterfaceSolver::factorize(const SparseMatrix& a, MatrixKind /*kind*/) {
  ready_ = false;
  if (!factor_) throw InternalError("interface solver: factorize called before factorize_reference");
  const int m = static_cast<int>(interface_.size());
  if (s_.size() != g_.size()) resize_on_huge_pages(s_, g_.size());
  std::copy(g_.begin(), g_.end(), s_.begin());
  for (int eq : interface_)
    for (SparseMatrix::InnerIterator it(a, eq); it; ++it)
      if (slot_[it.row()] >= slot_[eq]) s_[static_cast<std::size_t>(slot_[eq]) * m + slot_[it.row()]] += it.value();
  pivots_.assign(std::max(m, 1), 0);
  int info = 0, lwork = -1;
  double query = 0.0;
  dsytrf_("L", &m, s_.data(), &m, pivots_.data(), &query, &lwork, &info, 1);
  lwork = std::max(1, static_cast<int>(query));
  std::vector<double> work(lwork);
  {
    const WideBlas threads(wide_);
    dsytrf_("L", &m, s_.data(), &m, pivots_.data(), work.data(), &lwork, &info, 1);
  }
  if (info > 0)
    throw SolveError("the contact interface's Schur complement is singular (LAPACK dsytrf: zero pivot " +
                     std::to_string(info) + " of " + std::to_string(m) + ")");
  if (info < 0) throw InternalError("dsytrf: argument " + std::to_string(-info));
  ready_ = true;
}

Vector CholmodInterfaceSolver::solve(const Vector& b) const {
  if (!ready_) throw InternalError("interface solver: solve called without a valid factorisation");
  const int n = static_cast<int>(b.size()), m = static_cast<int>(interface_.size());
  const auto* perm = static_cast<const int*>(factor_->Perm);
  Vector y(n);
  for (int k = 0; k < n; ++k) y[k] = b[perm[k]];
  forward_sweep(factor_, plan_, y);
  Vector x_i = l_ii().triangularView<Eigen::Lower>() * y.tail(m);
  int info = 0, one = 1;
  dsytrs_("L", &m, &one, s_.data(), &m, pivots_.data(), x_i.data(), &m, &info, 1);
  if (info != 0) throw InternalError("dsytrs: argument " + std::to_string(-info));
  y.tail(m) = l_ii().transpose().triangularView<Eigen::Upper>() * x_i;
  backward_sweep(factor_, plan_, y);
  Vector out(n);
  for (int k = 0; k < n; ++k) out[perm[k]] = y[k];
  return out;
}
}  // namespace

std::vector<int> reverse_cuthill_mckee(const std::vector<int>& xadj, const std::vector<int>& adj) {
  const int n = static_cast<int>(xadj.size()) - 1;
  auto degree = [&xadj](int v) { return xadj[v + 1] - xadj[v]; };
  std::vector<int> by_degree(n);
  std::iota(by_degree.begin(), by_degree.end(), 0);
  std::stable_sort(by_degree.begin(), by_degree.end(), [&](int x, int y) { return degree(x) < degree(y); });
  std::vector<int> order, level(n, -1), queue;
  std::vector<char> placed(n, 0);
  order.reserve(n);
  queue.reserve(n);
  // Breadth-first levels from r over the vertices not yet placed; returns the last level's
  // vertex of least degree and the number of levels.
  auto sweep = [&](int r, int& far) {
    queue.assign(1, r);
    level[r] = 0;
    int depth = 0;
    far = r;
    for (size_t h = 0; h < queue.size(); ++h) {
      const int v = queue[h];
      if (level[v] > depth || (level[v] == depth && degree(v) < degree(far))) depth = level[v], far = v;
      for (int k = xadj[v]; k < xadj[v + 1]; ++k)
        if (!placed[adj[k]] && level[adj[k]] < 0) level[adj[k]] = level[v] + 1, queue.push_back(adj[k]);
    }
    for (int v : queue) level[v] = -1;
    return depth;
  };
  std::vector<int> next;
  for (int seed : by_degree) {
    if (placed[seed]) continue;
    // A pseudo-peripheral start (George and Liu): move to the far end while the levels deepen.
    int start = seed, far = seed, depth = sweep(start, far);
    for (int tries = 0; tries < 8 && far != start; ++tries) {
      int far2 = far;
      const int d = sweep(far, far2);
      if (d <= depth) break;
      start = far, depth = d, far = far2;
    }
    const size_t first = order.size();
    order.push_back(start);
    placed[start] = 1;
    for (size_t h = first; h < order.size(); ++h) {
      const int v = order[h];
      next.clear();
      for (int k = xadj[v]; k < xadj[v + 1]; ++k)
        if (!placed[adj[k]]) placed[adj[k]] = 1, next.push_back(adj[k]);
      std::stable_sort(next.begin(), next.end(), [&](int x, int y) { return degree(x) < degree(y); });
      order.insert(order.end(), next.begin(), next.end());
    }
  }
  std::reverse(order.begin(), order.end());
  return order;
}

std::vector<int> given_ordering(const SparseMatrix& a, FactorOrdering ordering) {
  const int n = static_cast<int>(a.cols());
  std::vector<int> perm;
  if (ordering == FactorOrdering::Natural) {
    perm.resize(n);
    std::iota(perm.begin(), perm.end(), 0);
    return perm;
  }
  if (ordering != FactorOrdering::Metis && ordering != FactorOrdering::Amd && ordering != FactorOrdering::Rcm) return {};
  const GraphOrdering graph = ordering == FactorOrdering::Metis ? GraphOrdering::Metis
                              : ordering == FactorOrdering::Amd ? GraphOrdering::Amd
                                                                : GraphOrdering::Rcm;
  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  perm = node_graph_ordering(a, &common, graph);
  if (perm.empty() && n > 0 && graph != GraphOrdering::Rcm) {
    // Few node runs: the graph of the equations themselves.
    std::vector<int> upper_count;
    cholmod_sparse view = upper_view(a, upper_count);
    perm.resize(n);
    const int ok = graph == GraphOrdering::Metis ? cholmod_metis(&view, nullptr, 0, 0, perm.data(), &common)
                                                 : cholmod_amd(&view, nullptr, 0, perm.data(), &common);
    if (!ok) perm.clear();
  }
  cholmod_finish(&common);
  return perm;
}

std::unique_ptr<LinearSolver> make_cholmod_solver() { return std::make_unique<CholmodSolver>(); }

std::unique_ptr<InterfaceSolver> make_interface_solver(std::vector<int> interface) {
  configure_blas();
  return std::make_unique<CholmodInterfaceSolver>(std::move(interface));
}

}  // namespace lunaster::engine

#include "engine/nonlinear/system_matrix.hpp"

#include <algorithm>
#include <cstring>

#include "engine/core/error.hpp"
#include "engine/core/memory.hpp"
#include "engine/core/two_workers.hpp"
#include "engine/assembly/assembly.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {

namespace {

/// FNV-1a key of a system's values: equal keys, equal matrices.
struct ValuesKey {
  std::uint64_t h = 1469598103934665603ULL;
  void mix(std::uint64_t v) { h = (h ^ v) * 1099511628211ULL; }
};

/// values[pos[k]] += contact[k] for every located triplet, each value mixed into `key`;
/// true when one was added.
bool add_triplet_values(const std::vector<Triplet>& contact, const std::vector<int>& pos, double* values,
                        ValuesKey& key) {
  bool any = false;
  for (size_t k = 0; k < contact.size(); ++k) {
    if (pos[k] < 0) continue;
    any = true;
    const double v = contact[k].value();
    values[pos[k]] += v;
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    key.mix(bits);
  }
  return any;
}

/// Position of entry (i, j) in a's storage (the entry must be in the pattern).
int position_in(const SparseMatrix& a, int i, int j) {
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  return static_cast<int>(std::lower_bound(inner + outer[j], inner + outer[j + 1], i) - inner);
}

/// Position in a of each contact triplet (free numbering), -1 for a constrained one, and with
/// `within` (per free equation) for one whose row or column it does not flag. One binary
/// search per triplet, most of them a cache miss: two threads share the triplets when there
/// are many (1.3 million on the 3D CONTINUE benchmark).
void locate_triplets(const SparseMatrix& a, const std::vector<int>& free_index, const std::vector<Triplet>& contact,
                     std::vector<int>& pos, const std::vector<char>* within = nullptr) {
  const size_t n = contact.size();
  resize_on_huge_pages(pos, n);
  auto locate = [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      const int i = free_index[contact[k].row()], j = free_index[contact[k].col()];
      pos[k] = i >= 0 && j >= 0 && (!within || ((*within)[i] && (*within)[j])) ? position_in(a, i, j) : -1;
    }
  };
  constexpr size_t kTripletsForTwoThreads = 100000;
  if (n < kTripletsForTwoThreads) return locate(0, n);
  run_two_workers([&](int w, size_t&) { w == 0 ? locate(0, n / 2) : locate(n / 2, n); });
}

}  // namespace

void SystemMatrix::clear() {
  cache_ = Cache{};
  ghost_ = SparseMatrix();
  ghost_nodes_.clear();
  elastic_.ff = SparseMatrix();  // the previous run's matrices go before new ones are built
  elastic_.c = SparseMatrix();
}

bool SystemMatrix::assemble(TangentSource& tangent, const Vector& u, const std::vector<int>& constrained,
                            bool distributed, Vector* f_int) {
  tangent_ = &tangent;
  distributed_ = distributed;
  tangent_at_ = Vector();
  SparseMatrix k;
  if (!tangent.assemble(u, &k, f_int)) return false;
  split_matrix(k, constrained, elastic_);
  elastic_.symmetric = !distributed;  // a rank holds only its own nodes' columns
  return true;
}

bool SystemMatrix::refresh(const Vector& u) {
  if (constant()) return true;
  // The same u, bit for bit, as the last refresh_with_forces: K is its tangent already.
  if (tangent_at_.size() == u.size() && std::memcmp(tangent_at_.data(), u.data(), sizeof(double) * u.size()) == 0)
    return true;
  return reassemble(u, nullptr);
}

bool SystemMatrix::refresh_with_forces(const Vector& u, Vector& f_int) {
  LUNASTER_ASSERT(!constant(), "a constant tangent's internal forces are K u");
  if (!reassemble(u, &f_int)) return false;
  tangent_at_ = u;
  return true;
}

bool SystemMatrix::reassemble(const Vector& u, Vector* f_int) {
  restore();
  const std::vector<int> constrained = elastic_.constrained;
  elastic_.ff = SparseMatrix();
  elastic_.c = SparseMatrix();
  const bool assembled = assemble(*tangent_, u, constrained, distributed_, f_int);
  // New values (or none, when an integration failed: the next refresh assembles them): a new
  // generation (new key); K_ff's storage is new, its contact positions with it.
  ++cache_.elastic_generation;
  cache_.contact_version = -3;
  cache_.contact_only.clear();
  ghost_nodes_.clear();  // the columns at the eliminated equations' nodes, K's of before
  return assembled;
}

Vector SystemMatrix::times(const Vector& u, const RankLayout& layout, const LinearSolver* holder) const {
  // With K_ff in the backend, elastic_.times() gives the constrained columns' part only.
  Vector ku = elastic_.times(u);
  // In parts with K_ff in the backend, its product gives the owned rows whole: the ghosts'
  // shares of the rest go to the owners first, the owners' sums to the ghosts last.
  if (layout.in_parts() && holder) layout.equation_halo().add_to_owners(ku.data(), 1);
  else layout.complete(ku);
  if (holder) {
    const int nf = static_cast<int>(elastic_.equation.size());
    Vector u_free(nf), k_u_free;
    for (int j = 0; j < nf; ++j) u_free[j] = u[elastic_.equation[j]];
    const bool done = holder->multiply(u_free, k_u_free);
    LUNASTER_ASSERT(done, "the backend holding K_ff gave no product");
    for (int j = 0; j < nf; ++j) ku[elastic_.equation[j]] += k_u_free[j];
    if (layout.in_parts()) layout.equation_halo().copy_to_ghosts(ku.data(), 1);
  }
  return ku;
}

Constraints::ColumnSource SystemMatrix::columns(const Constraints& cons, const std::vector<Elimination>& relations,
                                               const RankLayout& layout, const FeModel& model, const DofMap& dofs,
                                               const MeshPart* part) {
  if (layout.kind() == RankLayout::Kind::Whole) {
    // Its constrained rows are left out: their residual is not solved for and no term of K'
    // lies on them. So are zeros (the contact positions update_system added to K_ff's
    // pattern): the fill, and with it the system's pattern, follows the relations.
    return [this, &cons](int e, Constraints::Column& column) {
      for (SparseMatrix::InnerIterator it(elastic_.ff, cons.free_index[e]); it; ++it)
        if (it.value() != 0.0) column.emplace_back(elastic_.equation[it.row()], it.value());
    };
  }
  // This rank holds only its own nodes' columns: the whole columns of the eliminated
  // equations' nodes are computed (kept while the set of nodes holds), so that each rank gets
  // the whole fill and keeps its own columns of it. A shared model: every rank assembles them.
  // In parts: the owner of an eliminated unknown's node holds every cell around it, assembles
  // the node's columns whole and every rank gets them; their rows are on every rank (the slave
  // surfaces came with the cells around their nodes: with_whole_surfaces, layered).
  std::vector<int> nodes;
  for (const Elimination& e : relations) nodes.push_back(dofs.node_of(e.eq));
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  if (nodes != ghost_nodes_) {
    if (layout.in_parts()) {
      ghost_ = layout.gathered_columns(model, dofs, *part, nodes);
    } else {
      std::vector<char> mask(model.mesh->n_nodes(), 0);
      for (int v : nodes) mask[v] = 1;
      ghost_ = SparseMatrix();
      ghost_ = assemble_stiffness_matrix(model, dofs, &mask);
    }
    ghost_nodes_ = std::move(nodes);
  }
  return [this, &cons](int e, Constraints::Column& column) {
    for (SparseMatrix::InnerIterator it(ghost_, e); it; ++it)
      if (cons.free_index[it.row()] >= 0) column.emplace_back(static_cast<int>(it.row()), it.value());
  };
}

void SystemMatrix::begin(const Constraints& cons, const DofMap& dofs, const std::vector<char>* owned_nodes) {
  restore();
  Cache& sys = cache_;
  sys.new_constraints = !sys.valid || sys.constrained != cons.constrained;
  if (sys.new_constraints) {
    sys.constrained = cons.constrained;
    ++sys.elastic_generation;
  }
  LUNASTER_ASSERT(cons.constrained == elastic_.constrained, "the Dirichlet set changed within a run");
  if (!sys.new_constraints) return;
  sys.owned.clear();
  if (owned_nodes) {
    sys.owned.assign(cons.n_free, 0);
    for (int eq = 0; eq < dofs.n_dofs(); ++eq)
      if (cons.free_index[eq] >= 0) sys.owned[cons.free_index[eq]] = (*owned_nodes)[dofs.node_of(eq)];
  }
}

void SystemMatrix::fill_alone() {
  Cache& sys = cache_;
  if (sys.new_constraints) ++sys.pattern, sys.valid = true;
  sys.matrix = &elastic_.ff;
  std::uint64_t key = 1469598103934665603ULL;
  sys.values_key = (key ^ static_cast<std::uint64_t>(sys.elastic_generation)) * 1099511628211ULL;
}

void SystemMatrix::fill_interface(const Constraints& cons, const std::vector<Triplet>& contact,
                                  const std::vector<int>& condensed, long contact_version,
                                  const std::vector<int>& interface, const std::vector<char>& on_interface) {
  // The interface solver: a holds C alone, the contact terms and the condensed equations'
  // unit diagonals (K_ff has zeros there), in a pattern built once per contact pattern.
  // Only the terms within the interface: outside it, an interface of some components has
  // only terms below the interface's floor (a normal's round-off), which it leaves out.
  Cache& sys = cache_;
  const int nf = cons.n_free;
  if (sys.new_constraints || !sys.increment || contact_version != sys.contact_version || contact.size() != sys.contact_pos.size()) {
    sys.a = SparseMatrix();
    std::vector<Triplet> pattern;
    pattern.reserve(contact.size() + interface.size());
    for (const auto& tr : contact) {
      const int i = cons.free_index[tr.row()], j = cons.free_index[tr.col()];
      if (i >= 0 && j >= 0 && on_interface[i] && on_interface[j]) pattern.emplace_back(i, j, 0.0);
    }
    for (int j : interface) pattern.emplace_back(j, j, 0.0);
    SparseMatrix c(nf, nf);
    c.setFromTriplets(pattern.begin(), pattern.end());
    sys.a.swap(c);
    locate_triplets(sys.a, cons.free_index, contact, sys.contact_pos, &on_interface);
    sys.diagonal.assign(nf, -1);
    for (int j : interface) sys.diagonal[j] = position_in(sys.a, j, j);
    sys.contact_version = contact_version;
    sys.increment = true;
    ++sys.pattern;
    sys.valid = true;
    sys.matrix = &sys.a;
  }
  std::fill(sys.a.valuePtr(), sys.a.valuePtr() + sys.a.nonZeros(), 0.0);
  ValuesKey key;
  key.mix(static_cast<std::uint64_t>(sys.elastic_generation));
  double* values = sys.a.valuePtr();
  add_triplet_values(contact, sys.contact_pos, values, key);
  for (int eq : condensed)
    if (cons.free_index[eq] >= 0)
      values[sys.diagonal[cons.free_index[eq]]] = 1.0, key.mix(static_cast<std::uint64_t>(eq));
  sys.values_key = key.h;
}

void SystemMatrix::fill_whole(const Constraints& cons, const std::vector<Triplet>& contact,
                              const std::vector<int>& condensed, const std::vector<int>& eliminated,
                              long contact_version) {
  Cache& sys = cache_;
  if (sys.increment) {  // the interface solver was dropped: the whole system from now on
    sys.increment = false;
    sys.a = SparseMatrix();
    sys.contact_version = -2;
  }
  // K_ff and the system share one storage (a second copy of K_ff was the largest array of a
  // mortar run after the factor): K_ff's pattern grows to hold every contact position, and
  // each iteration writes its terms into it, saving the values it overwrites for restore().
  if (sys.new_constraints || contact_version != sys.contact_version || contact.size() != sys.contact_pos.size())
    rebuild_pattern(cons, contact, contact_version);
  write_values(cons, contact, condensed, eliminated);
}

void SystemMatrix::rebuild_pattern(const Constraints& cons, const std::vector<Triplet>& contact,
                                   long contact_version) {
  Cache& sys = cache_;
  SparseMatrix& k = elastic_.ff;
  const int nf = cons.n_free;
  const int* el_outer = k.outerIndexPtr();
  const int* el_inner = k.innerIndexPtr();
  const double* el_values = k.valuePtr();
  // Pattern column by column: the rows of K_ff merged with the contact rows of the column
  // (bucketed, sorted, unique) and the diagonal; no global sort. Positions K_ff did not
  // have hold zeros until the next pattern.
  std::vector<int> start(static_cast<size_t>(nf) + 2, 0), extra;
  for (const auto& tr : contact) {
    const int i = cons.free_index[tr.row()], j = cons.free_index[tr.col()];
    if (i >= 0 && j >= 0) ++start[j + 2];
  }
  for (int j = 0; j < nf; ++j) start[j + 2] += mine(j);  // the diagonal
  for (int j = 0; j <= nf; ++j) start[j + 1] += start[j];
  resize_on_huge_pages(extra, static_cast<size_t>(start[nf + 1]));
  for (const auto& tr : contact) {
    const int i = cons.free_index[tr.row()], j = cons.free_index[tr.col()];
    if (i >= 0 && j >= 0) extra[start[j + 1]++] = i;
  }
  for (int j = 0; j < nf; ++j)
    if (mine(j)) extra[start[j + 1]++] = j;
  std::vector<int> extra_end(nf);
  for (int j = 0; j < nf; ++j) {
    std::sort(extra.begin() + start[j], extra.begin() + start[j + 1]);
    extra_end[j] = static_cast<int>(std::unique(extra.begin() + start[j], extra.begin() + start[j + 1]) - extra.begin());
  }
  // Union of the two sorted row lists of column j, passed to emit(row, K_ff's value or 0,
  // whether the position is there for contact only), less the positions an earlier pairing
  // added that this one does not use (sys.contact_only, ascending): a sliding contact does
  // not leave its whole path in the pattern and the factor's fill. K_ff's own positions all
  // stay, zeros included (its pattern is symmetric to the bit, its values are not).
  // `changed` counts the positions added or dropped.
  long changed = 0;
  size_t cursor = 0;  // into sys.contact_only, restarted by each pass over the columns
  auto merge_column = [&](int j, auto&& emit) {
    const int* e0 = extra.data() + start[j];
    const int* e1 = extra.data() + extra_end[j];
    int p = el_outer[j];
    const int p1 = el_outer[j + 1];
    while (p < p1 || e0 != e1) {
      const int r = p < p1 ? el_inner[p] : -1;
      if (e0 == e1 || (r >= 0 && r < *e0)) {  // K_ff's only
        const bool stale = cursor < sys.contact_only.size() && sys.contact_only[cursor] == p;
        cursor += stale;
        if (stale) ++changed;
        else emit(r, el_values[p], false);
        ++p;
      } else if (r < 0 || *e0 < r) {  // contact's only
        emit(*e0++, 0.0, true), ++changed;
      } else {  // in both
        const bool added = cursor < sys.contact_only.size() && sys.contact_only[cursor] == p;
        cursor += added;
        emit(r, el_values[p++], added), ++e0;
      }
    }
  };
  SparseMatrix a(nf, nf);
  int* outer = a.outerIndexPtr();
  outer[0] = 0;
  for (int j = 0; j < nf; ++j) {
    int count = 0;
    merge_column(j, [&count](int, double, bool) { ++count; });
    outer[j + 1] = outer[j] + count;
  }
  if (changed > 0) {  // else K_ff's pattern is this one already
    a.resizeNonZeros(outer[nf]);
    // Written once, as K_ff's arrays in assembly: on huge pages, one fault per 2 MB.
    advise_huge_pages(a.innerIndexPtr(), sizeof(int) * static_cast<std::size_t>(outer[nf]));
    advise_huge_pages(a.valuePtr(), sizeof(double) * static_cast<std::size_t>(outer[nf]));
    int* inner = a.innerIndexPtr();
    double* values = a.valuePtr();
    std::vector<int> contact_only;
    cursor = 0;
    for (int j = 0; j < nf; ++j) {
      int at = outer[j];
      merge_column(j, [&](int row, double v, bool only) {
        if (only) contact_only.push_back(at);
        inner[at] = row, values[at++] = v;
      });
    }
    sys.contact_only.swap(contact_only);
    k.swap(a);  // the old K_ff goes with a; Eigen 3.4's sparse assignment would copy it
  }
  locate_contact(cons, contact, contact_version);
}

void SystemMatrix::locate_contact(const Constraints& cons, const std::vector<Triplet>& contact,
                                  long contact_version) {
  Cache& sys = cache_;
  SparseMatrix& k = elastic_.ff;
  locate_triplets(k, cons.free_index, contact, sys.contact_pos);
  sys.contact_unique.clear();
  {
    std::vector<char> seen;  // no sort of millions of 3D positions
    resize_on_huge_pages(seen, static_cast<size_t>(k.nonZeros()));
    reserve_on_huge_pages(sys.contact_unique, sys.contact_pos.size());
    for (int p : sys.contact_pos)
      if (p >= 0 && !seen[p]) seen[p] = 1, sys.contact_unique.push_back(p);
  }
  sys.contact_elastic.resize(sys.contact_unique.size());
  for (size_t i = 0; i < sys.contact_unique.size(); ++i) sys.contact_elastic[i] = k.valuePtr()[sys.contact_unique[i]];
  sys.diagonal.resize(cons.n_free);
  for (int j = 0; j < cons.n_free; ++j) sys.diagonal[j] = mine(j) ? position_in(k, j, j) : -1;
  sys.contact_version = contact_version;
  ++sys.pattern;
  sys.valid = true;
  sys.matrix = &k;
}

void SystemMatrix::write_values(const Constraints& cons, const std::vector<Triplet>& contact,
                                const std::vector<int>& condensed, const std::vector<int>& eliminated) {
  Cache& sys = cache_;
  SparseMatrix& k = elastic_.ff;
  const int nf = cons.n_free;
  double* values = k.valuePtr();
  std::vector<std::pair<int, double>>& saved = sys.saved;
  auto set = [&](int p, double v) { saved.emplace_back(p, values[p]), values[p] = v; };
  // The key of these values: the elastic part's generation, the contact values and the
  // condensed equations (FNV-1a over their bits). Equal keys, equal matrices.
  ValuesKey key;
  auto mix = [&key](std::uint64_t v) { key.mix(v); };
  mix(static_cast<std::uint64_t>(sys.elastic_generation));
  sys.contact_written = add_triplet_values(contact, sys.contact_pos, values, key);
  for (int eq : condensed)
    if (cons.free_index[eq] >= 0) {
      if (mine(cons.free_index[eq])) set(sys.diagonal[cons.free_index[eq]], 1.0);
      mix(static_cast<std::uint64_t>(eq));
    }
  // Eliminated unknowns: their rows and columns (elastic values included) become a unit diagonal.
  const int* outer = k.outerIndexPtr();
  const int* inner = k.innerIndexPtr();
  if (sys.owned.empty()) {
    for (int eq : eliminated) {
      const int j = cons.free_index[eq];
      for (int p = outer[j]; p < outer[j + 1]; ++p) {
        const int i = inner[p];
        set(p, 0.0);
        set(static_cast<int>(std::lower_bound(inner + outer[i], inner + outer[i + 1], j) - inner), 0.0);
      }
      set(sys.diagonal[j], 1.0);
      mix(~static_cast<std::uint64_t>(eq));
    }
  } else if (!eliminated.empty()) {
    // A shared model: column j may be another rank's, so row j is found by a pass over this
    // rank's columns.
    std::vector<char> gone(nf, 0);
    for (int eq : eliminated) gone[cons.free_index[eq]] = 1, mix(~static_cast<std::uint64_t>(eq));
    for (int j = 0; j < nf; ++j) {
      if (!mine(j)) continue;
      for (int p = outer[j]; p < outer[j + 1]; ++p)
        if (gone[j] || gone[inner[p]]) set(p, 0.0);
      if (gone[j]) set(sys.diagonal[j], 1.0);
    }
  }
  sys.values_key = key.h;
}

void SystemMatrix::agree_over_ranks(long pattern_before) {
  // Each rank keyed its own columns' terms: a rank with no contact point in its columns sees
  // the same matrix when the others see a new one, and would skip a factorisation the others
  // enter (MUMPS's and PETSc's are collective: the run would hang, as it did on three ranks).
  // The whole system is new when any rank's part is, and its key is every rank's key.
  Cache& sys = cache_;
  const bool changed_here = sys.pattern != pattern_before;
  sys.pattern = pattern_before + (parallel::max_over_ranks(changed_here ? 1.0 : 0.0) > 0.0 ? 1 : 0);
  const std::vector<int> halves = {static_cast<int>(sys.values_key & 0xffffffffULL),
                                   static_cast<int>(sys.values_key >> 32)};
  ValuesKey key;
  for (int half : parallel::gather_all(halves)) key.mix(static_cast<std::uint32_t>(half));
  sys.values_key = key.h;
}

void SystemMatrix::restore() {
  Cache& sys = cache_;
  double* values = elastic_.ff.valuePtr();
  for (auto it = sys.saved.rbegin(); it != sys.saved.rend(); ++it) values[it->first] = it->second;
  sys.saved.clear();
  if (sys.contact_written)
    for (size_t i = 0; i < sys.contact_unique.size(); ++i) values[sys.contact_unique[i]] = sys.contact_elastic[i];
  sys.contact_written = false;
}

}  // namespace lunaster::engine
